using System.Numerics;
using System.Runtime.InteropServices;
using System.Runtime.Intrinsics;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// Landmark lower bounds on flight time for A* (ALT: A*, landmarks, triangle inequality; Goldberg and Harrelson
/// 2005). For a few landmark nodes L, the least flight time from L to every node and from every node to L is
/// computed once, when the roadmap is frozen; then for any nodes v and g, d(v, g) ≥ d(L, g) − d(L, v) and
/// d(v, g) ≥ d(v, L) − d(g, L). Unreachability is exact: when L reaches v but not g, or g reaches L but v does
/// not, v cannot reach g at all. The bounds hold for the roadmap with any jumps removed (a request's rejected
/// jumps only lengthen paths) and are consistent, so A* with them still finds a path of least flight time.
/// </summary>
/// <remarks>
/// Landmarks are chosen by farthest-point selection on the nodes' horizontal positions (the first the node
/// farthest from the centroid, then each the node farthest from those chosen, lowest id on ties): deterministic,
/// and spread over the roadmap's periphery, where they bound best. Distances are stored node-major
/// (node × landmark) so that one node's bounds are read together.
/// </remarks>
internal sealed class Landmarks
{
    /// <summary>Landmarks of a roadmap with enough nodes.</summary>
    public const int MaxCount = 8;

    /// <summary>Float sums along different paths round differently: each bound gives up this share of its terms.</summary>
    private const float Slack = 1e-5f;

    private readonly float[] _from;
    private readonly float[] _to;

    private Landmarks(int count, float[] from, float[] to)
    {
        Count = count;
        _from = from;
        _to = to;
    }

    /// <summary>None: every bound is 0.</summary>
    public static Landmarks None { get; } = new(0, [], []);

    /// <summary>Number of landmarks (0 for a roadmap without jumps).</summary>
    public int Count { get; }

    /// <summary>Least flight times d(L, v) from each landmark to node <paramref name="node"/>, seconds (+∞: unreachable).</summary>
    public ReadOnlySpan<float> From(int node) => _from.AsSpan(node * Count, Count);

    /// <summary>Least flight times d(v, L) from node <paramref name="node"/> to each landmark, seconds (+∞: unreachable).</summary>
    public ReadOnlySpan<float> To(int node) => _to.AsSpan(node * Count, Count);

    /// <summary>
    /// A lower bound (seconds) on the flight time from a node to a goal, from their landmark distances
    /// (<see cref="From"/>, <see cref="To"/>): +∞ when the node cannot reach the goal.
    /// </summary>
    public static float LowerBound(ReadOnlySpan<float> nodeFrom, ReadOnlySpan<float> nodeTo, ReadOnlySpan<float> goalFrom, ReadOnlySpan<float> goalTo)
    {
        if (nodeFrom.Length == Vector256<float>.Count && Vector256.IsHardwareAccelerated)
        {
            return LowerBoundOfEight(nodeFrom, nodeTo, goalFrom, goalTo);
        }

        return ScalarLowerBound(nodeFrom, nodeTo, goalFrom, goalTo);
    }

    /// <summary>
    /// <see cref="LowerBound"/> for eight landmarks, in one 256-bit vector per distance list: the same value bit for
    /// bit (each term is computed with the same operations, and a maximum does not depend on its order).
    /// </summary>
    private static float LowerBoundOfEight(ReadOnlySpan<float> nodeFrom, ReadOnlySpan<float> nodeTo, ReadOnlySpan<float> goalFrom, ReadOnlySpan<float> goalTo)
    {
        Vector256<float> infinity = Vector256.Create(float.PositiveInfinity);
        Vector256<float> slack = Vector256.Create(Slack);
        Vector256<float> fv = Vector256.LoadUnsafe(ref MemoryMarshal.GetReference(nodeFrom));
        Vector256<float> fg = Vector256.LoadUnsafe(ref MemoryMarshal.GetReference(goalFrom));
        Vector256<float> tv = Vector256.LoadUnsafe(ref MemoryMarshal.GetReference(nodeTo));
        Vector256<float> tg = Vector256.LoadUnsafe(ref MemoryMarshal.GetReference(goalTo));
        Vector256<float> fromReached = Vector256.LessThan(fv, infinity);
        Vector256<float> toReached = Vector256.LessThan(tg, infinity);
        if ((fromReached & Vector256.Equals(fg, infinity)) != Vector256<float>.Zero || (toReached & Vector256.Equals(tv, infinity)) != Vector256<float>.Zero)
        {
            return float.PositiveInfinity; // a landmark reaches the node but not the goal, or the goal reaches it but the node does not
        }

        Vector256<float> from = Vector256.ConditionalSelect(fromReached, fg - fv - (slack * (fg + fv)), Vector256<float>.Zero);
        Vector256<float> to = Vector256.ConditionalSelect(toReached, tv - tg - (slack * (tv + tg)), Vector256<float>.Zero);
        Vector256<float> both = Vector256.Max(from, to);
        Vector128<float> half = Vector128.Max(both.GetLower(), both.GetUpper());
        float best = MathF.Max(MathF.Max(half.GetElement(0), half.GetElement(1)), MathF.Max(half.GetElement(2), half.GetElement(3)));
        return MathF.Max(best, 0f);
    }

