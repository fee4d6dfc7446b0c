using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// Ground a request no longer walks over (<see cref="QuerySettings.NoWalkSpots"/>): no walk of the plan passes within
/// the body's half-width of such a spot, seen from above, whether the roadmap holds the walk or the path's
/// post-processing would make it; the request walks everywhere else.
/// </summary>
public sealed class WalkBarrierTests
{
    /// <summary>Where the spider's rig files are written (removed when the fixture ends).</summary>
    private static readonly string RigFolder = RigFolders.For("walk-barrier");

    [OneTimeTearDown]
    public void RemoveTheRigFiles() => RigFolders.Remove(RigFolder);

    /// <summary>An 8 m × 8 m floor, its top at y = 0, open everywhere: a walk from x = −3 to x = 3 may go round a spot.</summary>
    private static readonly Lazy<(PlanningScene Scene, Roadmap Roadmap)> Floor = new(() =>
    {
        Level level = new LevelBuilder("floor").AddBox(new Vector3(-4f, -1f, -4f), new Vector3(4f, 0f, 4f)).Build();
        var scene = PlanningScene.Create(level, CharacterPresets.Skeleton());
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 3, MaxNodes = 150, Threads = 2 }).Roadmap;
        return (scene, roadmap);
    });

    private static readonly Vector3 From = new(-3f, 0f, 0f);
    private static readonly Vector3 To = new(3f, 0f, 0f);

    /// <summary>The horizontal distance from <paramref name="spot"/> to the segment from <paramref name="a"/> to <paramref name="b"/>, worked out here apart from the barrier's own test.</summary>
    private static float Distance(Vector3 spot, Vector3 a, Vector3 b)
    {
        float best = float.PositiveInfinity;
        for (int k = 0; k <= 200; k++)
        {
            Vector3 p = Vector3.Lerp(a, b, k / 200f);
            best = MathF.Min(best, new Vector2(p.X - spot.X, p.Z - spot.Z).Length());
        }

        return best;
    }

    private static float Nearest(IEnumerable<Walk> walks, Vector3 spot) =>
        walks.SelectMany(w => w.Path.Zip(w.Path.Skip(1), (a, b) => Distance(spot, a, b)).Append(Distance(spot, w.Path[0], w.Path[0]))).DefaultIfEmpty(float.PositiveInfinity).Min();

    [Test]
    public void TheBarriersRadiusIsTheBodysHalfWidthSeenFromAbove()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        ReducedCharacter spider = ForeignCharacters.Named("spider").Load(RigFolder).Reduced;
        float narrow = WalkBarrier.RadiusOf(skeleton);
        float wide = WalkBarrier.RadiusOf(spider);
        float widest = spider.Limbs.Where(l => l.Kind == LimbKind.Foot).Max(l => new Vector2((l.Home ?? l.WorkspaceCenter).X, (l.Home ?? l.WorkspaceCenter).Z).Length());
        float skeletonFeet = skeleton.Limbs.Where(l => l.Kind == LimbKind.Foot).Max(l => new Vector2((l.Home ?? l.WorkspaceCenter).X, (l.Home ?? l.WorkspaceCenter).Z).Length());
        Assert.Multiple(() =>
        {
            Assert.That(narrow, Is.EqualTo(MathF.Max(JumpTightener.SpotRadius, skeletonFeet)).Within(1e-5f), "a person: its feet's half-width, at least a spot's radius");
            Assert.That(narrow, Is.LessThan(0.3f), "not its hands' reach");
            Assert.That(wide, Is.EqualTo(widest).Within(1e-5f), "a spider: as far out as its contact pose holds a foot");
            Assert.That(wide, Is.GreaterThan(0.5f), "its legs span 1.3 m");
        });
    }

    [Test]
    public void ASegmentIsBarredWithinTheRadiusAndNotBeyondIt()
    {
        ReducedCharacter skeleton = CharacterPresets.Skeleton();
        var spot = new Vector3(1f, 0.3f, 2f);
        WalkBarrier barrier = WalkBarrier.Of([spot], skeleton)!;
        float r = barrier.Radius;
        Assert.Multiple(() =>
        {
            Assert.That(WalkBarrier.Of(null, skeleton), Is.Null);
            Assert.That(WalkBarrier.Of([], skeleton), Is.Null);
            Assert.That(barrier.Bars(new Vector3(-2f, 0f, 2f + r - 0.01f), new Vector3(4f, 5f, 2f + r - 0.01f)), Is.True, "passing just inside, at any height");
            Assert.That(barrier.Bars(new Vector3(-2f, 0f, 2f + r + 0.01f), new Vector3(4f, 0f, 2f + r + 0.01f)), Is.False, "passing just outside");
            Assert.That(barrier.Bars(new Vector3(1f + r + 0.01f, 0f, 2f), new Vector3(5f, 0f, 2f)), Is.False, "ending just short of it");
            Assert.That(barrier.Bars(new Vector3(1f + r - 0.01f, 0f, 2f), new Vector3(5f, 0f, 2f)), Is.True, "starting just within it");
        });
    }

    [Test]
    public void AQueryWalksNowhereNearItsNoWalkSpotsAndStillWalks()
    {
        (PlanningScene scene, Roadmap roadmap) = Floor.Value;
        var query = new PathQuery(scene, roadmap);
        PlanResult free = query.Plan(From, To, new QuerySettings());
        Assume.That(free.Status, Is.EqualTo(PlannerStatus.Exact), free.Reason);
        Assume.That(free.Walks, Is.Not.Empty);

        // A spot on the middle of the walk taken without it.
        Walk longest = free.Walks.MaxBy(w => w.Length)!;
        Vector3 spot = longest.PointAt(0.5f * longest.Length);
        float radius = WalkBarrier.RadiusOf(scene.Character);
        Assume.That(Nearest(free.Walks, spot), Is.LessThan(radius));
        PlanResult barred = query.Plan(From, To, new QuerySettings { NoWalkSpots = [spot] });
        Assert.Multiple(() =>
        {
            Assert.That(barred.Status, Is.EqualTo(PlannerStatus.Exact), barred.Reason);
            Assert.That(Nearest(barred.Walks, spot), Is.GreaterThan(radius - 1e-3f), "no walk passes within the body's half-width");
            Assert.That(barred.Walks.Sum(w => w.Length), Is.GreaterThan(2f), "it walks elsewhere");
        });

        AuditReport audit = PlanAudit.Check("walk round a no-walk spot", scene, From, To, barred, null);
        Assert.That(audit.Violations, Is.Empty, audit.ToString());
    }
}
