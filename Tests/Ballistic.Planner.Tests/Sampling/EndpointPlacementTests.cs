using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Sampling;

/// <summary>Plans start and end where asked: on the bar, on the step, on open ground; never on the floor beside it.</summary>
public sealed class EndpointPlacementTests
{
    private static readonly Lazy<PlanningScene> Slabs = new(() => PlanningScene.Create(ForeignLevels.Get("thin-slabs").Level, CharacterPresets.Skeleton()));

    private static readonly Lazy<PlanningScene> Stairs = new(() => PlanningScene.Create(ForeignLevels.Get("stairs").Level, CharacterPresets.Skeleton()));

    [TestCase(-2.5f, 0.8f, 4f, TestName = "A goal on top of a 20 cm bar stands on the bar")]
    [TestCase(0.5f, 0.95f, 0f, TestName = "A goal on a 5 cm slab stands on the slab")]
    [TestCase(-6f, 0f, 0f, TestName = "A goal on open ground stands on it")]
    public void TheStanceStandsOnTheRequestedSurface(float x, float y, float z)
    {
        var point = new Vector3(x, y, z);
        EndpointPlacement placed = Slabs.Value.Sampler.Place(point, new EndpointTolerance());
        Assert.That(placed.Placed, Is.True, placed.Failure("goal", new EndpointTolerance()));
        AssertWithin(placed, point, 0.5f, 0.25f);
        foreach (Contact c in placed.Pose!.Contacts)
        {
            Assert.That(c.Position.Y, Is.EqualTo(y).Within(0.02f), "every contact on the requested surface, not the floor beside it");
            Assert.That(c.Normal.Y, Is.GreaterThan(0.99f), "on the top face");
        }
    }

    [TestCase(3.35f, 0.68f, 0f)]
    [TestCase(2.75f, 0.51f, 0.5f)]
    [TestCase(6.5f, 1.36f, 0f)]
    public void AGoalOnAStepEndsOnThatStep(float x, float y, float z)
    {
        var point = new Vector3(x, y, z);
        EndpointPlacement placed = Stairs.Value.Sampler.Place(point, new EndpointTolerance());
        Assert.That(placed.Placed, Is.True, placed.Failure("goal", new EndpointTolerance()));
        AssertWithin(placed, point, 0.5f, 0.25f);
        Assert.That(placed.Pose!.Contacts.Min(c => c.Position.Y), Is.GreaterThan(y - 0.25f), "no foot on a lower step beyond the tolerance");
    }

    [Test]
    public void ATighterToleranceIsHonoured()
    {
        var point = new Vector3(-6f, 0f, 0f);
        var tight = new EndpointTolerance(0.1f, 0.05f);
        EndpointPlacement placed = Slabs.Value.Sampler.Place(point, tight);
        Assert.That(placed.Placed, Is.True, placed.Failure("start", tight));
        AssertWithin(placed, point, 0.1f, 0.05f);
    }

    /// <summary>Two floors with a 2 m wide hole between them (x from −1 to 1), for the skeleton.</summary>
    private static PlanningScene BesideAHole() =>
        PlanningScene.Create(new LevelBuilder("hole").AddFloor(-6f, -6f, -1f, 6f, 0f).AddFloor(1f, -6f, 6f, 6f, 0f).Build(), CharacterPresets.Skeleton());

    [Test]
    public void APlacementFacingAWayFacesItStandsTallAndDoesNotSearchBeyondTheTolerance()
    {
        PlanningScene scene = BesideAHole();
        var tolerance = new EndpointTolerance(0.3f, 0.25f);
        foreach (float degrees in new[] { 0f, 60f, -135f })
        {
            float yaw = degrees * MathF.PI / 180f;
            EndpointPlacement placed = scene.Sampler.PlaceFacing(new Vector3(-3f, 0f, 1f), tolerance, yaw);
            Assert.That(placed.Placed, Is.True, placed.Failure("stance", tolerance));
            Vector3 forward = placed.Pose!.Pose.Forward;
            Assert.That(Vector3.Dot(Vector3.Normalize(new Vector3(forward.X, 0f, forward.Z)), new Vector3(MathF.Sin(yaw), 0f, MathF.Cos(yaw))), Is.GreaterThan(0.999f), $"faces {degrees}°");
            EndpointPlacement start = scene.Sampler.Place(new Vector3(-3f, 0f, 1f), tolerance);
            Assert.That(placed.Pose.Pose.Position.Y, Is.GreaterThan(start.Pose!.Pose.Position.Y), "taller than a start placed there");
        }

        EndpointPlacement overHole = scene.Sampler.PlaceFacing(new Vector3(0f, 0f, 0f), tolerance, 0f);
        Assert.That(overHole.Placed, Is.False);
        Assert.That(overHole.NearestValid, Is.Null, "no search beyond the tolerance");
        Assert.That(() => scene.Sampler.PlaceFacing(Vector3.Zero, tolerance, float.NaN), Throws.ArgumentException);
    }

