using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// What the body check sees of a loaded rig's skin: skin beside a crate's edge is outside it, however the rounding of
/// coordinates far from the origin falls; the trunk's own skin (a pelvis) is probed; and skin blended between a leg
/// and the trunk bone it hangs from (a thigh's top) goes where the hip takes it.
/// </summary>
public sealed class BodySkinTests
{
    private static readonly Lazy<CharacterModel> Tailed = new(() => ForeignCharacters.Named("tailed").Load().Model);

    private static readonly Lazy<CharacterModel> Spider = new(() => ForeignCharacters.Named("spider").Load().Model);

    private static (Vector3[] Positions, Quaternion[] Rotations) Solve(CharacterModel model, RootPose root)
    {
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(root, model.ContactPose, positions, rotations);
        return (positions, rotations);
    }

    private static Triangle[] Box(Vector3 min, Vector3 max, Matrix4x4 place)
    {
        var b = new LevelBuilder("box");
        ForeignLevels.AddSoupBox(b, "crate", min, max, place);
        return [.. b.Build().Triangles];
    }

    /// <summary>
    /// The tail's hindmost skin point lies in the plane of a crate's side, 5 cm past the edge where that side meets the
    /// crate's back: equally near both faces, in front of the back. Tried at 36 headings 30 m from the origin, where
    /// the two faces' distances differ only by rounding, it is never inside (it was, by 5 cm, on some headings, when
    /// the face nearer by a rounding error decided: a quadruped's thigh read 7 cm inside a crate it walked past).
    /// </summary>
    [Test]
    public void SkinPastACratesEdgeIsOutsideItOnEveryHeading()
    {
        CharacterModel model = Tailed.Value;
        Rig rig = model.Rig;
        int tip = rig.IndexOf("tail_2");
        var outside = new List<string>();
        var inside = new List<string>();
        for (int k = 0; k < 36; k++)
        {
            float heading = k * MathF.Tau / 36f;
            var root = new RootPose(new Vector3(30.3f, 0.4f, -29.7f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, heading));
            (Vector3[] positions, Quaternion[] rotations) = Solve(model, root);
            Vector3 p = model.Source!.SkinProbes[tip].Select(s => positions[tip] + Vector3.Transform(s, rotations[tip])).MinBy(s => Vector3.Dot(s - positions[tip], Vector3.Transform(Vector3.UnitZ, root.Rotation)));

            // The crate's frame: its back faces the body (+w, toward the trunk), its side lies in the plane through p.
            Quaternion turn = Quaternion.CreateFromAxisAngle(Vector3.UnitY, heading + 0.3f);
            Matrix4x4 place = Matrix4x4.CreateFromQuaternion(turn) * Matrix4x4.CreateTranslation(p);
            Triangle[] nearTriangles = Box(new Vector3(-0.3f, -0.2f, -0.35f), new Vector3(0f, 0.2f, -0.05f), place);
            if (new BodyCollision(new TriangleBvh(nearTriangles), model, nearTriangles).OtherBoneColliding(positions, rotations) is int seen and >= 0)
            {
                outside.Add($"{heading * 180f / MathF.PI:0}° ({rig.Joints[seen].Name})");
            }

            // The same crate 7 cm nearer and 3 cm wider: the point is 2 cm inside it.
            Triangle[] intoTriangles = Box(new Vector3(-0.3f, -0.2f, -0.28f), new Vector3(0.03f, 0.2f, 0.02f), place);
            if (new BodyCollision(new TriangleBvh(intoTriangles), model, intoTriangles).OtherBoneColliding(positions, rotations) < 0)
            {
                inside.Add($"{heading * 180f / MathF.PI:0}°");
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(outside, Is.Empty, "headings on which skin 5 cm past the crate's edge was seen inside it");
            Assert.That(inside, Is.Empty, "headings on which skin 2 cm inside the crate was not seen");
        });
    }

