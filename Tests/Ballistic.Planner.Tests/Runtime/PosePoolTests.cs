using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Kinds;

namespace Ballistic.Planner.Tests.Runtime;

/// <summary>
/// Poses as slices of world-wide pools (issue 22 item 2): each agent's joint angles and rotations are its own slice
/// of two shared arrays, a removed agent's slices go to the next agent of the same rig, and nothing is shared.
/// </summary>
public sealed class PosePoolTests
{
    [Test]
    public void AFreedSliceGoesToTheNextOfItsLengthClearedAndGrowingKeepsWhatIsThere()
    {
        var pool = new SlicePool<float>();
        int a = pool.Rent(5);
        int b = pool.Rent(5);
        int c = pool.Rent(3);
        Assert.That(new[] { a, b, c }, Is.EqualTo(new[] { 0, 5, 10 }), "rented one after another");
        pool.Slice(b, 5).Fill(7f);
        pool.Return(b, 5);
        Assert.That(pool.Rent(3), Is.EqualTo(13), "a slice of another length does not take the freed one");
        Assert.That(pool.Rent(5), Is.EqualTo(b), "the next slice of its length does");
        Assert.That(pool.Slice(b, 5).ToArray(), Is.All.Zero, "cleared for its new owner");

        pool.Slice(a, 5).Fill(1f);
        int big = pool.Rent(200);
        Assert.That(pool.Items.Length, Is.GreaterThanOrEqualTo(big + 200), "grown");
        Assert.That(pool.Slice(a, 5).ToArray(), Is.All.EqualTo(1f), "what was there kept through the growth");
        Assert.That(pool.Top, Is.EqualTo(big + 200));
    }

    [Test]
    public void AgentsHaveDisjointPoseSlicesAndANewAgentTakesARemovedOnesWithoutGrowingThePools()
    {
        (JumpWorld world, KindHandle kind) = RuntimeWorlds.Desert();
        using (world)
        {
            Roadmap roadmap = RuntimeWorlds.DesertSkeleton.Roadmap;
            int joints = RuntimeWorlds.DesertSkeleton.JointCount;
            var agents = new List<AgentHandle>();
            for (int i = 0; i < 20; i++)
            {
                AddAgentResult added = world.AddAgent(kind, RuntimeWorlds.Point(roadmap.Nodes[i * 7 % roadmap.Nodes.Count]));
                Assert.That(added.Ok, Is.True, added.Result.ToString());
                agents.Add(added.Agent);
            }

            world.Step();
            AssertDisjointAndFilled(world, agents, joints);
            AgentHandle anchor = agents[10]; // stays: slices are told by their offset from its
            long[] removedSlices = [.. agents.Take(10).Select(a => Offset(world, anchor, a))];
            foreach (AgentHandle agent in agents.Take(10))
            {
                Assert.That(world.RemoveAgent(agent).Ok, Is.True);
            }

            agents.RemoveRange(0, 10);
            for (int i = 0; i < 10; i++)
            {
                AddAgentResult added = world.AddAgent(kind, RuntimeWorlds.Point(roadmap.Nodes[(i * 11) + 3]));
                Assert.That(added.Ok, Is.True, added.Result.ToString());
                agents.Add(added.Agent);
            }

            long[] newSlices = [.. agents.Skip(10).Select(a => Offset(world, anchor, a))];
            Assert.That(newSlices, Is.EquivalentTo(removedSlices), "the new agents took the removed ones' rotation slices, none rented anew");
            world.Step();
            AssertDisjointAndFilled(world, agents, joints);

            // One agent's pose is its own: sending one off changes no other's.
            Quaternion[][] still = [.. agents.Skip(1).Select(a => world.GetJointRotations(a).ToArray())];
            Assert.That(world.SetTarget(agents[0], RuntimeWorlds.Point(roadmap.Nodes[^1])).Ok, Is.True);
            Quaternion[] first = world.GetJointRotations(agents[0]).ToArray();
            RuntimeWorlds.Run(world, 60);
            Assert.That(world.GetJointRotations(agents[0]).ToArray(), Is.Not.EqualTo(first), "the agent sent off moved its limbs");
            for (int i = 1; i < agents.Count; i++)
            {
                Assert.That(world.GetJointRotations(agents[i]).ToArray(), Is.EqualTo(still[i - 1]), $"agent {i} kept its pose");
            }
        }
    }

    private static void AssertDisjointAndFilled(JumpWorld world, List<AgentHandle> agents, int joints)
    {
        for (int i = 0; i < agents.Count; i++)
        {
            ReadOnlySpan<Quaternion> rotations = world.GetJointRotations(agents[i]);
            Assert.That(rotations.Length, Is.EqualTo(joints));
            Assert.That(rotations.ToArray().All(q => MathF.Abs(q.Length() - 1f) < 1e-3f), Is.True, $"agent {i}'s rotations filled");
            for (int j = 0; j < i; j++)
            {
                Assert.That(rotations.Overlaps(world.GetJointRotations(agents[j])), Is.False, $"agents {i} and {j} share rotations");
                Assert.That(world.GetJointAngles(agents[i]).Overlaps(world.GetJointAngles(agents[j])), Is.False, $"agents {i} and {j} share angles");
            }
        }
    }

    /// <summary>Where <paramref name="agent"/>'s rotations lie from <paramref name="anchor"/>'s in the pool, bytes.</summary>
    private static long Offset(JumpWorld world, AgentHandle anchor, AgentHandle agent) =>
        Unsafe.ByteOffset(ref MemoryMarshal.GetReference(world.GetJointRotations(anchor)), ref MemoryMarshal.GetReference(world.GetJointRotations(agent)));
}