    [Test]
    public void APlacementFacingAWayIsRememberedPerStanceCheckAndIsTheSameAsOneMadeAnew()
    {
        PlanningScene scene = BesideAHole();
        var tolerance = new EndpointTolerance(0.3f, 0.25f);
        var point = new Vector3(-3f, 0f, 1f);
        int asked = 0;
        bool Counting(PoseEvaluation pose)
        {
            asked++;
            return pose.Contacts.Count >= 2;
        }

        Func<PoseEvaluation, bool> check = Counting;
        EndpointPlacement first = scene.Sampler.PlaceFacing(point, tolerance, 0.5f, check);
        Assert.That(first.Placed, Is.True, first.Failure("stance", tolerance));
        int once = asked;
        Assert.That(once, Is.GreaterThan(0));

        EndpointPlacement again = scene.Sampler.PlaceFacing(point, tolerance, 0.5f, Counting);
        Assert.That(again, Is.SameAs(first), "remembered: the same check (an equal delegate) is not asked again");
        Assert.That(asked, Is.EqualTo(once));

        EndpointPlacement otherWay = scene.Sampler.PlaceFacing(point, tolerance, 0.6f, check);
        Assert.That(asked, Is.GreaterThan(once), "another facing is placed anew");
        Assert.That(otherWay.Pose!.Pose, Is.Not.EqualTo(first.Pose!.Pose));

        int before = asked;
        EndpointPlacement otherCheck = scene.Sampler.PlaceFacing(point, tolerance, 0.5f, pose => pose.Contacts.Count >= 2 && ++asked > 0);
        Assert.That(asked, Is.GreaterThan(before), "another stance check is asked: it may refuse what the first took");
        Assert.That(otherCheck.Pose!.Pose, Is.EqualTo(first.Pose.Pose));

        // What is remembered never changes an answer: a scene made anew places the very same stance.
        EndpointPlacement fresh = BesideAHole().Sampler.PlaceFacing(point, tolerance, 0.5f, check);
        Assert.That(fresh.Pose!.Pose, Is.EqualTo(first.Pose.Pose));
        Assert.That(fresh.Pose.Contacts, Is.EqualTo(first.Pose.Contacts));
        Assert.That(fresh.ContactCentre, Is.EqualTo(first.ContactCentre));
    }

