using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Surfaces;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Contacts;

public sealed class ContactEstimatorTests
{
    [Test]
    public void SkeletonStandingOnAFloorTouchesWithBothFeetUnderTheirHomes()
    {
        Level level = new LevelBuilder("t").AddFloor(-5f, -5f, 5f, 5f, 0f).Build();
        ContactEstimator estimator = Estimator(level, CharacterPresets.Skeleton());
        var pose = new RootPose(new Vector3(0.3f, 1.1f, -0.2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.4f));
        PoseEvaluation evaluation = estimator.Evaluate(pose);
        ReducedCharacter skeleton = CharacterPresets.Skeleton();

        Assert.That(evaluation.Validity, Is.EqualTo(PoseValidity.Valid));
        Assert.That(evaluation.Contacts.Select(c => skeleton.Limbs[c.Limb].Name), Is.EquivalentTo(new[] { "left_foot", "right_foot" }));
        foreach (Contact c in evaluation.Contacts)
        {
            // On the floor, inside the workspace, under the foot's home (where the contact pose holds it), with the
            // floor's normal and the default μ.
            OrientedBox workspace = skeleton.Limbs[c.Limb].WorkspaceAt(pose);
            Assert.That(skeleton.Limbs[c.Limb].Home, Is.Not.Null);
            Vector3 under = pose.ToWorld(skeleton.Limbs[c.Limb].Home!.Value) with { Y = 0f };
            Assert.That(workspace.Contains(under), Is.True);
            Assert.That(c.Position.Y, Is.EqualTo(0f).Within(1e-5f));
            Assert.That(Vector3.Distance(c.Position, under), Is.LessThan(1e-3f));
            Assert.That(Vector3.Distance(c.Normal, Vector3.UnitY), Is.LessThan(1e-5f));
            Assert.That(c.Mu, Is.EqualTo(0.5f));
        }

        Assert.That(Vector3.Distance(evaluation.Cone.Axis, Vector3.UnitY), Is.LessThan(1e-5f));
    }

    [Test]
    public void AWorkspacePiercingAThinSlabTakesItsTopNeverItsUnderside()
    {
        // 3 cm slabs at several heights under a frog (no normal filter: it accepts any face): the workspaces reach
        // through the slab, so both faces lie inside them; only the top faces the trunk.
        ReducedCharacter frog = CharacterPresets.Frog();
        foreach (float thickness in new[] { 0.02f, 0.05f, 0.1f })
        {
            Level level = new LevelBuilder("slab").AddBox(new Vector3(-1f, -thickness, -1f), new Vector3(1f, 0f, 1f)).Build();
            ContactEstimator estimator = Estimator(level, frog);
            for (float lift = 0.07f; lift <= 0.13f; lift += 0.02f)
            {
                var pose = new RootPose(new Vector3(0f, lift, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, lift * 10f));
                PoseEvaluation evaluation = estimator.Evaluate(pose);
                Assert.That(evaluation.Contacts, Is.Not.Empty, $"{thickness} m slab, lift {lift}");
                foreach (Contact c in evaluation.Contacts)
                {
                    Assert.That(c.Normal.Y, Is.GreaterThan(0.99f), $"{frog.Limbs[c.Limb].Name} takes a face turned away from the trunk ({thickness} m slab, lift {lift})");
                    Assert.That(c.Position.Y, Is.EqualTo(0f).Within(1e-4f));
                }

                if (evaluation.IsValid)
                {
                    Assert.That(evaluation.Cone.Axis.Y, Is.GreaterThan(0.99f), "the cone is not tilted by an underside");
                }
            }
        }
    }

