using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

/// <summary>The angle between two rotations, exact near zero as near π.</summary>
public sealed class RotationsTests
{
    /// <summary>
    /// Seeded headings and turns from 10⁻⁵ rad to nearly π: the angle read back is the turn within 10⁻⁶ rad (the cosine
    /// of the quaternions' dot product read 10⁻³ rad as 0 to 1.3·10⁻³ and a rounding error as a 0.4 s turn in place).
    /// </summary>
    [Test]
    public void TheAngleBetweenTwoHeadingsIsTheTurnBetweenThem()
    {
        var random = new Random(5);
        var wrong = new List<string>();
        foreach (float turn in (float[])[1e-5f, 1e-4f, 1e-3f, 0.1f, 1f, 3f])
        {
            for (int k = 0; k < 100; k++)
            {
                float heading = (float)(random.NextDouble() * 2.0 * Math.PI);
                Quaternion a = Quaternion.CreateFromAxisAngle(Vector3.UnitY, heading);
                Quaternion b = a * Quaternion.CreateFromAxisAngle(Vector3.UnitY, k % 2 == 0 ? turn : -turn);
                float seen = Rotations.AngleBetween(a, -b);
                if (MathF.Abs(seen - turn) > 1e-6f + (1e-6f * turn))
                {
                    wrong.Add($"{turn} rad from {heading:0.000}: {seen}");
                }
            }
        }

        Assert.That(wrong, Is.Empty);
    }

    /// <summary>
    /// A rotation is no angle from itself, though single precision makes it no unit quaternion (a quarter turn about
    /// +Y has squared length 0.99999994: the cosine of the dot product read 7·10⁻⁴ rad).
    /// </summary>
    [Test]
    public void ARotationIsNoAngleFromItself()
    {
        float[] seen = [.. Enumerable.Range(0, 16).Select(k => Quaternion.CreateFromAxisAngle(Vector3.UnitY, k * MathF.PI / 8f)).Select(q => Rotations.AngleBetween(q, q))];
        Assert.That(seen, Has.All.LessThan(1e-6f));
    }
}