    /// <summary>
    /// A request's start or goal, placed again by every request to the same point (agents sent to one spot), is
    /// remembered like a stance placed facing a way, per stance check, and is the stance a scene made anew places:
    /// over a hole, where the search goes beyond the tolerance, and where a stance stands within it. Before, each
    /// request placed them anew (on the rooftops, up to 30 ms a request for a point with no stance within the tolerance).
    /// </summary>
    [Test]
    public void ARequestsEndIsRememberedPerStanceCheckAndIsTheSameAsOneMadeAnew()
    {
        PlanningScene scene = BesideAHole();
        var tolerance = new EndpointTolerance(0.3f, 0.25f);
        int asked = 0;
        bool Counting(PoseEvaluation pose)
        {
            asked++;
            return pose.Contacts.Count >= 2;
        }

        foreach (Vector3 point in new[] { new Vector3(-3f, 0f, 1f), Vector3.Zero })
        {
            asked = 0;
            EndpointPlacement first = scene.Sampler.Place(point, tolerance, Counting);
            int once = asked;
            EndpointPlacement again = scene.Sampler.Place(point, tolerance, Counting);
            Assert.That(again, Is.SameAs(first), $"{point}: remembered");
            Assert.That(asked, Is.EqualTo(once), $"{point}: the check is not asked again");

            EndpointPlacement otherCheck = scene.Sampler.Place(point, tolerance, pose => pose.Contacts.Count >= 2 && ++asked > 0);
            Assert.That(otherCheck, Is.Not.SameAs(first), $"{point}: placed anew for another stance check");
            Assert.That(otherCheck.Pose?.Pose, Is.EqualTo(first.Pose?.Pose));

            EndpointPlacement fresh = BesideAHole().Sampler.Place(point, tolerance, Counting);
            Assert.That((fresh.Placed, fresh.Pose?.Pose, fresh.NearestValid, fresh.ContactCentre), Is.EqualTo((first.Placed, first.Pose?.Pose, first.NearestValid, first.ContactCentre)), $"{point}: as placed anew");
            if (point == Vector3.Zero)
            {
                Assert.That(first.Placed, Is.False, "over the hole: nothing within the tolerance");
                Assert.That(first.NearestValid, Is.Not.Null, "the nearest stance beyond it is found");
            }
            else
            {
                Assert.That(first.Placed, Is.True, first.Failure("start", tolerance));
                Assert.That(once, Is.GreaterThan(0), "the check is asked once");
            }

            Assert.That(scene.Sampler.PlaceFacing(point, tolerance, 0f, Counting), Is.Not.SameAs(first), $"{point}: a stance placed facing a way is another placement");
        }
    }

    [Test]
    public void APointWithNoStanceWithinToleranceSaysHowFarTheNearestIs()
    {
        // 0.9 m above the floor and away from every slab: the floor is 0.9 m down, beyond 0.25 m.
        var point = new Vector3(-6f, 0.9f, -4f);
        EndpointPlacement placed = Slabs.Value.Sampler.Place(point, new EndpointTolerance());
        Assert.That(placed.Placed, Is.False);
        Assert.That(placed.NearestValid, Is.Null.Or.GreaterThan(0.25f));

        // Beside a 2 m wide hole with 0.3 m tolerance: the nearest stance is found beyond it, and its distance told.
        PlanningScene scene = BesideAHole();
        var tolerance = new EndpointTolerance(0.3f, 0.25f);
        EndpointPlacement overHole = scene.Sampler.Place(new Vector3(0f, 0f, 0f), tolerance);
        Assert.That(overHole.Placed, Is.False);
        Assert.That(overHole.NearestValid, Is.Not.Null);
        Assert.That(overHole.NearestValid!.Value, Is.InRange(0.3f, 1.6f));
        Assert.That(overHole.Failure("goal", tolerance), Does.Contain("nearest valid pose found stands").And.Contain("0.3 m across"));
    }