    /// <summary><see cref="LowerBound"/> landmark by landmark (any number of them).</summary>
    internal static float ScalarLowerBound(ReadOnlySpan<float> nodeFrom, ReadOnlySpan<float> nodeTo, ReadOnlySpan<float> goalFrom, ReadOnlySpan<float> goalTo)
    {
        float best = 0f;
        for (int l = 0; l < nodeFrom.Length; l++)
        {
            float fv = nodeFrom[l];
            float fg = goalFrom[l];
            if (fv < float.PositiveInfinity)
            {
                if (fg == float.PositiveInfinity)
                {
                    return float.PositiveInfinity; // L reaches the node but not the goal
                }

                best = MathF.Max(best, fg - fv - (Slack * (fg + fv)));
            }

            float tv = nodeTo[l];
            float tg = goalTo[l];
            if (tg < float.PositiveInfinity)
            {
                if (tv == float.PositiveInfinity)
                {
                    return float.PositiveInfinity; // the goal reaches L but the node does not
                }

                best = MathF.Max(best, tv - tg - (Slack * (tv + tg)));
            }
        }

        return best;
    }

    /// <summary>Chooses the landmarks and computes their distances over the roadmap's compressed rows.</summary>
    public static Landmarks Build(Vector2[] horizontal, int[] offsets, int[] targets, float[] times)
    {
        int n = horizontal.Length;
        int k = targets.Length == 0 ? 0 : Math.Min(MaxCount, n);
        if (k == 0)
        {
            return None;
        }

        int[] chosen = Choose(horizontal, k);

        // Reverse rows: the edges entering each node, for the distances to a landmark.
        int[] reverseOffsets = new int[n + 1];
        foreach (int t in targets)
        {
            reverseOffsets[t + 1]++;
        }

        for (int i = 0; i < n; i++)
        {
            reverseOffsets[i + 1] += reverseOffsets[i];
        }

        int[] reverseSources = new int[targets.Length];
        float[] reverseTimes = new float[targets.Length];
        int[] next = reverseOffsets[..n];
        for (int v = 0; v < n; v++)
        {
            for (int e = offsets[v]; e < offsets[v + 1]; e++)
            {
                int slot = next[targets[e]]++;
                reverseSources[slot] = v;
                reverseTimes[slot] = times[e];
            }
        }

        float[] from = new float[n * k];
        float[] to = new float[n * k];
        float[] distance = new float[n];
        var open = new PriorityQueue<int, float>();
        for (int l = 0; l < k; l++)
        {
            ShortestTimes(chosen[l], offsets, targets, times, distance, open);
            for (int v = 0; v < n; v++)
            {
                from[(v * k) + l] = distance[v];
            }

            ShortestTimes(chosen[l], reverseOffsets, reverseSources, reverseTimes, distance, open);
            for (int v = 0; v < n; v++)
            {
                to[(v * k) + l] = distance[v];
            }
        }

        return new Landmarks(k, from, to);
    }

    /// <summary>Farthest-point selection on horizontal positions, lowest id on ties.</summary>
    private static int[] Choose(Vector2[] horizontal, int k)
    {
        int n = horizontal.Length;
        Vector2 centroid = Vector2.Zero;
        foreach (Vector2 p in horizontal)
        {
            centroid += p;
        }

        centroid /= n;
        float[] nearest = new float[n];
        Array.Fill(nearest, float.PositiveInfinity);
        int[] chosen = new int[k];
        int pick = Farthest(horizontal, i => Vector2.DistanceSquared(horizontal[i], centroid));
        for (int l = 0; l < k; l++)
        {
            chosen[l] = pick;
            for (int i = 0; i < n; i++)
            {
                nearest[i] = MathF.Min(nearest[i], Vector2.DistanceSquared(horizontal[i], horizontal[pick]));
            }

            pick = Farthest(horizontal, i => nearest[i]);
        }

        return chosen;
    }

    private static int Farthest(Vector2[] horizontal, Func<int, float> score)
    {
        int best = 0;
        float bestScore = float.NegativeInfinity;
        for (int i = 0; i < horizontal.Length; i++)
        {
            float s = score(i);
            if (s > bestScore)
            {
                (best, bestScore) = (i, s);
            }
        }

        return best;
    }

    /// <summary>Dijkstra from <paramref name="source"/> over compressed rows: least total flight time to every node.</summary>
    private static void ShortestTimes(int source, int[] offsets, int[] targets, float[] times, float[] distance, PriorityQueue<int, float> open)
    {
        Array.Fill(distance, float.PositiveInfinity);
        open.Clear();
        distance[source] = 0f;
        open.Enqueue(source, 0f);
        while (open.TryDequeue(out int node, out float d))
        {
            if (d > distance[node])
            {
                continue;
            }

            for (int e = offsets[node]; e < offsets[node + 1]; e++)
            {
                int next = targets[e];
                float candidate = d + times[e];
                if (candidate < distance[next])
                {
                    distance[next] = candidate;
                    open.Enqueue(next, candidate);
                }
            }
        }
    }
}