    /// <summary>
    /// The link from a Rigify panda's chest to its right shoulder (0.16 m out on a chest 0.24 m wide) is checked no
    /// wider than the chest's skin it runs in: a wall beside the shoulder 1 cm clear of that skin is not hit, one 2 cm
    /// into it is. Before, the link was checked as thick as half its radius, measured from the chest's skin (0.25 m),
    /// and stood 4 cm out of the body: the panda's jumps facing through a 0.9 m door hit the jamb with it and it hopped
    /// through backwards.
    /// </summary>
    [Test]
    public void AShouldersLinkIsNoWiderThanTheChestsSkin()
    {
        CharacterModel model = ForeignCharacters.Panda().Load().Model;
        Rig rig = model.Rig;
        int shoulder = rig.IndexOf("upper_arm.R");
        int chest = rig.Joints[shoulder].Parent;
        (Vector3[] positions, Quaternion[] rotations) = Solve(model, new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity));
        Vector3 at = positions[shoulder];
        float side = MathF.Sign(at.X - positions[chest].X);
        Assume.That(side, Is.Not.Zero, "the shoulder is off the chest's middle");

        // The chest's skin on the shoulder's side, about the shoulder's height and depth.
        float skin = model.Source!.SkinProbes[chest].Select(p => positions[chest] + Vector3.Transform(p, rotations[chest]))
            .Where(p => MathF.Abs(p.Z - at.Z) <= 0.2f).Max(p => side * p.X);
        Assume.That(skin - (side * at.X), Is.GreaterThan(0.05f), "the chest's skin stands out beyond the shoulder");

        Triangle[] Wall(float gap)
        {
            // A wall 0.3 m thick whose face stands gap metres beyond the skin (negative: into it), beside the shoulder.
            float face = side * (skin + gap);
            float back = face + (side * 0.3f);
            Level wall = new LevelBuilder("wall").AddBox(new Vector3(MathF.Min(face, back), at.Y - 0.1f, at.Z - 0.1f), new Vector3(MathF.Max(face, back), at.Y + 0.1f, at.Z + 0.1f)).Build();
            return [.. wall.Triangles];
        }

