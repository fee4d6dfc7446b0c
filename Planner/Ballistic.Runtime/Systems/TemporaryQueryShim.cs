using System.Numerics;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;

namespace Ballistic.Runtime.Systems;

// TEMPORARY until the roadmap-index branch lands (its instance members then win over these).
internal static class TemporaryQueryShim
{
    extension(PlanResult result)
    {
        public int Expansions => 0;
    }

    extension(Roadmap roadmap)
    {
        public int? FindNode(Vector3 point, EndpointTolerance tolerance)
        {
            int? best = null;
            float bestDistance = float.PositiveInfinity;
            foreach (RoadmapNode node in roadmap.Nodes)
            {
                Vector3 c = Centre(node);
                float across = new Vector2(c.X - point.X, c.Z - point.Z).Length();
                float updown = MathF.Abs(c.Y - point.Y);
                if (across <= tolerance.Across && updown <= tolerance.UpDown && Vector3.Distance(c, point) < bestDistance)
                {
                    bestDistance = Vector3.Distance(c, point);
                    best = node.Id;
                }
            }

            return best;
        }
    }

    extension(PathQuery query)
    {
        public PlanResult Plan(RoadmapNode start, Vector3 to, QuerySettings settings, IReadOnlySet<(int From, int To)> rejected) =>
            query.Plan(Centre(start), to, settings, rejected);

        public PlanResult Plan(RoadmapNode start, RoadmapNode goal, QuerySettings settings, IReadOnlySet<(int From, int To)> rejected) =>
            query.Plan(Centre(start), Centre(goal), settings, rejected);
    }

    private static Vector3 Centre(RoadmapNode node)
    {
        Vector3 sum = Vector3.Zero;
        foreach (var c in node.Contacts)
        {
            sum += c.Position;
        }

        return node.Contacts.Count > 0 ? sum / node.Contacts.Count : node.Pose.Position;
    }
}
