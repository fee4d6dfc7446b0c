using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Hosting;

/// <summary>Where an agent stands (its body point there is the stance's contact centre, <see cref="BodyMotion"/>).</summary>
internal static class Stances
{
    /// <summary>
    /// The stance the agent stands on, or, following a path, the one it stands on next: the end of the move it is in
    /// (a jump's landing, a walk's last stance), or the first stance of the next move between two moves. <c>null</c>
    /// for an unknown agent.
    /// </summary>
    public static RoadmapNode? Standing(JumpWorld world, AgentHandle agent)
    {
        if (world.GetStance(agent) is { } stance)
        {
            return stance;
        }

        if (world.GetPath(agent) is not { } path)
        {
            return null;
        }

        float t = world.GetPathTime(agent);
        for (int i = 0; i < path.Count; i++)
        {
            PathMove move = path.Moves[i];
            if (t < move.Start)
            {
                return move.From;
            }

            if (t < move.End)
            {
                return move.To;
            }
        }

        return path.Goal;
    }

    /// <summary>True when <paramref name="node"/> is <paramref name="roadmap"/>'s node of its id.</summary>
    public static bool IsNodeOf(Roadmap roadmap, RoadmapNode node) =>
        (uint)node.Id < (uint)roadmap.Nodes.Count && roadmap.Nodes[node.Id].Pose == node.Pose;
}
