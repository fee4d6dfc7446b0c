using System.Numerics;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// The points spread over a bone's skin (<see cref="MeshDefaults.Spread"/>) that keep a loaded rig's head or tail out
/// of the level along with its hull's extremes: a door's jamb entered a Rigify panda's box-shaped head 9.7 cm between
/// the extremes, in a walk reported exact.
/// </summary>
public sealed class SpreadSkinProbeTests
{
    [Test]
    public void PointsAreSpreadOverTheWholeSkinNotOnlyItsExtremes()
    {
        // A 0.3 m box-shaped head, its six faces a grid of vertices 1 cm apart (5,400 vertices).
        var points = new List<Vector3>();
        for (int face = 0; face < 6; face++)
        {
            for (int i = 0; i < 30; i++)
            {
                for (int k = 0; k < 30; k++)
                {
                    float u = -0.145f + (0.01f * i);
                    float v = -0.145f + (0.01f * k);
                    float w = face % 2 == 0 ? 0.15f : -0.15f;
                    points.Add((face / 2) switch { 0 => new Vector3(w, u, v), 1 => new Vector3(u, w, v), _ => new Vector3(u, v, w) });
                }
            }
        }

        Vector3[] spread = MeshDefaults.Spread(points);
        Vector3[] extremes = MeshDefaults.Extremes(points);

        // A jamb's vertical edge entering the front face (z = 0.15) 2 cm deep at its middle, at 45°: the face is inside
        // it where |x| < 2 cm.
        static bool InJamb(Vector3 p) => p.Z > 0.149f && MathF.Abs(p.X) < 0.02f;
        Assert.Multiple(() =>
        {
            Assert.That(spread, Has.Length.LessThanOrEqualTo(MeshDefaults.SpreadCap));
            Assert.That(spread, Has.All.Matches<Vector3>(points.Contains), "every spread point is a vertex of the skin");
            Assert.That(points.Max(p => spread.Min(q => Vector3.Distance(p, q))), Is.LessThanOrEqualTo(MeshDefaults.SpreadSpacing * 1.5f * MathF.Sqrt(3f)), "every vertex has a spread point within a (widened) cell of it");
            Assert.That(spread.Count(InJamb), Is.GreaterThan(0), "a spread point lies inside the jamb's edge");
            Assert.That(extremes.Count(InJamb), Is.Zero, "no extreme does: they are the box's corners and faces' first vertices");
            Assert.That(MeshDefaults.Spread([]), Is.Empty, "no skin, no points");
            Assert.That(MeshDefaults.Spread(points), Is.EqualTo(spread), "the same skin gives the same points");
        });
    }
}
