using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Authoring.Levels;

/// <summary>Accumulates positions and triangles for one generated mesh.</summary>
internal sealed class MeshBuilder
{
    public List<Vector3> Positions { get; } = [];

    public List<int> Indices { get; } = [];

    public int TriangleCount => Indices.Count / 3;

    /// <summary>Adds a vertex and returns its index.</summary>
    public int Vertex(Vector3 p)
    {
        Positions.Add(p);
        return Positions.Count - 1;
    }

    public void Triangle(int a, int b, int c) => Indices.AddRange([a, b, c]);

    /// <summary>A quad a-b-c-d, counter-clockwise seen from the front, split into n × m cells.</summary>
    public void Quad(Vector3 a, Vector3 b, Vector3 c, Vector3 d, int n = 1, int m = 1)
    {
        int start = Positions.Count;
        for (int i = 0; i <= n; i++)
        {
            float u = i / (float)n;
            Vector3 left = Vector3.Lerp(a, d, u);
            Vector3 right = Vector3.Lerp(b, c, u);
            for (int j = 0; j <= m; j++)
            {
                Positions.Add(Vector3.Lerp(left, right, j / (float)m));
            }
        }

        for (int i = 0; i < n; i++)
        {
            for (int j = 0; j < m; j++)
            {
                int p00 = start + (i * (m + 1)) + j;
                int p01 = p00 + 1;
                int p10 = p00 + m + 1;
                int p11 = p10 + 1;
                Indices.AddRange([p00, p01, p11, p00, p11, p10]);
            }
        }
    }

    /// <summary>A closed axis-aligned box with outward faces, each face split into cells of about <paramref name="cell"/> metres.</summary>
    public void Box(Vector3 min, Vector3 max, float cell = float.PositiveInfinity)
    {
        int N(float length) => Math.Max(1, (int)MathF.Ceiling(length / cell));
        Vector3 s = max - min;
        Vector3 P(float x, float y, float z) => new(x, y, z);

        // Each face: corners counter-clockwise seen from outside.
        Quad(P(min.X, max.Y, min.Z), P(min.X, max.Y, max.Z), P(max.X, max.Y, max.Z), P(max.X, max.Y, min.Z), N(s.X), N(s.Z)); // top (+Y)
        Quad(P(min.X, min.Y, min.Z), P(max.X, min.Y, min.Z), P(max.X, min.Y, max.Z), P(min.X, min.Y, max.Z), N(s.Z), N(s.X)); // bottom (−Y)
        Quad(P(min.X, min.Y, max.Z), P(max.X, min.Y, max.Z), P(max.X, max.Y, max.Z), P(min.X, max.Y, max.Z), N(s.Y), N(s.X)); // +Z
        Quad(P(max.X, min.Y, min.Z), P(min.X, min.Y, min.Z), P(min.X, max.Y, min.Z), P(max.X, max.Y, min.Z), N(s.Y), N(s.X)); // −Z
        Quad(P(max.X, min.Y, max.Z), P(max.X, min.Y, min.Z), P(max.X, max.Y, min.Z), P(max.X, max.Y, max.Z), N(s.Y), N(s.Z)); // +X
        Quad(P(min.X, min.Y, min.Z), P(min.X, min.Y, max.Z), P(min.X, max.Y, max.Z), P(min.X, max.Y, min.Z), N(s.Y), N(s.Z)); // −X
    }

    /// <summary>A flat disc (top face up, bottom face down, rim) of <paramref name="segments"/> sides.</summary>
    public void Disc(Vector3 center, float radius, float thickness, int segments)
    {
        int top = Vertex(center);
        int bottom = Vertex(center - new Vector3(0f, thickness, 0f));
        int ring = Positions.Count;
        for (int k = 0; k < segments; k++)
        {
            float a = 2f * MathF.PI * k / segments;
            var offset = new Vector3(radius * MathF.Cos(a), 0f, radius * MathF.Sin(a));
            Vertex(center + offset);
            Vertex(center + offset - new Vector3(0f, thickness, 0f));
        }

        for (int k = 0; k < segments; k++)
        {
            int t0 = ring + (2 * k);
            int b0 = t0 + 1;
            int t1 = ring + (2 * ((k + 1) % segments));
            int b1 = t1 + 1;
            Triangle(top, t1, t0);
            Triangle(bottom, b0, b1);
            Triangle(t0, t1, b1);
            Triangle(t0, b1, b0);
        }
    }

    public LevelMesh ToMesh(string name, LevelMaterial material, Vector4 color) => new(name, [.. Positions], [.. Indices], material, color);
}
