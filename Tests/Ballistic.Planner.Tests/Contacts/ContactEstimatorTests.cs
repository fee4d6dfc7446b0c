using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Surfaces;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Contacts;

public sealed class ContactEstimatorTests
{
    [Test]
    public void SkeletonStandingOnAFloorTouchesWithBothFeetAtTheWorkspaceFootprint()
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
            // On the floor, inside the workspace, under its centre, with the floor's normal and the default μ.
            OrientedBox workspace = skeleton.Limbs[c.Limb].WorkspaceAt(pose);
            Vector3 under = workspace.Center with { Y = 0f };
            Assert.That(c.Position.Y, Is.EqualTo(0f).Within(1e-5f));
            Assert.That(Vector3.Distance(c.Position, under), Is.LessThan(1e-3f));
            Assert.That(Vector3.Distance(c.Normal, Vector3.UnitY), Is.LessThan(1e-5f));
            Assert.That(c.Mu, Is.EqualTo(0.5f));
        }

        Assert.That(Vector3.Distance(evaluation.Cone.Axis, Vector3.UnitY), Is.LessThan(1e-5f));
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
