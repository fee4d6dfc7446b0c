using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Tests.Support;

/// <summary>Independent checks that a jump or a node obeys everything the planner promises.</summary>
internal static class PhysicsChecks
{
    public static void AssertJump(PlanningScene scene, RoadmapNode from, RoadmapNode to, BallisticArc arc, string context)
    {
        ReducedCharacter c = scene.Character;
        Assert.That(Vector3.Distance(arc.PositionAt(0f), from.Pose.Position), Is.LessThan(1e-4f), $"{context}: arc does not start at the takeoff node");
        Assert.That(Vector3.Distance(arc.PositionAt(arc.FlightTime), to.Pose.Position), Is.LessThan(5e-3f), $"{context}: arc misses the landing node");
        Assert.That(from.Cone.AngleTo(arc.TakeoffVelocity), Is.LessThanOrEqualTo(from.Cone.HalfAngle + 1e-4f), $"{context}: takeoff velocity outside the takeoff cone");
        Assert.That(to.Cone.AngleTo(-arc.LandingVelocity), Is.LessThanOrEqualTo(to.Cone.HalfAngle + 1e-4f), $"{context}: reversed landing velocity outside the landing cone");
        Assert.That(arc.TakeoffVelocity.Length(), Is.LessThanOrEqualTo(c.TakeoffSpeedMax * 1.0001f), $"{context}: takeoff speed");
        Assert.That(arc.LandingVelocity.Length(), Is.LessThanOrEqualTo(c.LandingSpeedMax * 1.0001f), $"{context}: landing speed");

        // The trunk never touches the level: dense samples, 1 cm of travel apart at most.
        float speed = MathF.Max(arc.TakeoffVelocity.Length(), arc.LandingVelocity.Length());
        int steps = Math.Max(8, (int)MathF.Ceiling(arc.FlightTime * speed / 0.01f));
        for (int k = 0; k <= steps; k++)
        {
            RootPose pose = arc.PoseAt(arc.FlightTime * k / steps);
            Assert.That(scene.Bvh.Overlaps(new OrientedBox(pose.Position, c.TrunkHalfExtents, pose.Rotation)), Is.False, $"{context}: trunk touches the level at t = {arc.FlightTime * k / steps:0.###} s");
        }
    }

    public static void AssertNode(PlanningScene scene, RoadmapNode node, string context)
    {
        ReducedCharacter c = scene.Character;
        Assert.That(scene.Bvh.Overlaps(new OrientedBox(node.Pose.Position, c.TrunkHalfExtents, node.Pose.Rotation)), Is.False, $"{context}: trunk in the level");
        Assert.That(node.Contacts, Has.Count.GreaterThanOrEqualTo(c.RequiredContacts), $"{context}: too few contacts");
        Vector3 sum = Vector3.Zero;
        foreach (Contact contact in node.Contacts)
        {
            sum += contact.Normal;
            Assert.That(c.Limbs[contact.Limb].WorkspaceAt(node.Pose).Contains(contact.Position), Is.True, $"{context}: contact outside its limb's workspace");
            Assert.That(c.Limbs[contact.Limb].Filter.Accepts(contact.Normal), Is.True, $"{context}: contact on a surface its limb may not touch");
        }

        Assert.That(Vector3.Distance(node.Cone.Axis, Vector3.Normalize(sum)), Is.LessThan(1e-4f), $"{context}: cone axis is not the normalised sum of the contact normals");
        Assert.That(node.Cone.Mu, Is.EqualTo(node.Contacts.Min(x => x.Mu)), $"{context}: cone μ is not the least contact μ");
    }
}
