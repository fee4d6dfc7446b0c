using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// <see cref="WorldSettings.PrepareSearches"/>: a kind's searches prepared on a background thread from the moment it
/// has a roadmap, stopped when it goes, and changing no path, trajectory or event.
/// </summary>
public sealed class SearchPreparationTests
{
    [Test]
    public void AKindIsPreparedInTheBackgroundAndItsAgentsMoveAsInAWorldThatDoesNotPrepare()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        Roadmap roadmap = desert.Roadmap;
        int pairs = roadmap.Edges.Select(e => (e.From, e.To)).Concat(roadmap.Walks.Select(w => (w.From, w.To))).Distinct().Count();
        string[] Events(bool prepare, out int prepared, out int kept)
        {
            // A scene of its own, so that neither world finds what the other (or another test) worked out.
            var scene = PlanningScene.Create(desert.Scene.Level, desert.Scene.Character);
            var kind = new CharacterKind(scene, roadmap, desert.Animator, new SimpleMoveAnimator(desert.Animator));
            var settings = new WorldSettings { AnimationThreads = 1, Locomotion = Locomotion.WalkAndJump, PrepareSearches = prepare };
            using var world = new JumpWorld(scene.Level, settings);
            KindHandle handle = world.AddKind(kind).Kind;
            Task<int>? preparation = world.GetKindPreparation(handle);
            Assert.That(preparation is null, Is.EqualTo(!prepare));
            prepared = 0;
            if (preparation is not null)
            {
                Assert.That(preparation.Wait(TimeSpan.FromMinutes(3)), Is.True, "the preparation ends");
                prepared = preparation.Result;
            }

            kept = scene.KeptCount;
            foreach ((RoadmapNode from, RoadmapNode to) in RuntimeWorlds.ConnectedPairs(roadmap, 4, seed: 31))
            {
                Assert.That(world.SetTarget(world.AddAgent(handle, RuntimeWorlds.Point(from)).Agent, RuntimeWorlds.Point(to)).Ok, Is.True);
            }

            return [.. RuntimeWorlds.Run(world, 3_600, (_, seen) => seen.Count(e => e.Kind is JumpEventKind.TargetReached or JumpEventKind.PathFailed) == 4).Select(e => e.ToString())];
        }

        string[] plain = Events(prepare: false, out _, out int keptPlain);
        string[] prepared = Events(prepare: true, out int count, out int kept);
        Assert.Multiple(() =>
        {
            Assert.That(count, Is.EqualTo(pairs), "every pair a roadmap jump or walk links");
            Assert.That(kept, Is.GreaterThan(0));
            Assert.That(keptPlain, Is.Zero, "a world that does not prepare keeps nothing");
            Assert.That(plain.Count(e => e.Contains(nameof(JumpEventKind.TargetReached), StringComparison.Ordinal)), Is.EqualTo(4), "every agent arrives");
            Assert.That(prepared, Is.EqualTo(plain), "the same events, tick for tick");
        });
    }

    [Test]
    public void APreparationStopsWhenItsKindIsRemoved()
    {
        CharacterKind desert = RuntimeWorlds.DesertSkeleton;
        int pairs = desert.Roadmap.Edges.Select(e => (e.From, e.To)).Concat(desert.Roadmap.Walks.Select(w => (w.From, w.To))).Distinct().Count();
        var scene = PlanningScene.Create(desert.Scene.Level, desert.Scene.Character);
        using var world = new JumpWorld(scene.Level, RuntimeWorlds.JumpOnly with { PrepareSearches = true });
        KindHandle handle = world.AddKind(new CharacterKind(scene, desert.Roadmap, desert.Animator)).Kind;
        Task<int> preparation = world.GetKindPreparation(handle)!;
        Assert.That(world.RemoveKind(handle).Ok, Is.True);
        Assert.That(world.GetKindPreparation(handle), Is.Null, "the kind is gone");
        Assert.That(SpinWait.SpinUntil(() => preparation.IsCompleted, TimeSpan.FromMinutes(1)), Is.True, "the preparation ends");
        Assert.That(preparation.IsCanceled || preparation.Result < pairs, Is.True, "stopped before the end");
    }
}