    [Test]
    public void EstimatedContactsOnCurvedGroundLieOnTheMeshWithItsNormal()
    {
        (Level level, _) = ForeignLevels.Get("curved");
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        ContactEstimator estimator = Estimator(level, skeleton);
        var bvh = new TriangleBvh(level.Triangles);
        var random = new Random(5);
        int checkedContacts = 0;
        for (int i = 0; i < 300; i++)
        {
            float x = -6f + (12f * (float)random.NextDouble());
            float z = -6f + (12f * (float)random.NextDouble());
            var pose = new RootPose(new Vector3(x, ForeignLevels.CurvedHeight(x, z) + 1.1f, z), Quaternion.CreateFromAxisAngle(Vector3.UnitY, (float)random.NextDouble() * 6f));
            PoseEvaluation evaluation = estimator.Evaluate(pose);
            foreach (Contact c in evaluation.Contacts)
            {
                var near = new List<int>();
                bvh.TrianglesNear(new Aabb(c.Position - new Vector3(0.05f), c.Position + new Vector3(0.05f)), near);
                int nearest = near.MinBy(t => Vector3.Distance(level.Triangles[t].ClosestPoint(c.Position), c.Position));
                Assert.That(Vector3.Distance(level.Triangles[nearest].ClosestPoint(c.Position), c.Position), Is.LessThanOrEqualTo(1e-3f), "contact on the mesh");
                Assert.That(near.Any(t => Vector3.Distance(level.Triangles[t].ClosestPoint(c.Position), c.Position) < 1e-3f && Vector3.Dot(level.Triangles[t].Normal, c.Normal) > 0.9999f), Is.True, "with the normal of a triangle it lies on");
                Assert.That(skeleton.Limbs[c.Limb].WorkspaceAt(pose).Contains(c.Position), Is.True, "inside its workspace");
                checkedContacts++;
            }
        }

        Assert.That(checkedContacts, Is.GreaterThan(200));
    }

    [Test]
    public void AContactIsTheNearestPointUnderItsHomeOfItsSurfacesPatchInTheWorkspace([Values("curved", "field")] string name)
    {
        // The definition worked out over every triangle of the level: of the pieces of the contact's surface inside
        // the limb's workspace (touching it with some area, facing the trunk, accepted by the limb), the one whose
        // nearest point to the limb's home is nearest gives the contact: that point, or the piece's centre when the
        // point lies outside the workspace. Neither level has a brink for the ledge rule to move a foot off.
        (Level level, _) = ForeignLevels.Get(name);
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        ContactEstimator estimator = Estimator(level, skeleton);
        SurfaceSet surfaces = SurfaceSet.Build(level);
        var bvh = new TriangleBvh(level.Triangles);
        var random = new Random(17);
        int checkedContacts = 0;
        int clippedPieces = 0;
        for (int i = 0; i < 120; i++)
        {
            float x = -5f + (10f * (float)random.NextDouble());
            float z = -5f + (10f * (float)random.NextDouble());
            bvh.Raycast(new Vector3(x, 20f, z), new Vector3(0f, -40f, 0f), 1f, out RayHit ground);
            var pose = new RootPose(ground.Point + new Vector3(0f, 0.9f + (0.3f * (float)random.NextDouble()), 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, (float)random.NextDouble() * 6.3f));
            foreach (Contact c in estimator.Evaluate(pose).Contacts)
            {
                Limb limb = skeleton.Limbs[c.Limb];
                OrientedBox workspace = limb.WorkspaceAt(pose);
                Vector3 aim = pose.ToWorld(limb.Home!.Value);
                float nearest = float.PositiveInfinity;
                Vector3 expected = default;
                for (int t = 0; t < level.Triangles.Count; t++)
                {
                    Triangle triangle = level.Triangles[t];
                    if (surfaces.SurfaceOf(t) != c.Surface || !limb.Filter.Accepts(triangle.Normal) || !workspace.Intersects(triangle))
                    {
                        continue;
                    }

                    (float area, Vector3 centre) = BoxClipper.ClipArea(workspace, triangle);
                    if (!(area > 0f) || !ContactEstimator.FacesTrunk(triangle.Normal, centre, pose.Position))
                    {
                        continue;
                    }

                    clippedPieces += area < triangle.Area * 0.999f ? 1 : 0;
                    Vector3 closest = triangle.ClosestPoint(aim);
                    if (Vector3.DistanceSquared(closest, aim) < nearest)
                    {
                        nearest = Vector3.DistanceSquared(closest, aim);
                        expected = workspace.Contains(closest) ? closest : centre;
                    }
                }

                Assert.That(Vector3.Distance(c.Position, expected), Is.LessThan(1e-5f), $"pose {i}, {limb.Name}");
                checkedContacts++;
            }
        }

        Assert.That(checkedContacts, Is.GreaterThan(150));
        Assert.That(clippedPieces, Is.GreaterThan(150), "pieces cut by the workspace's faces");
    }

