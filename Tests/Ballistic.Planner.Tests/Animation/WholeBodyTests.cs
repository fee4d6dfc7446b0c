using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>Every bone checked, feet that do not teleport, stances at the rig's own height.</summary>
public sealed class WholeBodyTests
{
    [Test]
    public void BonesOfNoLimbAreCheckedToo()
    {
        // The tailed quadruped from another tool: its tail and head are in no limb.
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-tail-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            (string gltf, string spec) = ForeignCharacters.TailedQuadruped().Write(folder);
            (CharacterModel model, _) = CharacterSpecFile.Load(gltf, spec);
            Rig rig = model.Rig;
            var positions = new Vector3[rig.Joints.Count];
            var rotations = new Quaternion[rig.Joints.Count];
            rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
            Level far = new LevelBuilder("far").AddFloor(-5f, -5f, 5f, 5f, -20f).Build();
            var clear = new BodyCollision(new TriangleBvh(far.Triangles), model);
            Assert.That(clear.OtherBoneColliding(positions), Is.EqualTo(-1));
            Assert.That(clear.OtherBones.Select(j => rig.Joints[j].Name), Has.Some.Contains("tail"));

            // A floor through the middle of each tail bone in turn: that bone is found.
            foreach (int j in clear.OtherBones.Where(j => rig.Joints[j].Name.Contains("tail", StringComparison.Ordinal)))
            {
                Vector3 mid = (positions[rig.Joints[j].Parent] + positions[j]) * 0.5f;
                var across = new LevelBuilder("cut");
                Vector3 along = Vector3.Normalize(positions[j] - positions[rig.Joints[j].Parent]);
                Vector3 side = Vector3.Normalize(Vector3.Cross(along, MathF.Abs(along.Y) < 0.9f ? Vector3.UnitY : Vector3.UnitX));
                Vector3 other = Vector3.Cross(along, side);
                Vector3[] quad = [mid - side - other, mid + side - other, mid + side + other, mid - side + other];
                across.AddMesh("plane", quad, [0, 1, 2, 0, 2, 3], Matrix4x4.Identity, TestLevels.Ground);
                var cut = new BodyCollision(new TriangleBvh(across.Build().Triangles), model);
                Assert.That(cut.OtherBoneColliding(positions), Is.Not.EqualTo(-1), $"a plane through {rig.Joints[j].Name} is seen");
            }
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    /// <summary>
    /// A character built in code is checked by the corners of the bone boxes its GLB draws: a wall a few millimetres
    /// beside every bone of a leg but inside the leg's boxes (as wide as the bones' radii) is seen when the checker has
    /// the level's triangles, and was not by the bones alone (the skeleton's foot box went 4.5 cm into a debris block on
    /// the holes-and-debris level, its ankle and knee boxes 3.5-3.8 cm into a dune and a block, in plans reported exact).
    /// </summary>
    [TestCase("skeleton")]
    [TestCase("jumperman")]
    public void ABuiltCharactersBoneBoxesAreKeptOutOfTheLevel(string name)
    {
        CharacterModel model = CharacterPresets.Model(name);
        Rig rig = model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        Vector3[][] boxes = BoneBoxes.Of(model).InJointFrames();
        int tested = 0;
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            // Farthest out to the limb's own side (model +X is the left) of its bones, and of its boxes' corners.
            float side = MathF.Sign(positions[limb.RootJoint].X - positions[0].X);
            int[] bones = [.. Enumerable.Range(0, rig.Joints.Count).Where(j => (limb.Chain.Contains(j) && j != limb.RootJoint) || rig.IsAncestor(limb.EffectorJoint, j))];
            float boneOut = bones.Max(j => MathF.Max(side * positions[j].X, side * positions[rig.Joints[j].Parent].X));
            boneOut = MathF.Max(boneOut, side * limb.EffectorPosition(positions, rotations).X);
            float boxOut = limb.Chain.Concat(bones).Distinct().SelectMany(j => boxes[j].Select(p => side * (positions[j] + Vector3.Transform(p, rotations[j])).X)).Max();
            if (boxOut < boneOut + 0.03f)
            {
                continue; // this leg's boxes do not reach far enough beyond its bones to tell
            }

            float x = side * (boneOut + 0.005f);
            SeenOnlyWithItsSkin(model, limb, positions, rotations, new Vector3(MathF.Min(x, x + side), -5f, -5f), new Vector3(MathF.Max(x, x + side), 5f, 5f), $"{limb.Name}'s boxes reach {(boxOut - boneOut) * 100f:0.0} cm beyond its bones, into the wall");
            tested++;
        }

        Assert.That(tested, Is.GreaterThan(0), "a leg whose boxes reach beyond its bones");
    }

