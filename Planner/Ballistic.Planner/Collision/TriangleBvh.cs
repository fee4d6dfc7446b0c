using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Collision;

/// <summary>
/// A bounding-volume hierarchy over the level's triangles (binned surface-area heuristic, at most
/// <see cref="MaxLeafSize"/> triangles a leaf) answering the planner's exact queries: oriented box against the
/// level, the triangles a box touches, and the first hit of a segment. Immutable once built; safe to query from
/// many threads at once.
/// </summary>
internal sealed class TriangleBvh : ICollisionWorld
{
    /// <summary>Largest number of triangles in a leaf.</summary>
    public const int MaxLeafSize = 4;

    private const int BinCount = 12;

    /// <summary>Below this depth the surface-area heuristic chooses splits; deeper, lists are halved, bounding the depth.</summary>
    private const int HeuristicDepth = 48;

    /// <summary>Traversal stack size: the depth is at most <see cref="HeuristicDepth"/> + log₂(triangles) + 1.</summary>
    private const int StackSize = 128;

    private readonly Node[] _nodes;
    private readonly Triangle[] _triangles; // in leaf order
    private readonly Aabb[] _triangleBounds; // in leaf order
    private readonly int[] _originalIndex; // leaf order → caller's index

    /// <summary>Builds the hierarchy. Deterministic: the same triangles give the same tree.</summary>
    /// <param name="triangles">World-space triangles; their indices are the ones queries report.</param>
    public TriangleBvh(IReadOnlyList<Triangle> triangles)
    {
        ArgumentNullException.ThrowIfNull(triangles);
        int n = triangles.Count;
        var bounds = new Aabb[n];
        var centroids = new Vector3[n];
        var order = new int[n];
        for (int i = 0; i < n; i++)
        {
            bounds[i] = triangles[i].Bounds;
            centroids[i] = bounds[i].Center;
            order[i] = i;
        }

        var nodes = new List<Node>(Math.Max(1, 2 * n / MaxLeafSize));
        Build(nodes, bounds, centroids, order);
        _nodes = [.. nodes];
        _triangles = new Triangle[n];
        _triangleBounds = new Aabb[n];
        _originalIndex = order;
        for (int i = 0; i < n; i++)
        {
            _triangles[i] = triangles[order[i]];
            _triangleBounds[i] = bounds[order[i]];
        }
    }

    /// <summary>Number of triangles.</summary>
    public int TriangleCount => _triangles.Length;

    /// <summary>Number of nodes of the tree.</summary>
    public int NodeCount => _nodes.Length;

    /// <summary>Bounds of the whole level.</summary>
    internal Aabb Bounds => _nodes.Length > 0 ? _nodes[0].Bounds : Aabb.Empty;

    /// <summary>True when <paramref name="box"/> (world space) touches any triangle of the level.</summary>
    internal bool Overlaps(in OrientedBox box) => Visit(box, results: null);

    /// <inheritdoc />
    bool ICollisionWorld.Overlaps(in OrientedBox box) => Overlaps(box);

    /// <summary>Adds to <paramref name="results"/> the index of every triangle that <paramref name="box"/> touches.</summary>
    internal void OverlappingTriangles(in OrientedBox box, List<int> results)
    {
        ArgumentNullException.ThrowIfNull(results);
        Visit(box, results);
    }

    /// <summary>
    /// Adds to <paramref name="results"/>, in the order <see cref="OverlappingTriangles"/> would, the index of every
    /// triangle whose bounds meet <paramref name="box"/>'s and whose leaf the box is not separated from: a superset of
    /// the triangles the box touches, for a caller that tests each triangle exactly itself.
    /// </summary>
    internal void TrianglesNearBox(in OrientedBox box, List<int> results)
    {
        ArgumentNullException.ThrowIfNull(results);
        Visit(box, results, exact: false);
    }

    /// <summary>
    /// The first triangle met by the segment <c>origin + t·direction</c>, <c>t ∈ [0, maxT]</c> (both faces count).
    /// </summary>
    /// <returns>True with the hit when the segment meets the level.</returns>
    public bool Raycast(Vector3 origin, Vector3 direction, float maxT, out RayHit hit)
    {
        hit = default;
        if (_nodes.Length == 0)
        {
            return false;
        }

        Vector3 inverse = new(1f / direction.X, 1f / direction.Y, 1f / direction.Z);
        float best = maxT;
        int bestTriangle = -1;
        Span<int> stack = stackalloc int[StackSize];
        int top = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            ref readonly Node node = ref _nodes[stack[--top]];
            if (!node.Bounds.IntersectsRay(origin, inverse, 0f, best, out _))
            {
                continue;
            }

            if (node.Count > 0)
            {
                for (int i = node.Start; i < node.Start + node.Count; i++)
                {
                    if (IntersectRay(_triangles[i], origin, direction, out float t) && t >= 0f && t <= best)
                    {
                        best = t;
                        bestTriangle = i;
                    }
                }

                continue;
            }

            stack[top++] = node.Start;
            stack[top++] = node.Start + 1;
        }