    [Test]
    public void AStanceWantedOnlyWhenValidIsTheWholeEvaluationOrNone([Values("stairs", "thin-slabs", "curved")] string name, [Values("skeleton", "ant")] string character)
    {
        // The sampler's shortcut (hands tried first, given up once too few limbs are left) against the evaluation
        // that tries every limb: the same contacts in the same order and the same cone when valid, nothing otherwise.
        (Level level, _) = ForeignLevels.Get(name);
        ReducedCharacter body = CharacterPresets.Get(character);
        ContactEstimator estimator = Estimator(level, body);
        var bvh = new TriangleBvh(level.Triangles);
        var random = new Random(23);
        int valid = 0;
        int none = 0;
        int some = 0;
        for (int i = 0; i < 400; i++)
        {
            float x = -5f + (10f * (float)random.NextDouble());
            float z = -5f + (10f * (float)random.NextDouble());
            if (!bvh.Raycast(new Vector3(x, 20f, z), new Vector3(0f, -40f, 0f), 1f, out RayHit ground))
            {
                continue;
            }

            var pose = new RootPose(ground.Point + new Vector3(0f, 1.8f * (float)random.NextDouble(), 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, (float)random.NextDouble() * 6.3f));
            PoseEvaluation whole = estimator.EvaluateContacts(pose);
            PoseEvaluation? quick = estimator.ValidOrNull(pose);
            if (whole.IsValid)
            {
                Assert.That(quick, Is.Not.Null, $"pose {i}");
                Assert.That(quick!.Contacts, Is.EqualTo(whole.Contacts), $"pose {i}: contacts");
                Assert.That(quick.Cone, Is.EqualTo(whole.Cone), $"pose {i}: cone");
                valid++;
            }
            else
            {
                Assert.That(quick, Is.Null, $"pose {i}: {whole.Validity}");
                none += whole.Contacts.Count == 0 ? 1 : 0;
                some += whole.Contacts.Count > 0 ? 1 : 0;
            }
        }

        Assert.Multiple(() =>
        {
            Assert.That(valid, Is.GreaterThan(30), "valid");
            Assert.That(none, Is.GreaterThan(30), "touching nothing");
            Assert.That(some, Is.GreaterThan(0), "touching, too little");
        });
    }

    [Test]
    public void TooHighOrInsideTheFloorIsInvalid()
    {
        Level level = new LevelBuilder("t").AddFloor(-5f, -5f, 5f, 5f, 0f).Build();
        ContactEstimator estimator = Estimator(level, CharacterPresets.Skeleton());
        Assert.Multiple(() =>
        {
            Assert.That(estimator.Evaluate(new RootPose(new Vector3(0f, 2.5f, 0f), Quaternion.Identity)).Validity, Is.EqualTo(PoseValidity.TooFewContacts));
            Assert.That(estimator.Evaluate(new RootPose(new Vector3(0f, 0.3f, 0f), Quaternion.Identity)).Validity, Is.EqualTo(PoseValidity.TrunkCollides));
        });
    }