    /// <summary>
    /// A loaded rig's skinned feet reach beyond the segments between their joints (toes, heels): a wall just clear of
    /// every bone of a foot's limb but inside the foot's skin is seen when the checker has the level's triangles, and
    /// was not by the bones alone (the armature human's toes went 8.2 cm into a stair).
    /// </summary>
    [TestCase("tailed")]
    [TestCase("human")]
    public void ALoadedRigsSkinnedFeetAreKeptOutOfTheLevel(string rigName)
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-skin-{Guid.NewGuid():N}");
        try
        {
            (CharacterModel model, _) = ForeignCharacters.Named(rigName).Load(folder);
            Rig rig = model.Rig;
            var positions = new Vector3[rig.Joints.Count];
            var rotations = new Quaternion[rig.Joints.Count];
            rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
            IReadOnlyList<Vector3[]> skin = model.Source!.SkinProbes;
            int tested = 0;
            foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
            {
                // Farthest forward (+Z) of the limb's bones, and of the skin of its foot (effector and below).
                int[] bones = [.. Enumerable.Range(0, rig.Joints.Count).Where(j => limb.Chain.Contains(j) || rig.IsAncestor(limb.EffectorJoint, j))];
                float boneFront = bones.Max(j => positions[j].Z);
                boneFront = MathF.Max(boneFront, limb.EffectorPosition(positions, rotations).Z);
                float skinFront = bones.Where(j => j == limb.EffectorJoint || rig.IsAncestor(limb.EffectorJoint, j))
                    .SelectMany(j => skin[j].Select(p => (positions[j] + Vector3.Transform(p, rotations[j])).Z))
                    .DefaultIfEmpty(float.NegativeInfinity).Max();
                if (skinFront < boneFront + 0.03f)
                {
                    continue; // this foot's skin does not reach far enough beyond its bones to tell
                }

                SeenOnlyWithItsSkin(model, limb, positions, rotations, new Vector3(-5f, -5f, boneFront + 0.005f), new Vector3(5f, 5f, boneFront + 1f), $"{limb.Name}'s skin reaches {(skinFront - boneFront) * 100f:0.0} cm beyond its bones, into the wall");
                tested++;
            }

            Assert.That(tested, Is.GreaterThan(0), "a foot whose skin reaches beyond its bones");
        }
        finally
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        }
    }

    [Test]
    public void ContactsChangeOnlyByStepsBetweenJumps()
    {
        // Desert, many jumps: no limb's contact moves more than 2 cm within 0.1 s, and stances with steps take time.
        Level level = SharedLevels.Bundled("desert");
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        var planner = new AnimatedPlanner(scene, new JumpAnimator(scene, CharacterPresets.Model("skeleton")));
        (AnimatedPlan plan, _) = planner.BakeAndPlan(LevelPoints.Ground(scene.Bvh, 7.7f, 5.8f)!.Value, LevelPoints.Ground(scene.Bvh, -7.5f, -8.5f)!.Value, new BakeSettings { MaxNodes = 600, Threads = 2, Locomotion = Locomotion.Jump });
        Assert.That(plan.Result.Status, Is.EqualTo(PlannerStatus.Exact), plan.Result.Reason);
        JumpAnimation animation = plan.Animation!;
        Assert.That(animation.Arcs, Has.Count.GreaterThan(2));
        foreach (IGrouping<int, ContactPhase> limb in animation.ContactPhases.GroupBy(p => p.Limb))
        {
            ContactPhase[] phases = [.. limb.OrderBy(p => p.From)];
            for (int i = 1; i < phases.Length; i++)
            {
                float gap = phases[i].From - phases[i - 1].To;
                Assert.That(gap, Is.GreaterThanOrEqualTo(-1e-4f), "phases of one limb do not overlap");
                if (Vector3.Distance(phases[i].Position, phases[i - 1].Position) > 0.02f)
                {
                    Assert.That(gap, Is.GreaterThanOrEqualTo(JumpAnimator.MinAirTime - 1e-3f), $"{animation.Model.Limbs[limb.Key].Name} jumps to a new contact at {phases[i].From:0.000} s");
                }
            }
        }

        // Every stance between two jumps lasts the least ground time (longer with steps); its root only sinks below the
        // landing pose (absorbing, crouching; leaning by half the drop where the legs ask), by at most the dip's share
        // of a 1 m leg, never rising above it.
        for (int j = 0; j < animation.Stances.Count; j++)
        {
            float stance = animation.Stances[j];
            Assert.That(stance, Is.GreaterThanOrEqualTo(StanceDip.MinGroundTime - 1e-4f));
            float start = animation.JumpStart(j) + animation.Arcs[j].FlightTime;
            for (float t = start; t <= start + stance; t += 0.05f)
            {
                Vector3 root = animation.RootAt(t).Position;
                Vector3 end = animation.Arcs[j].End;
                Assert.That(end.Y - root.Y, Is.InRange(-1e-3f, StanceDip.DepthShare * 1f));
                Assert.That(new Vector2(root.X - end.X, root.Z - end.Z).Length(), Is.LessThanOrEqualTo((0.5f * (end.Y - root.Y)) + 0.01f));
            }
        }
    }

    [TestCase("skeleton", true)]
    [TestCase("jumperman", true)]
    [TestCase("frog", false)]
    public void StancesStandAtTheRigsOwnHeightNotSquatting(string name, bool legsReachStanding)
    {
        // Root joint (pelvis, thorax) at least 70 % of its standing height above the contacts, at most all of it.
        ReducedCharacter character = CharacterPresets.Get(name);
        CharacterModel model = CharacterPresets.Model(name);
        Level floor = new LevelBuilder("floor").AddFloor(-10f, -10f, 10f, 10f, 0f, n: 8).Build();
        var scene = PlanningScene.Create(floor, character);
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 9, MaxNodes = 60, Threads = 2 });
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.Rig.Neutral(), positions, rotations);
        float standing = positions[0].Y - model.Limbs.Select(l => l.EffectorPosition(positions, rotations).Y).Order().Take(character.RequiredContacts).Average();
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        standing = MathF.Max(standing, positions[0].Y - model.Limbs.Select(l => l.EffectorPosition(positions, rotations).Y).Order().Take(character.RequiredContacts).Average());
        Assert.That(bake.Roadmap.Nodes, Has.Count.EqualTo(60));

        // The frog's forelegs do not reach the ground at its standing height: its range slides down to what they reach.
        Assert.That(scene.Sampler.Lift.Min >= character.StanceLift.Min - 1e-5f, Is.EqualTo(legsReachStanding));
        foreach (RoadmapNode node in bake.Roadmap.Nodes)
        {
            float rootJoint = node.Pose.ToWorld(model.Rig.RootOffset + model.Rig.Joints[0].Offset).Y;
            Assert.That(rootJoint, Is.LessThanOrEqualTo(standing + 1e-3f), $"{name} node {node.Id} above its standing height");
            if (legsReachStanding)
            {
                Assert.That(rootJoint, Is.GreaterThanOrEqualTo((0.7f * standing) - 1e-3f), $"{name} node {node.Id} squats");
            }
        }
    }

    /// <summary>
    /// A wall (the box from <paramref name="min"/> to <paramref name="max"/>) that <paramref name="limb"/>'s bones clear
    /// but its skin reaches: the checker without the level's triangles (bones only) passes the pose, with them it does not.
    /// </summary>
    private static void SeenOnlyWithItsSkin(CharacterModel model, RigLimb limb, Vector3[] positions, Quaternion[] rotations, Vector3 min, Vector3 max, string reaches)
    {
        Level wall = new LevelBuilder("wall").AddBox(min, max).Build();
        var bvh = new TriangleBvh(wall.Triangles);
        Assert.Multiple(() =>
        {
            Assert.That(new BodyCollision(bvh, model).LimbCollides(limb, positions, rotations, null), Is.False, $"{limb.Name}'s bones are clear of the wall");
            Assert.That(new BodyCollision(bvh, model, wall.Triangles).LimbCollides(limb, positions, rotations, null), Is.True, reaches);
        });
    }
}