        if (bestTriangle < 0)
        {
            return false;
        }

        Triangle tri = _triangles[bestTriangle];
        hit = new RayHit(_originalIndex[bestTriangle], best, origin + (direction * best), tri.Normal);
        return true;
    }

    /// <summary>
    /// Adds to <paramref name="results"/> every triangle whose bounding box meets <paramref name="box"/>: a quick,
    /// conservative gathering (it may include triangles that only come near the box).
    /// </summary>
    internal void TrianglesNear(Aabb box, List<int> results)
    {
        ArgumentNullException.ThrowIfNull(results);
        Near(box, results);
    }

    /// <summary>
    /// Whether some triangle's bounding box meets <paramref name="box"/>: <see cref="TrianglesNear"/> would add one. It
    /// stops at the first.
    /// </summary>
    internal bool AnyTriangleNear(Aabb box) => Near(box, results: null);

    /// <summary>The triangles whose bounding boxes meet <paramref name="box"/>, added to <paramref name="results"/> in the hierarchy's order; with none, whether there is one (stopping at the first).</summary>
    private bool Near(Aabb box, List<int>? results)
    {
        if (_nodes.Length == 0 || box.IsEmpty)
        {
            return false;
        }

        bool found = false;
        Span<int> stack = stackalloc int[StackSize];
        int top = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            ref readonly Node node = ref _nodes[stack[--top]];
            if (!node.Bounds.Intersects(box))
            {
                continue;
            }

            if (node.Count > 0)
            {
                for (int i = node.Start; i < node.Start + node.Count; i++)
                {
                    if (_triangleBounds[i].Intersects(box))
                    {
                        if (results is null)
                        {
                            return true;
                        }

                        results.Add(_originalIndex[i]);
                        found = true;
                    }
                }

                continue;
            }

            stack[top++] = node.Start;
            stack[top++] = node.Start + 1;
        }

        return found;
    }

    /// <summary>Adds to <paramref name="results"/> every triangle that touches the axis-aligned box.</summary>
    internal void TrianglesInBox(Aabb box, List<int> results)
    {
        if (box.IsEmpty)
        {
            return;
        }

        OverlappingTriangles(new OrientedBox(box.Center, box.HalfExtents, Quaternion.Identity), results);
    }

    /// <summary>Walks the tree for <paramref name="box"/>: the triangles it touches (when not <paramref name="exact"/>, those whose bounds meet its bounds), added to <paramref name="results"/>, or when that is <c>null</c> whether there is one.</summary>
    private bool Visit(in OrientedBox box, List<int>? results, bool exact = true)
    {
        if (_nodes.Length == 0)
        {
            return false;
        }

        Aabb boxBounds = box.Bounds;
        Vector3 a0 = box.AxisX;
        Vector3 a1 = box.AxisY;
        Vector3 a2 = box.AxisZ;
        Vector3 h = box.HalfExtents;
        Vector3 c = box.Center;
        bool found = false;
        Span<int> stack = stackalloc int[StackSize];
        int top = 0;
        stack[top++] = 0;
        while (top > 0)
        {
            ref readonly Node node = ref _nodes[stack[--top]];
            if (!node.Bounds.Intersects(boxBounds) || SeparatedOnBoxAxes(node.Bounds, c, a0, a1, a2, h))
            {
                continue;
            }

            if (node.Count > 0)
            {
                for (int i = node.Start; i < node.Start + node.Count; i++)
                {
                    if (_triangleBounds[i].Intersects(boxBounds) && (!exact || box.Intersects(_triangles[i])))
                    {
                        if (results is null)
                        {
                            return true;
                        }

                        results.Add(_originalIndex[i]);
                        found = true;
                    }
                }

                continue;
            }

            stack[top++] = node.Start;
            stack[top++] = node.Start + 1;
        }

        return found;
    }

    /// <summary>Separating-axis test of a node's box against the oriented box, on the oriented box's three face axes.</summary>
    private static bool SeparatedOnBoxAxes(Aabb node, Vector3 center, Vector3 a0, Vector3 a1, Vector3 a2, Vector3 h)
    {
        Vector3 d = center - node.Center;
        Vector3 e = node.HalfExtents;
        return Separated(d, e, a0, h.X) || Separated(d, e, a1, h.Y) || Separated(d, e, a2, h.Z);

        static bool Separated(Vector3 d, Vector3 e, Vector3 axis, float radius) =>
            MathF.Abs(Vector3.Dot(d, axis)) > radius + Vector3.Dot(e, Vector3.Abs(axis));
    }

    /// <summary>Möller–Trumbore, both faces.</summary>
    private static bool IntersectRay(in Triangle tri, Vector3 origin, Vector3 direction, out float t)
    {
        t = 0f;
        Vector3 e1 = tri.B - tri.A;
        Vector3 e2 = tri.C - tri.A;
        Vector3 p = Vector3.Cross(direction, e2);
        float det = Vector3.Dot(e1, p);
        if (MathF.Abs(det) < 1e-12f)
        {
            return false;
        }

        float inverse = 1f / det;
        Vector3 s = origin - tri.A;
        float u = Vector3.Dot(s, p) * inverse;
        if (u < 0f || u > 1f)
        {
            return false;
        }

        Vector3 q = Vector3.Cross(s, e1);
        float v = Vector3.Dot(direction, q) * inverse;
        if (v < 0f || u + v > 1f)
        {
            return false;
        }

        t = Vector3.Dot(e2, q) * inverse;
        return true;
    }

    private static void Build(List<Node> nodes, Aabb[] bounds, Vector3[] centroids, int[] order)
    {
        if (order.Length == 0)
        {
            return;
        }

        nodes.Add(default);
        var work = new Stack<(int NodeIndex, int Start, int Count, int Depth)>();
        work.Push((0, 0, order.Length, 0));
        Span<Aabb> binBounds = stackalloc Aabb[BinCount];
        Span<int> binCounts = stackalloc int[BinCount];
        Span<float> rightAreas = stackalloc float[BinCount];
        Span<int> rightCounts = stackalloc int[BinCount];
        while (work.Count > 0)
        {
            (int nodeIndex, int start, int count, int depth) = work.Pop();
            Aabb nodeBounds = Aabb.Empty;
            Aabb centroidBounds = Aabb.Empty;
            for (int i = start; i < start + count; i++)
            {
                nodeBounds = Aabb.Union(nodeBounds, bounds[order[i]]);
                centroidBounds = centroidBounds.Encapsulate(centroids[order[i]]);
            }

            if (count <= MaxLeafSize)
            {
                nodes[nodeIndex] = new Node(nodeBounds, start, count);
                continue;
            }

            // Binned SAH on the widest centroid axis.
            Vector3 size = centroidBounds.Max - centroidBounds.Min;
            int axis = size.X >= size.Y && size.X >= size.Z ? 0 : size.Y >= size.Z ? 1 : 2;
            float lo = Component(centroidBounds.Min, axis);
            float extent = Component(size, axis);
            int split;
            if (extent <= 1e-9f || depth >= HeuristicDepth)
            {
                split = start + (count / 2); // centroids coincide, or the tree is deep: halve the list
            }
            else
            {
                binBounds.Fill(Aabb.Empty);
                binCounts.Clear();
                float scale = BinCount / extent;
                for (int i = start; i < start + count; i++)
                {
                    int bin = Math.Min(BinCount - 1, (int)((Component(centroids[order[i]], axis) - lo) * scale));
                    binCounts[bin]++;
                    binBounds[bin] = Aabb.Union(binBounds[bin], bounds[order[i]]);
                }

                Aabb accumulated = Aabb.Empty;
                int accumulatedCount = 0;
                for (int b = BinCount - 1; b > 0; b--)
                {
                    accumulated = Aabb.Union(accumulated, binBounds[b]);
                    accumulatedCount += binCounts[b];
                    rightAreas[b] = accumulated.SurfaceArea;
                    rightCounts[b] = accumulatedCount;
                }

                float bestCost = float.PositiveInfinity;
                int bestBin = BinCount / 2;
                accumulated = Aabb.Empty;
                accumulatedCount = 0;
                for (int b = 0; b < BinCount - 1; b++)
                {
                    accumulated = Aabb.Union(accumulated, binBounds[b]);
                    accumulatedCount += binCounts[b];
                    if (accumulatedCount == 0 || rightCounts[b + 1] == 0)
                    {
                        continue;
                    }

                    float cost = (accumulated.SurfaceArea * accumulatedCount) + (rightAreas[b + 1] * rightCounts[b + 1]);
                    if (cost < bestCost)
                    {
                        bestCost = cost;
                        bestBin = b;
                    }
                }

                // Stable partition: bins ≤ bestBin to the left, keeping the input order inside each side.
                int[] left = new int[count];
                int[] right = new int[count];
                int nl = 0;
                int nr = 0;
                for (int i = start; i < start + count; i++)
                {
                    int index = order[i];
                    int bin = Math.Min(BinCount - 1, (int)((Component(centroids[index], axis) - lo) * scale));
                    if (bin <= bestBin)
                    {
                        left[nl++] = index;
                    }
                    else
                    {
                        right[nr++] = index;
                    }
                }

                if (nl == 0 || nr == 0)
                {
                    split = start + (count / 2);
                }
                else
                {
                    Array.Copy(left, 0, order, start, nl);
                    Array.Copy(right, 0, order, start + nl, nr);
                    split = start + nl;
                }
            }

            int leftChild = nodes.Count;
            nodes.Add(default);
            nodes.Add(default);
            nodes[nodeIndex] = new Node(nodeBounds, leftChild, 0);
            work.Push((leftChild + 1, split, start + count - split, depth + 1));
            work.Push((leftChild, start, split - start, depth + 1));
        }
    }

    private static float Component(Vector3 v, int axis) => axis == 0 ? v.X : axis == 1 ? v.Y : v.Z;

    /// <summary>Interior node: children at Start and Start + 1, Count = 0. Leaf: triangles [Start, Start + Count).</summary>
    private readonly record struct Node(Aabb Bounds, int Start, int Count);
}