    [Test]
    public void CentroidalConeSumsNormalsAndTakesTheLeastFriction()
    {
        // Feet on a sticky floor, hands on an icy wall in front: axis leans away from the wall, μ is the ice's.
        var ice = new LevelMaterial("ice", 0.1f);
        Level level = new LevelBuilder("t")
            .AddFloor(-5f, -5f, 5f, 5f, 0f)
            .AddBox(new Vector3(-2f, 0f, 0.5f), new Vector3(2f, 3f, 1.5f), ice)
            .Build();
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        ContactEstimator estimator = Estimator(level, new ReducedCharacter("no-filter", skeleton.TrunkHalfExtents,
            [.. skeleton.Limbs.Select(l => l with { Filter = NormalFilter.None })], 2, 8f, 12f, 0.5f));
        PoseEvaluation evaluation = estimator.Evaluate(new RootPose(new Vector3(0f, 1.1f, 0.2f), Quaternion.Identity));

        Assert.That(evaluation.Validity, Is.EqualTo(PoseValidity.Valid));
        Vector3 sum = evaluation.Contacts.Aggregate(Vector3.Zero, (s, c) => s + c.Normal);
        Assert.Multiple(() =>
        {
            Assert.That(evaluation.Contacts, Has.Count.EqualTo(4));
            Assert.That(Vector3.Distance(evaluation.Cone.Axis, Vector3.Normalize(sum)), Is.LessThan(1e-5f));
            Assert.That(evaluation.Cone.Axis.Z, Is.LessThan(-0.1f), "the wall pushes back");
            Assert.That(evaluation.Cone.Mu, Is.EqualTo(0.1f));
        });
    }

    /// <summary>
    /// A limb with a home (where its contact pose holds it) touches the floor under its home, not under its
    /// workspace's centre; a home beyond the workspace's reach over the floor is not aimed at (the floor's piece
    /// inside the workspace is, at its centre).
    /// </summary>
    [Test]
    public void AContactIsEstimatedUnderTheLimbsHome()
    {
        Level level = new LevelBuilder("t").AddFloor(-5f, -5f, 5f, 5f, 0f).Build();
        var pose = new RootPose(new Vector3(1f, 1f, -2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.5f));
        Vector3 Touch(Vector3? home)
        {
            var limb = new Limb("foot", LimbKind.Foot, new Vector3(0f, -0.8f, 0f), new Vector3(0.3f), Quaternion.Identity, NormalFilter.None) { Home = home };
            var character = new ReducedCharacter("one-legged", new Vector3(0.2f), [limb], 1, 5f, 5f, 1f);
            Assert.That(Estimator(level, character).TryEstimate(0, pose, [], out Contact contact), Is.True);
            return contact.Position;
        }

        Assert.Multiple(() =>
        {
            Assert.That(Vector3.Distance(Touch(null), pose.ToWorld(new Vector3(0f, -1f, 0f))), Is.LessThan(1e-3f), "no home: under the workspace's centre");
            Assert.That(Vector3.Distance(Touch(new Vector3(0.2f, -1.05f, 0.15f)), pose.ToWorld(new Vector3(0.2f, -1f, 0.15f))), Is.LessThan(1e-3f), "under the home");
            Assert.That(Vector3.Distance(Touch(new Vector3(0.5f, -1f, 0f)), pose.ToWorld(new Vector3(0f, -1f, 0f))), Is.LessThan(1e-3f), "a home beyond the workspace: under its centre");
        });
    }