    [Test]
    public void PlacementIsDeterministicAndTheBakedNodesAreTheQuerysNodes()
    {
        PlanningScene scene = Slabs.Value;
        var from = new Vector3(-6f, 0f, 0f);
        var to = new Vector3(-3f, 0.62f, 0f);
        EndpointPlacement first = scene.Sampler.Place(from, new EndpointTolerance());
        EndpointPlacement again = scene.Sampler.Place(from, new EndpointTolerance());
        Assert.That(again.Pose!.Pose, Is.EqualTo(first.Pose!.Pose));
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 4, MaxNodes = 400, Start = from, Goal = to, StopWhenConnected = true, Threads = 2 });
        Assert.That(bake.Status, Is.EqualTo(PlannerStatus.Exact), bake.Reason);
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(from, to, new QuerySettings { FaceJumps = false });
        PlanResult faced = new PathQuery(scene, bake.Roadmap).Plan(from, to);
        Assert.Multiple(() =>
        {
            Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact), "the bake connected start and goal, so the query does too");
            Assert.That(plan.Start!.Id, Is.EqualTo(bake.StartNode));
            Assert.That(plan.Goal!.Id, Is.EqualTo(bake.GoalNode));
            Assert.That(plan.StartPlacement!.Across, Is.LessThanOrEqualTo(0.5f));
            Assert.That(plan.GoalPlacement!.UpDown, Is.LessThanOrEqualTo(0.25f));

            // Facing the first and last jumps may place the start and goal again: at the same points, within the same
            // tolerance, said so.
            Assert.That(faced.Status, Is.EqualTo(PlannerStatus.Exact), faced.Reason);
            Assert.That(faced.Start, Is.SameAs(faced.Moves[0].From));
            Assert.That(faced.StartPlacement!.Pose!.Pose, Is.EqualTo(faced.Start!.Pose), "the placement reported is the start's");
            Assert.That(faced.StartPlacement!.Across, Is.LessThanOrEqualTo(0.5f));
            Assert.That(faced.Goal, Is.SameAs(faced.Moves[^1].To));
            Assert.That(faced.GoalPlacement!.Across, Is.LessThanOrEqualTo(0.5f));
            Assert.That(faced.GoalPlacement!.UpDown, Is.LessThanOrEqualTo(0.25f));
            Assert.That(faced.GoalPlacement!.Pose!.Pose, Is.EqualTo(faced.Goal!.Pose), "the placement reported is the goal's");
        });
    }

    [Test]
    public void TheSameStartAndGoalIsAPlanWithoutJumps()
    {
        PlanningScene scene = Slabs.Value;
        BakeResult bake = new RoadmapBaker(scene).Bake(new BakeSettings { Seed = 4, MaxNodes = 20, Threads = 2 });
        PlanResult plan = new PathQuery(scene, bake.Roadmap).Plan(new Vector3(-6f, 0f, 0f), new Vector3(-6f, 0f, 0f));
        Assert.That(plan.Status, Is.EqualTo(PlannerStatus.Exact));
        Assert.That(plan.Jumps, Is.Empty);
        Assert.That(plan.Start, Is.SameAs(plan.Goal));
    }

    /// <summary>
    /// A jump's stance is turned to face the jump at no more than its own height (a stance under a ceiling stays as
    /// low), but a roadmap crouch lower than the sampler's whole lift range has no upright lift that low: turned, such
    /// a stance that stands nowhere within the tolerance at its own height is tried at the range's lowest lift. On the
    /// desert's roadmap, crouches turned every eighth of a turn, where they stand and shifted along the way as the
    /// facer shifts them, are placed wherever a stance at the range's lowest lift is; each faces the way asked, stands
    /// within the tolerance, and no taller than that lift (to within 15 cm: the ground's tilt and the contacts' centre
    /// below the trunk's surface point).
    /// </summary>
    [Test]
    public void ACrouchTurnedToFaceAJumpIsPlacedWhereverAStanceAtTheLowestUprightLiftIs()
    {
        PlanningScene scene = SharedLevels.Scene("desert", "skeleton");
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 400, Threads = 2 }).Roadmap;
        float lowest = scene.Sampler.Lift.Min;
        RoadmapNode[] crouches = [.. roadmap.Nodes.Where(n => JumpFacer.Height(scene.Sampler, n) < lowest - 0.01f).Take(16)];
        Assume.That(crouches, Has.Length.GreaterThanOrEqualTo(12), "the desert's roadmap has crouches below the lift range");
        var tolerance = new EndpointTolerance(0.2f, 0.3f);
        int tried = 0;
        int standsLow = 0;
        int refused = 0;
        float tallest = 0f;
        foreach (RoadmapNode crouch in crouches)
        {
            for (int eighth = 0; eighth < 8; eighth++)
            {
                float facing = eighth * MathF.PI / 4f;
                var along = new Vector3(MathF.Sin(facing), 0f, MathF.Cos(facing));
                foreach (float shift in new[] { 0f, JumpFacer.HopShift, -JumpFacer.HopShift })
                {
                    // As the facer places it: where the crouch stands, measured so only when it leans a hand on something.
                    Vector3 stands = scene.Sampler.StandingCentre(crouch.Contacts, crouch.Pose.Position);
                    bool leans = stands != crouch.ContactCentre;
                    Vector3 point = stands + (shift * along);
                    EndpointPlacement turned = scene.Sampler.PlaceFacingWithin(point, tolerance, facing, JumpFacer.Yaws, null, JumpFacer.Height(scene.Sampler, crouch), leans);
                    EndpointPlacement low = scene.Sampler.PlaceFacingWithin(point, tolerance, facing, JumpFacer.Yaws, null, lowest, leans);
                    tried++;
                    standsLow += low.Placed ? 1 : 0;
                    if (!turned.Placed)
                    {
                        refused += low.Placed ? 1 : 0;
                        continue;
                    }

                    AssertWithin(turned, point, tolerance.Across, tolerance.UpDown, leans ? scene.Sampler : null);
                    Vector3 now = turned.Pose!.Pose.Forward;
                    float off = MathF.Abs(MathF.IEEERemainder(MathF.Atan2(now.X, now.Z) - facing, 2f * MathF.PI)) * 180f / MathF.PI;
                    Assert.That(off, Is.LessThanOrEqualTo(15f), "faces the way asked, within the yaws tried (10°) and what the ground's tilt adds");
                    tallest = MathF.Max(tallest, turned.Pose.Pose.Position.Y - (leans ? scene.Sampler.StandingCentre(turned.Pose.Contacts, turned.Pose.Pose.Position) : TrunkSampler.ContactCentre(turned.Pose)).Y);
                }
            }
        }

        TestContext.Out.WriteLine($"{tried} turned placements of {crouches.Length} crouches; {standsLow} stand at the lowest lift ({lowest:0.000} m); {refused} of those refused to the crouch; tallest {tallest:0.000} m");
        Assert.That(standsLow, Is.GreaterThan(tried / 2), "the lowest lift stands on most of these spots");
        Assert.That(refused, Is.Zero, "a crouch turned is placed wherever a stance at the range's lowest lift is");
        Assert.That(tallest, Is.LessThanOrEqualTo(lowest + 0.15f), "no taller than the range's lowest lift, but for the ground's tilt and where the contacts stand below the trunk's surface point");
    }

    /// <summary>
    /// A stance leaning a hand on a block's top beside its feet (the desert's roadmap has them: feet in the sand, a hand
    /// on a sandstone block 1.1 m up) has its contacts' centre a third of the way up the block. Turned to face a jump,
    /// it is placed where it stands (<see cref="TrunkSampler.StandingCentre"/>: the centre of the contacts holding it up), as
    /// the facer asks: measured by all its contacts, no stance on its feet alone stood within the tolerance of it, and
    /// every spot, yaw and lift was tried in vain. Each placed stance stands within the tolerance of where the old one
    /// stood, and faces the way asked; a frog, which stands on its hands as on its feet, stands at its contacts' centre.
    /// </summary>
    [Test]
    public void AStanceLeaningAHandOnABlockIsTurnedWhereItStands()
    {
        PlanningScene scene = SharedLevels.Scene("desert", "skeleton");
        Roadmap roadmap = new RoadmapBaker(scene).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 400, Threads = 2 }).Roadmap;
        // Where the test expects a stance to stand: the centre of its contacts but hands higher than a step above its
        // feet.
        Vector3 StandsAt(RoadmapNode n)
        {
            Contact[] feet = [.. n.Contacts.Where(c => scene.Character.Limbs[c.Limb].Kind == LimbKind.Foot)];
            float lean = (feet.Sum(c => c.Position.Y) / feet.Length) + scene.Character.StepReach;
            Contact[] standing = [.. n.Contacts.Where(c => scene.Character.Limbs[c.Limb].Kind == LimbKind.Foot || c.Position.Y <= lean)];
            return standing.Aggregate(Vector3.Zero, (sum, c) => sum + c.Position) / standing.Length;
        }

        RoadmapNode[] leaning = [.. roadmap.Nodes.Where(n => n.Contacts.Any(c => scene.Character.Limbs[c.Limb].Kind == LimbKind.Foot) && n.ContactCentre.Y - StandsAt(n).Y > 0.3f).Take(8)];
        Assume.That(leaning, Has.Length.GreaterThanOrEqualTo(3), "the desert's roadmap has stances leaning a hand on a block");
        var tolerance = new EndpointTolerance(0.2f, 0.3f);
        int tried = 0;
        int placed = 0;
        int byAll = 0;
        foreach (RoadmapNode stance in leaning)
        {
            Assert.That(stance.Contacts.Any(c => scene.Character.Limbs[c.Limb].Kind == LimbKind.Hand), "what raises the centre is a hand");
            Vector3 stands = scene.Sampler.StandingCentre(stance.Contacts, stance.Pose.Position);
            Assert.That(Vector3.Distance(stands, StandsAt(stance)), Is.LessThan(1e-5f), "it stands where its feet are");
            for (int quarter = 0; quarter < 4; quarter++)
            {
                float facing = quarter * MathF.PI / 2f;
                tried++;
                EndpointPlacement all = scene.Sampler.PlaceFacingWithin(stance.ContactCentre, tolerance, facing, JumpFacer.Yaws, null, stance.Pose.Position.Y - stance.ContactCentre.Y);
                byAll += all.Placed ? 1 : 0;
                EndpointPlacement turned = scene.Sampler.PlaceFacingWithin(stands, tolerance, facing, JumpFacer.Yaws, null, JumpFacer.Height(scene.Sampler, stance), standing: true);
                if (!turned.Placed)
                {
                    continue;
                }

                placed++;
                AssertWithin(turned, stands, tolerance.Across, tolerance.UpDown, scene.Sampler);
                Vector3 now = turned.Pose!.Pose.Forward;
                float off = MathF.Abs(MathF.IEEERemainder(MathF.Atan2(now.X, now.Z) - facing, 2f * MathF.PI)) * 180f / MathF.PI;
                Assert.That(off, Is.LessThanOrEqualTo(15f), "faces the way asked, within the yaws tried (10°) and what the ground's tilt adds");
            }
        }

        TestContext.Out.WriteLine($"{leaning.Length} stances leaning a hand, {tried} turns: {placed} placed where the stance stands, {byAll} measured by all the contacts");
        Assert.That(placed, Is.GreaterThan(tried / 2), "most turns stand where the stance stood");
        Assert.That(placed, Is.GreaterThan(byAll), "measured by all its contacts, the hand's block keeps most turns from standing");

        // A frog stands on its hands as much as on its feet: its stances stand at their contacts' centre.
        PlanningScene pond = SharedLevels.Scene("pond", "frog");
        Roadmap frogs = new RoadmapBaker(pond).Bake(new BakeSettings { Locomotion = Locomotion.Jump, Seed = 7, MaxNodes = 100, Threads = 2 }).Roadmap;
        RoadmapNode[] onHands = [.. frogs.Nodes.Where(n => n.Contacts.Any(c => pond.Character.Limbs[c.Limb].Kind == LimbKind.Hand) && n.Contacts.Any(c => pond.Character.Limbs[c.Limb].Kind == LimbKind.Foot))];
        Assume.That(onHands, Is.Not.Empty, "the frog stands on hands and feet");
        Assert.That(onHands.Select(n => pond.Sampler.StandingCentre(n.Contacts, n.Pose.Position)), Is.EqualTo(onHands.Select(n => n.ContactCentre)), "a frog stands where all its contacts are");
    }

    /// <summary>Asserts <paramref name="placed"/> stands within the tolerance of <paramref name="point"/>: its contacts' centre, or where it stands when placed so (<paramref name="standing"/>, the sampler that placed it).</summary>
    private static void AssertWithin(EndpointPlacement placed, Vector3 point, float across, float upDown, TrunkSampler? standing = null)
    {
        Vector3 centre = standing is null ? TrunkSampler.ContactCentre(placed.Pose!) : standing.StandingCentre(placed.Pose!.Contacts, placed.Pose.Pose.Position);
        Assert.Multiple(() =>
        {
            Assert.That(new Vector2(centre.X - point.X, centre.Z - point.Z).Length(), Is.LessThanOrEqualTo(across));
            Assert.That(MathF.Abs(centre.Y - point.Y), Is.LessThanOrEqualTo(upDown));
            Assert.That(placed.Across, Is.EqualTo(new Vector2(centre.X - point.X, centre.Z - point.Z).Length()).Within(1e-4f));
            Assert.That(placed.UpDown, Is.EqualTo(MathF.Abs(centre.Y - point.Y)).Within(1e-4f));
        });
    }
}