        Triangle[] clear = Wall(0.01f);
        Triangle[] into = Wall(-0.02f);
        int hit = new BodyCollision(new TriangleBvh(clear), model, clear).OtherBoneColliding(positions, rotations);
        Assert.Multiple(() =>
        {
            Assert.That(hit, Is.LessThan(0), () => $"bone '{rig.Joints[hit].Name}' hits a wall 1 cm clear of the chest's skin");
            Assert.That(new BodyCollision(new TriangleBvh(into), model, into).OtherBoneColliding(positions, rotations), Is.GreaterThanOrEqualTo(0), "a wall 2 cm into the chest's skin is seen");
        });
    }

    /// <summary>
    /// The trunk's own skin is probed: a skin point of the hips 2 cm into a post under it is seen, though no bone's
    /// segment reaches the post (the desert skeleton's pelvis sank 3.3 cm into a dune as it crouched to jump).
    /// </summary>
    [Test]
    public void TheTrunksSkinIsProbed()
    {
        CharacterModel model = Tailed.Value;
        Rig rig = model.Rig;
        int hips = rig.IndexOf("hips");
        Assume.That(model.Limbs.Any(l => rig.IsAncestor(hips, l.RootJoint)), Is.True, "the legs hang from the hips");
        (Vector3[] positions, Quaternion[] rotations) = Solve(model, new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity));
        // The lowest of the hips' skin points at least 8 cm from every bone (no bone's box reaches a slab around it).
        Vector3[] clear = [.. model.Source!.SkinProbes[hips].Select(s => positions[hips] + Vector3.Transform(s, rotations[hips]))
            .Where(p => Enumerable.Range(1, rig.Joints.Count - 1).All(j => ForeignRigTests.SegmentDistance(p, positions[rig.Joints[j].Parent], positions[j]) > 0.08f))];
        Assume.That(clear, Is.Not.Empty, "the hips' skin reaches 8 cm from their bones");
        Vector3 lowest = clear.MinBy(p => p.Y);

        // A post under it, 4 cm square, its top 3 cm above it: the point is 2 cm inside.
        Level slab = new LevelBuilder("post").AddBox(lowest - new Vector3(0.02f, 0.5f, 0.02f), lowest + new Vector3(0.02f, 0.03f, 0.02f)).Build();
        var collision = new BodyCollision(new TriangleBvh(slab.Triangles), model, slab.Triangles);
        Assert.Multiple(() =>
        {
            Assert.That(collision.OtherBoneColliding(positions), Is.EqualTo(-1), "no bone's segment reaches the post");
            Assert.That(collision.OtherBoneColliding(positions, rotations), Is.EqualTo(hips), "the hips' skin does");
        });
    }

    /// <summary>
    /// Skin blended between a leg's first bone and the trunk bone it hangs from (a thigh's top, 0.2 to the hips) is
    /// checked with the leg, where linear blend skinning puts it: a block around it, clear of every bone and rigid
    /// probe, is seen.
    /// </summary>
    [Test]
    public void SkinBlendedWithTheTrunkIsCheckedWithTheLeg()
    {
        CharacterModel model = Tailed.Value;
        Rig rig = model.Rig;
        RigLimb leg = model.Limbs.Single(l => l.Name == "left_hind");
        int trunk = rig.Joints[leg.Chain[0]].Parent;
        (Vector3[] positions, Quaternion[] rotations) = Solve(model, new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity));
        SkinBlend[][] blended = [.. model.Source!.BlendProbes.SelectMany(b => b).Where(b => b.Any(part => part.Joint == trunk) && b.Any(part => leg.Chain.Contains(part.Joint)))];
        Assume.That(blended, Is.Not.Empty, "the thigh's top is skinned partly to the hips");
        Vector3 Blended(SkinBlend[] blend) => blend.Aggregate(Vector3.Zero, (sum, part) => sum + (part.Weight * (positions[part.Joint] + Vector3.Transform(part.Point, rotations[part.Joint]))));
        // Everything else the leg's check sees: its rigid skin and its blended skin not carried by the trunk, its bones.
        Vector3[] others = [
            .. Enumerable.Range(0, rig.Joints.Count).SelectMany(j => model.Source.SkinProbes[j].Select(s => positions[j] + Vector3.Transform(s, rotations[j]))),
            .. model.Source.BlendProbes.SelectMany(b => b).Where(b => !b.Any(part => part.Joint == trunk)).Select(Blended)];
        float Clear(Vector3 p) => MathF.Min(others.Min(o => Vector3.Distance(o, p)), Enumerable.Range(1, rig.Joints.Count - 1).Min(j => ForeignRigTests.SegmentDistance(p, positions[rig.Joints[j].Parent], positions[j])));
        SkinBlend[] loneliest = blended.MaxBy(b => Clear(Blended(b)))!;
        Vector3 at = Blended(loneliest);
        float clear = Clear(at);
        Assume.That(clear, Is.GreaterThan(0.035f), "a blended point with no other probe or bone near it");

        float half = 0.8f * clear / MathF.Sqrt(3f);
        Level block = new LevelBuilder("block").AddBox(at - new Vector3(half), at + new Vector3(half)).Build();
        var collision = new BodyCollision(new TriangleBvh(block.Triangles), model, block.Triangles);
        Assert.That(collision.LimbCollides(leg, positions, rotations, null), Is.True, $"the thigh's top, blended with the trunk, {half * 100f:0.0} cm inside a block");
    }

    /// <summary>
    /// How deep a loaded rig's foot skin lies below a held ground plane (<see cref="BodyCollision.SoleSink"/>, by which
    /// the gait holds a panda's foot higher where its skin, blended with the shin, would sink): the tailed quadruped's
    /// hind foot sinks at least as far as a plane is raised above its foot's lowest skin point, and not at all below a
    /// plane under every point of it; a character built in code (its bone boxes are no skin) reads 0 whatever the plane.
    /// </summary>
    [Test]
    public void ASolesSinkIsReadFromTheFootsSkin()
    {
        CharacterModel model = Tailed.Value;
        RigLimb foot = model.Limbs.Single(l => l.Name == "left_hind");
        (Vector3[] positions, Quaternion[] rotations) = Solve(model, new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity));
        int effector = foot.EffectorJoint;
        float lowest = model.Source!.SkinProbes[effector].Min(s => (positions[effector] + Vector3.Transform(s, rotations[effector])).Y);
        Level floor = new LevelBuilder("floor").AddFloor(-2f, -2f, 2f, 2f, 0f).Build();
        var collision = new BodyCollision(new TriangleBvh(floor.Triangles), model, floor.Triangles);
        float Sink(float planeY) => collision.SoleSink(foot, positions, rotations, new Vector3(positions[effector].X, planeY, positions[effector].Z), Vector3.UnitY);

        CharacterModel built = CharacterPresets.Model("skeleton");
        (Vector3[] builtPositions, Quaternion[] builtRotations) = Solve(built, new RootPose(Vector3.Zero, Quaternion.Identity));
        var builtCollision = new BodyCollision(new TriangleBvh(floor.Triangles), built, floor.Triangles);
        Assert.Multiple(() =>
        {
            Assert.That(Sink(lowest + 0.05f), Is.GreaterThanOrEqualTo(0.05f - 1e-4f), "a plane 5 cm above the foot's lowest skin point");
            Assert.That(Sink(lowest - 0.5f), Is.EqualTo(0f), "a plane half a metre under the foot");
            Assert.That(builtCollision.SoleSink(built.Limbs[0], builtPositions, builtRotations, new Vector3(0f, 10f, 0f), Vector3.UnitY), Is.EqualTo(0f), "a character built in code");
        });
    }

    /// <summary>
    /// A foot's sole where the GLB draws it (<see cref="BodyCollision.SoleHeight"/>, by which a walking step's first and
    /// last moments count in its contact phase only while the drawn foot touches the ground): the spider's tarsus skin
    /// is blended a fifth with its tibia, so as the tarsus joint bends, the drawn sole leaves the points that stand
    /// rigidly on the tarsus. In the contact pose the lowest drawn point is the lowest rigid one; with the tarsus
    /// turned 0.5 rad about its third axis it stands at least 2 mm above it, 2.7 mm measured (on a dune's 34° side,
    /// as the tibia leaned over a held foot, the drawn foot stood about 1 cm above the rigid one, and the spider's feet
    /// floated 1.5–2.0 cm in walks where the rigid points were read); a character built in code has no skin and
    /// reads +∞.
    /// </summary>
    [Test]
    public void AFootsSoleIsReadWhereTheGlbDrawsItNotWhereItsRigidPointsStand()
    {
        CharacterModel model = Spider.Value;
        RigLimb leg = model.Limbs[0];
        Level floor = new LevelBuilder("floor").AddFloor(-2f, -2f, 2f, 2f, 0f).Build();
        var collision = new BodyCollision(new TriangleBvh(floor.Triangles), model, floor.Triangles);
        var root = new RootPose(new Vector3(0f, 1f, 0f), Quaternion.Identity);

        // The lowest drawn point and the lowest of every point read off a plane a metre above the foot.
        (float Drawn, float Rigid) Lowest(float bend)
        {
            float[] q = (float[])model.ContactPose.Clone();
            q[model.Rig.FirstDof(leg.EffectorJoint) + 2] += bend;
            var positions = new Vector3[model.Rig.Joints.Count];
            var rotations = new Quaternion[model.Rig.Joints.Count];
            model.Rig.Solve(root, q, positions, rotations);
            var above = new Vector3(positions[leg.EffectorJoint].X, positions[leg.EffectorJoint].Y + 1f, positions[leg.EffectorJoint].Z);
            return (above.Y + collision.SoleHeight(leg, positions, rotations, above, Vector3.UnitY), above.Y - collision.SoleSink(leg, positions, rotations, above, Vector3.UnitY));
        }

        (float drawn, float rigid) = Lowest(-0.5f);
        (float drawnInPose, float rigidInPose) = Lowest(0f);
        CharacterModel built = CharacterPresets.Model("skeleton");
        (Vector3[] builtPositions, Quaternion[] builtRotations) = Solve(built, root);
        var builtCollision = new BodyCollision(new TriangleBvh(floor.Triangles), built, floor.Triangles);
        Assert.Multiple(() =>
        {
            Assert.That(model.Rig.DofsOf(leg.EffectorJoint), Is.EqualTo(3), "the tarsus joint turns about three axes");
            Assert.That(drawnInPose, Is.EqualTo(rigidInPose).Within(1e-4f), "in the contact pose the drawn sole is the rigid one");
            Assert.That(drawn - rigid, Is.GreaterThanOrEqualTo(0.002f), $"bent: drawn {drawn:0.0000} m, rigid {rigid:0.0000} m");
            Assert.That(builtCollision.SoleHeight(built.Limbs[0], builtPositions, builtRotations, Vector3.Zero, Vector3.UnitY), Is.EqualTo(float.PositiveInfinity), "a character built in code");
        });
    }

    /// <summary>
    /// A skin point is inside the level exactly where its nearest surface (within <see cref="BodyCollision.SkinReach"/>)
    /// faces away from it by more than <see cref="BodyCollision.SkinDepth"/>, whichever shortcut the check takes (a
    /// point in front of every nearby triangle's plane is passed without looking for the nearest): 6,000 seeded points
    /// within 8 cm of the surfaces of levels in other tools' shapes (stairs, thin slabs, curved dunes, a doorway's
    /// jambs and lintel), in front of and behind them, against the definition worked out over every triangle.
    /// </summary>
    [TestCase("stairs")]
    [TestCase("thin-slabs")]
    [TestCase("curved")]
    [TestCase("doorway")]
    public void SkinIsInsideWhereItsNearestSurfaceFacesAway(string levelName)
    {
        Level level = ForeignLevels.Get(levelName).Level;
        IReadOnlyList<Triangle> triangles = level.Triangles;
        var collision = new BodyCollision(level.Bvh, Tailed.Value, triangles);
        var random = new Random(11);
        var near = new List<int>();
        var closest = new Vector3[triangles.Count];
        float[] distance = new float[triangles.Count];
        var wrong = new List<string>();
        (int inside, int outside, int behindSomePlane) = (0, 0, 0);
        while (inside + outside < 1_500)
        {
            Triangle t = triangles[random.Next(triangles.Count)];
            float u = random.NextSingle();
            float v = random.NextSingle() * (1f - u);
            Vector3 p = t.A + (u * (t.B - t.A)) + (v * (t.C - t.A)) + (t.Normal * ((random.NextSingle() * 0.16f) - 0.08f))
                + new Vector3((random.NextSingle() - 0.5f) * 0.1f, (random.NextSingle() - 0.5f) * 0.1f, (random.NextSingle() - 0.5f) * 0.1f);

            // The definition, over every triangle: the nearest distance, and among the triangles that near (within the
            // tie), the one the point is most in front of decides.
            for (int k = 0; k < triangles.Count; k++)
            {
                closest[k] = triangles[k].ClosestPoint(p);
                distance[k] = Vector3.Distance(closest[k], p);
            }

            float nearest = distance.Min();
            if (nearest > 0.09f)
            {
                continue; // beyond the check's reach: not seen either way
            }

            float front = float.NegativeInfinity;
            bool behindPlane = false;
            for (int k = 0; k < triangles.Count; k++)
            {
                if (distance[k] <= nearest + BodyCollision.EdgeTie)
                {
                    front = MathF.Max(front, Vector3.Dot(p - closest[k], triangles[k].Normal));
                }

                behindPlane |= distance[k] <= BodyCollision.SkinReach && Vector3.Dot(p - triangles[k].A, triangles[k].Normal) < 0f;
            }

            bool expected = nearest > BodyCollision.SkinDepth && front < 0f;
            behindSomePlane += behindPlane && !expected ? 1 : 0;

            near.Clear();
            level.Bvh.TrianglesNear(new Aabb(p, p).Inflate(BodyCollision.SkinReach), near);
            bool seen = collision.Inside(p, near, out _, out _);
            if (seen != expected)
            {
                wrong.Add($"{p}: {(seen ? "inside" : "outside")}, the nearest surface {nearest:0.000} m away {(expected ? "faces away" : "does not face away")}");
            }

            (inside, outside) = expected ? (inside + 1, outside) : (inside, outside + 1);
        }

        Assert.Multiple(() =>
        {
            Assert.That(wrong, Is.Empty, $"points the check reads otherwise than the definition on the {levelName}");
            Assert.That(inside, Is.GreaterThan(100), "points inside in the sample");
            Assert.That(behindSomePlane, Is.GreaterThan(20), "points outside but behind some nearby triangle's plane in the sample (the shortcut cannot pass them)");
        });
    }

    /// <summary>
    /// The skin of a bone that belongs to no limb lies within its bound's radius of its joint in every pose, so that a
    /// bone whose sphere has no triangle near it is rightly passed without posing its skin: 300 seeded configurations
    /// (every angle drawn over a full turn, clamped into its limits) of the tailed quadruped (its skin blended between
    /// its spine and tail bones), the spider (its abdomen weighted to its cephalothorax) and the skeleton (bone boxes),
    /// each with a point weighted to two bones far apart added.
    /// </summary>
    [TestCase("tailed")]
    [TestCase("spider")]
    [TestCase("skeleton")]
    public void AFreeBonesSkinLiesWithinItsBound(string rig)
    {
        CharacterModel model = rig switch { "tailed" => Tailed.Value, "spider" => Spider.Value, _ => CharacterPresets.Model(rig) };
        Triangle[] floor = Box(new Vector3(-1f, -1f, -1f), new Vector3(1f, 0f, 1f), Matrix4x4.Identity);
        var collision = new BodyCollision(new TriangleBvh(floor), model, floor);
        // Each bone's skin, and its blended points alone with a bound of their own (the rigid points' reach would
        // cover a blended bound that ignored how far apart its bones' joints stand).
        var skins = collision.FreeSkins.ToArray();
        skins = [.. skins, .. skins.Select(s => (s.Joint, Probes: s.Probes.Where(p => p.Blend is not null).ToArray(), s.Bound))
            .Where(s => s.Probes.Length > 0).Select(s => (s.Joint, s.Probes, BodyCollision.SkinReachBound.Of(s.Probes)))];

        // And a point weighted half to the first such bone and half to the rig's last joint (bones far apart, as a
        // careless weight paint joins them): its bound must reach across the joints between.
        int last = model.Rig.Joints.Count - 1;
        (int, Vector3, SkinBlend[]?)[] painted = [(skins[0].Joint, Vector3.Zero, [new SkinBlend(skins[0].Joint, 0.5f, new Vector3(0f, 0.01f, 0f)), new SkinBlend(last, 0.5f, new Vector3(0.02f, 0f, 0f))])];
        skins = [.. skins, (skins[0].Joint, painted, BodyCollision.SkinReachBound.Of(painted))];
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        var random = new Random(5);
        float[] q = new float[model.Rig.DofCount];
        (float worst, int blended) = (0f, collision.FreeSkins.Sum(s => s.Probes.Count(p => p.Blend is not null)));
        for (int k = 0; k < 300; k++)
        {
            for (int d = 0; d < q.Length; d++)
            {
                q[d] = (random.NextSingle() * 2f * MathF.PI) - MathF.PI;
            }

            model.Rig.Clamp(q);
            var root = new RootPose(new Vector3(random.NextSingle() * 40f, random.NextSingle(), random.NextSingle() * -40f), Quaternion.Normalize(new Quaternion(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f)));
            model.Rig.Solve(root, q, positions, rotations);
            foreach ((int joint, var probes, BodyCollision.SkinReachBound bound) in skins)
            {
                float radius = bound.Radius(positions, joint);
                foreach (var probe in probes)
                {
                    worst = MathF.Max(worst, Vector3.Distance(BodyCollision.Posed(probe, positions, rotations), positions[joint]) / radius);
                }
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(skins, Is.Not.Empty, $"the {rig}'s bones outside its limbs carry skin");
            Assert.That(worst, Is.LessThanOrEqualTo(1f), $"the farthest posed skin point of the {rig}, in its bound's radius");
            Assert.That(worst, Is.GreaterThan(0.5f), "the bound is not loose beyond use");
            Assert.That(blended, rig == "skeleton" ? Is.EqualTo(0) : Is.GreaterThan(0), "blended skin points of the rig's own");
        });
    }

    /// <summary>
    /// The bones of no limb are passed at once when no triangle is near a box around all their ends: the same bone
    /// found in the level, or none, as checking each bone every time, over 400 seeded poses (every angle drawn over a
    /// full turn, clamped into its limits; the root 0–1.2 m above a floor with a crate on it, turned anyhow) of the
    /// tailed quadruped, the spider and the skeleton; in some poses a bone is in the level, in others no triangle is
    /// near the box.
    /// </summary>
    [TestCase("tailed")]
    [TestCase("spider")]
    [TestCase("skeleton")]
    public void ABoxAroundTheTrunksBonesPassesOnlyPosesNoneOfThemTouches(string rig)
    {
        CharacterModel model = rig switch { "tailed" => Tailed.Value, "spider" => Spider.Value, _ => CharacterPresets.Model(rig) };
        Triangle[] level = [.. Box(new Vector3(-4f, -1f, -4f), new Vector3(4f, 0f, 4f), Matrix4x4.Identity), .. Box(new Vector3(0.3f, 0f, -0.5f), new Vector3(1.3f, 0.6f, 0.5f), Matrix4x4.Identity)];
        var bvh = new TriangleBvh(level);
        var boxed = new BodyCollision(bvh, model, level);
        var each = new BodyCollision(bvh, model, level) { BoxesOtherBones = false };
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        var random = new Random(11);
        float[] q = new float[model.Rig.DofCount];
        var wrong = new List<string>();
        (int touching, int clear) = (0, 0);
        for (int k = 0; k < 400; k++)
        {
            for (int d = 0; d < q.Length; d++)
            {
                q[d] = (random.NextSingle() * 2f * MathF.PI) - MathF.PI;
            }

            model.Rig.Clamp(q);
            var root = new RootPose(new Vector3((random.NextSingle() * 3f) - 1f, random.NextSingle() * 1.2f, random.NextSingle() - 0.5f), Quaternion.Normalize(new Quaternion(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f)));
            model.Rig.Solve(root, q, positions, rotations);
            int expected = each.OtherBoneColliding(positions);
            int found = boxed.OtherBoneColliding(positions);
            if (found != expected)
            {
                wrong.Add($"pose {k}: bone {found} found, {expected} checking each");
            }

            touching += expected >= 0 ? 1 : 0;
            clear += TrianglesNear(bvh, model, positions) ? 0 : 1;
        }

        Assert.Multiple(() =>
        {
            Assert.That(wrong, Is.Empty);
            Assert.That(touching, Is.GreaterThan(20), $"poses of the {rig} with a bone of no limb in the level");
            Assert.That(clear, Is.GreaterThan(20), $"poses of the {rig} whose bones of no limb have no triangle near their ends' bounds");
        });
    }

    /// <summary>Whether a triangle of <paramref name="bvh"/> has bounds within 5 cm of the bounds of the ends of <paramref name="model"/>'s bones that belong to no limb.</summary>
    private static bool TrianglesNear(TriangleBvh bvh, CharacterModel model, Vector3[] positions)
    {
        var limbJoints = new HashSet<int>(model.Limbs.SelectMany(l => l.Chain));
        int[] others = [.. Enumerable.Range(0, model.Rig.Joints.Count).Where(j => model.Rig.Joints[j].Parent >= 0 && !limbJoints.Contains(j))];
        Vector3 min = others.Select(j => Vector3.Min(positions[j], positions[model.Rig.Joints[j].Parent])).Aggregate(Vector3.Min);
        Vector3 max = others.Select(j => Vector3.Max(positions[j], positions[model.Rig.Joints[j].Parent])).Aggregate(Vector3.Max);
        return bvh.AnyTriangleNear(new Aabb(min - new Vector3(0.05f), max + new Vector3(0.05f)));
    }
}