    /// <summary>
    /// A foot whose home lies past a ledge's brink (a 0.6 m platform, its face at x = 1, the home 10 cm beyond it over
    /// the drop) touches the platform <see cref="ContactEstimator.LedgeInset"/> in from the edge, not on the edge line
    /// (before: x = 1.000, half the foot over nothing); past a stair's nosing, with the floor below within the step
    /// height, it stays at the edge the home is nearest (the foot steps down there); a home over the platform is
    /// touched straight below, as before.
    /// </summary>
    [Test]
    public void AFootAimingPastALedgesBrinkStandsOnTheLedgeFiveCentimetresInNotOnItsEdge()
    {
        Vector3 Touch(Level level, Vector3 trunk, Vector3 home)
        {
            var limb = new Limb("foot", LimbKind.Foot, new Vector3(0f, -0.3f, 0f), new Vector3(0.3f, 0.1f, 0.3f), Quaternion.Identity, NormalFilter.None) { Home = home };
            var character = new ReducedCharacter("one-legged", new Vector3(0.15f, 0.1f, 0.15f), [limb], 1, 5f, 5f, 1f)
            {
                Walking = new WalkingLimits(1f, 30f, 0.2f),
            };
            Assert.That(Estimator(level, character).TryEstimate(0, new RootPose(trunk, Quaternion.Identity), [], out Contact contact), Is.True, $"a contact for the home {home} at {trunk}");
            return contact.Position;
        }

        Level ledge = new LevelBuilder("ledge").AddFloor(-3f, -3f, 1f, 3f, 0f).AddBox(new Vector3(1f, 0f, -2f), new Vector3(3f, 0.6f, 2f)).Build();
        Level step = new LevelBuilder("step").AddFloor(-3f, -3f, 1f, 3f, 0f).AddBox(new Vector3(1f, 0f, -2f), new Vector3(3f, 0.15f, 2f)).Build();
        var onLedge = new Vector3(1.15f, 0.9f, 0f);
        var onStep = new Vector3(1.15f, 0.45f, 0f);
        Vector3 overDrop = Touch(ledge, onLedge, new Vector3(-0.25f, -0.3f, 0f));
        Vector3 overTread = Touch(step, onStep, new Vector3(-0.25f, -0.3f, 0f));
        Vector3 over = Touch(ledge, onLedge, new Vector3(0.1f, -0.3f, 0.05f));
        Assert.Multiple(() =>
        {
            Assert.That(overDrop.Y, Is.EqualTo(0.6f).Within(1e-4f), "on the platform's top");
            Assert.That(overDrop.X, Is.EqualTo(1f + ContactEstimator.LedgeInset).Within(1e-3f), "moved in from the brink");
            Assert.That(overTread.X, Is.EqualTo(1f).Within(1e-3f), "a stair's nosing, the floor 15 cm below: at the edge");
            Assert.That(overTread.Y, Is.EqualTo(0.15f).Within(1e-4f), "on the first tread");
            Assert.That(Vector3.Distance(over, new Vector3(1.25f, 0.6f, 0.05f)), Is.LessThan(1e-3f), "a home over the platform: straight below it");
        });
    }

