using System.Numerics;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Tests.Roadmaps;

/// <summary>A stance's contact centre: where a game reads the character as standing.</summary>
public sealed class RoadmapNodeTests
{
    [Test]
    public void TheContactCentreIsTheMeanOfTheContactsOrTheTrunkWithoutAny()
    {
        var pose = new RootPose(new Vector3(1f, 0.9f, -2f), Quaternion.Identity);
        var cone = new FrictionCone(Vector3.UnitY, 0.8f);
        Contact[] feet =
        [
            new(0, new Vector3(0.8f, 0f, -2.1f), Vector3.UnitY, 0.8f, 0),
            new(1, new Vector3(1.2f, 0.2f, -1.9f), Vector3.UnitY, 0.8f, 0),
            new(2, new Vector3(1.3f, 0.1f, -2.3f), Vector3.UnitY, 0.8f, 0),
        ];
        Assert.Multiple(() =>
        {
            Vector3 centre = new RoadmapNode(0, pose, cone, feet).ContactCentre;
            Assert.That(Vector3.Distance(centre, new Vector3(1.1f, 0.1f, -2.1f)), Is.LessThan(1e-6f), $"{centre}");
            Assert.That(new RoadmapNode(1, pose, cone, []).ContactCentre, Is.EqualTo(pose.Position), "no contacts: the trunk");
        });
    }
}
