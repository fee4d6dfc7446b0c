using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Runtime;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Query;

/// <summary>
/// One request's plan job run in steps (<see cref="PlanJob.Advance"/>, <see cref="PathQuery"/>'s steps, sliced A*)
/// ends as the job run whole: the same search, moves and animation, however it is sliced.
/// </summary>
public sealed class PlanInStepsTests
{
    /// <summary>A slice that is spent after any step: the job advances one step per call.</summary>
    private static readonly TerminationCondition OneStep = TerminationCondition.Timeout(TimeSpan.FromTicks(1));

    [Test]
    public void ASearchSlicedEveryFourExpansionsExpandsAndFindsWhatTheWholeSearchDoes()
    {
        CharacterKind kind = RuntimeWorlds.DesertSkeleton;
        var settings = new QuerySettings { Locomotion = Locomotion.Jump, FaceJumps = false }; // one A* search, nothing else to pause at
        int longest = 0;
        Assert.Multiple(() =>
        {
            foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(kind.Roadmap, 6, seed: 9, minDistance: 8f))
            {
                PlanResult whole = new PathQuery(kind.Scene, kind.Roadmap).Plan(from, to, settings);
                var sliced = new PathQuery(kind.Scene, kind.Roadmap) { SliceExpansions = 4 };
                int pauses = 0;
                PlanResult? last = null;
                foreach (PlanResult? step in sliced.PlanSteps(from, to, settings, rejected: null, termination: null))
                {
                    if (step is null)
                    {
                        pauses++;
                    }
                    else
                    {
                        last = step;
                    }
                }

                string pair = $"{from.Id} → {to.Id}";
                Assert.That(last, Is.Not.Null, pair);
                Assert.That(last!.Status, Is.EqualTo(whole.Status), pair);
                Assert.That(last.Reason, Is.EqualTo(whole.Reason), pair);
                Assert.That(last.Expansions, Is.EqualTo(whole.Expansions), $"{pair}: the same nodes expanded");
                Assert.That(last.Moves.Select(m => (m.From.Id, m.To.Id)), Is.EqualTo(whole.Moves.Select(m => (m.From.Id, m.To.Id))), pair);
                Assert.That(pauses, Is.EqualTo((whole.Expansions - 1) / 4), $"{pair}: a pause every four expansions before the goal's");
                longest = Math.Max(longest, whole.Expansions);
            }
        });

        Assert.That(longest, Is.GreaterThan(12), "some search expands enough nodes to be sliced several times");
    }

    [Test]
    public void AWalkingPlanAdvancedOneStepPerCallEndsWithTheWholeJobsMovesAndAnimation()
    {
        CharacterKind kind = RuntimeWorlds.DesertSkeleton;
        (RoadmapNode a, RoadmapNode b) = RuntimeWorlds.ConnectedPairs(kind.Roadmap, 1, seed: 4, minDistance: 6f)[0];
        Vector3 from = RuntimeWorlds.Point(a);
        Vector3 to = RuntimeWorlds.Point(b);
        var settings = new QuerySettings { Locomotion = Locomotion.WalkAndJump, CanStand = kind.Animator.CanStand, CanPush = kind.Animator.CanPush };

        PlanJob Job()
        {
            var query = new PathQuery(kind.Scene, kind.Roadmap);
            return new PlanJob((r, stop) => query.PlanSteps(from, to, r.Adjust(settings), r.Excluded, stop), kind.Animator, new JumpRepair(kind.Roadmap.Nodes.Count + 2), AnimatedPlanner.DefaultRounds, 30f);
        }

        using PlanJob whole = Job();
        (PlanResult result, JumpAnimation? animation, int rounds) = whole.Run();
        Assume.That(result.Status, Is.EqualTo(PlannerStatus.Exact), result.Reason);

        using PlanJob stepped = Job();
        int calls = 0;
        while (!stepped.Advance(OneStep))
        {
            calls++;
            Assert.That(stepped.Outcome, Is.Null, "no outcome before the job ends");
        }

        (PlanResult sliced, JumpAnimation? slicedAnimation, int slicedRounds) = stepped.Outcome!.Value;
        Assert.Multiple(() =>
        {
            Assert.That(result.Moves.OfType<Walk>(), Is.Not.Empty, "the plan walks");
            Assert.That(calls, Is.GreaterThanOrEqualTo(result.Moves.Count + 2), "paused at least after the placements and after each move animated");
            Assert.That(stepped.Steps, Is.EqualTo(calls), "one step per call (the last call finds the job ended)");
            Assert.That(sliced.Status, Is.EqualTo(result.Status));
            Assert.That(sliced.Reason, Is.EqualTo(result.Reason));
            Assert.That(slicedRounds, Is.EqualTo(rounds));
            Assert.That(sliced.Moves.Select(m => (m.GetType(), m.From.Id, m.To.Id, m.Duration)), Is.EqualTo(result.Moves.Select(m => (m.GetType(), m.From.Id, m.To.Id, m.Duration))));
            Assert.That(slicedAnimation!.Frames.Select(f => (f.Time, f.Root.Position, f.Root.Rotation)), Is.EqualTo(animation!.Frames.Select(f => (f.Time, f.Root.Position, f.Root.Rotation))), "the same root motion, frame by frame");
            Assert.That(slicedAnimation.Frames.SelectMany(f => f.Angles), Is.EqualTo(animation.Frames.SelectMany(f => f.Angles)), "the same joint angles");
            Assert.That(slicedAnimation.ContactPhases, Is.EqualTo(animation.ContactPhases));
            Assert.That(stepped.Advance(OneStep), Is.True, "an ended job stays ended");
        });
    }
}