    /// <summary>
    /// A rig's derived limbs have their homes where its contact pose holds each contact point (the human rig whose
    /// pelvis and legs carry 90° rest rotations, as assimp and FBX converters write them): over a floor at the height
    /// of its feet's workspaces' centres, each foot's contact is estimated within 1 cm of straight above where the
    /// contact pose puts it.
    /// </summary>
    [Test]
    public void ADerivedFootTouchesTheFloorWhereItsContactPoseStands()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-home-{Guid.NewGuid():N}");
        try
        {
            (CharacterModel model, ReducedCharacter reduced) = ForeignCharacters.Named("human").Load(folder);
            var positions = new Vector3[model.Rig.Joints.Count];
            var rotations = new Quaternion[model.Rig.Joints.Count];
            var root = new RootPose(new Vector3(0.4f, 2f, -0.7f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 2f));
            model.Rig.Solve(root, model.ContactPose, positions, rotations);
            RigLimb[] feet = [.. model.Limbs.Where(l => l.Kind == LimbKind.Foot)];
            float floor = reduced.Limbs.Where(l => l.Kind == LimbKind.Foot).Max(l => root.ToWorld(l.WorkspaceCenter).Y);
            Level level = new LevelBuilder("t").AddFloor(-5f, -5f, 5f, 5f, floor).Build();
            ContactEstimator estimator = Estimator(level, reduced);
            Assert.Multiple(() =>
            {
                foreach (RigLimb foot in feet)
                {
                    int index = reduced.Limbs.ToList().FindIndex(l => l.Name == foot.Name);
                    Vector3 standing = foot.EffectorPosition(positions, rotations);
                    Assert.That(reduced.Limbs[index].Home, Is.Not.Null, foot.Name);
                    Assert.That(estimator.TryEstimate(index, root, [], out Contact contact), Is.True, foot.Name);
                    Assert.That(Vector3.Distance(contact.Position, standing with { Y = floor }), Is.LessThan(0.01f), $"{foot.Name} touches the floor where its contact pose stands");
                }
            });
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
    public void OpposingWallsAreForceClosure()
    {
        // A hand-only character squeezed between two walls: the normals cancel.
        var hand = new Vector3(0.3f, 0.3f, 0.3f);
        var character = new ReducedCharacter("spreader", new Vector3(0.2f, 0.2f, 0.2f),
        [
            new Limb("left", LimbKind.Hand, new Vector3(0.5f, 0f, 0f), hand, Quaternion.Identity, NormalFilter.None),
            new Limb("right", LimbKind.Hand, new Vector3(-0.5f, 0f, 0f), hand, Quaternion.Identity, NormalFilter.None),
        ], 2, 5f, 5f, 1f);
        Level level = new LevelBuilder("t")
            .AddBox(new Vector3(0.6f, -2f, -2f), new Vector3(1f, 2f, 2f))
            .AddBox(new Vector3(-1f, -2f, -2f), new Vector3(-0.6f, 2f, 2f))
            .Build();
        Assert.That(Estimator(level, character).Evaluate(new RootPose(Vector3.Zero, Quaternion.Identity)).Validity, Is.EqualTo(PoseValidity.ForceClosure));
    }

    [Test]
    public void WorkspaceFollowsTheTrunkRotation()
    {
        // Rotating the trunk must carry the workspace rigidly: its corners are the trunk-frame corners mapped by the pose.
        var limb = new Limb("l", LimbKind.Foot, new Vector3(0.3f, -0.5f, 0.2f), new Vector3(0.1f, 0.2f, 0.3f),
            Quaternion.CreateFromAxisAngle(Vector3.UnitX, 0.3f), NormalFilter.None);
        var pose = new RootPose(new Vector3(1f, 2f, 3f), Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(1f, 2f, 0.5f)), 1.1f));
        OrientedBox inTrunk = new(limb.WorkspaceCenter, limb.WorkspaceHalfExtents, limb.WorkspaceRotation);
        OrientedBox world = limb.WorkspaceAt(pose);
        Span<Vector3> a = stackalloc Vector3[8];
        Span<Vector3> b = stackalloc Vector3[8];
        inTrunk.GetCorners(a);
        world.GetCorners(b);
        for (int i = 0; i < 8; i++)
        {
            Assert.That(Vector3.Distance(pose.ToWorld(a[i]), b[i]), Is.LessThan(1e-5f), $"corner {i}");
        }
    }

    [Test]
    public void ClippedAreaMatchesTheOverlapOfAFloorAndABox()
    {
        // A 2 × 2 m floor triangle pair under a box tilted about Y: the box's footprint area is exact.
        var box = new OrientedBox(new Vector3(0.2f, 0f, 0.1f), new Vector3(0.3f, 0.5f, 0.2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 0.6f));
        var t1 = new Triangle(new Vector3(-1f, 0f, -1f), new Vector3(-1f, 0f, 1f), new Vector3(1f, 0f, 1f));
        var t2 = new Triangle(new Vector3(-1f, 0f, -1f), new Vector3(1f, 0f, 1f), new Vector3(1f, 0f, -1f));
        (float a1, Vector3 c1) = BoxClipper.ClipArea(box, t1);
        (float a2, Vector3 c2) = BoxClipper.ClipArea(box, t2);
        Vector3 centroid = ((c1 * a1) + (c2 * a2)) / (a1 + a2);
        Assert.Multiple(() =>
        {
            Assert.That(a1 + a2, Is.EqualTo(0.6f * 0.4f).Within(1e-5f));
            Assert.That(Vector3.Distance(centroid, new Vector3(0.2f, 0f, 0.1f)), Is.LessThan(1e-5f));
            Assert.That(BoxClipper.ClipArea(box, new Triangle(new Vector3(5f, 0f, 5f), new Vector3(6f, 0f, 5f), new Vector3(5f, 0f, 6f))).Area, Is.Zero);
        });
    }

    internal static ContactEstimator Estimator(Level level, ReducedCharacter character) =>
        new(level, new TriangleBvh(level.Triangles), SurfaceSet.Build(level), character);
}
