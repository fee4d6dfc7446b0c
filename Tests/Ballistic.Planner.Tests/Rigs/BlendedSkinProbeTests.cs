using System.Numerics;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// The blended skin a loaded rig's body check probes (<see cref="MeshDefaults.BlendedExtremes"/>): only vertices
/// weighted to several bones, and along the bone's whole length, not only at its ends (the mixamo-shaped human's shin,
/// skinned 0.3 to the thigh, went 3.3 cm into a step at the middle of its back after a landing on the stairs).
/// </summary>
public sealed class BlendedSkinProbeTests
{
    [Test]
    public void BlendedSkinIsProbedAlongTheBoneAndRigidSkinIsLeftToTheBone()
    {
        // A shin's box down its bone's −Y (0.42 m), a ring of 8 vertices every 3 cm, all skinned 0.7 to the shin and
        // 0.3 to the thigh, but for a rigid ring at its foot end.
        var points = new List<Vector3>();
        var blends = new List<SkinBlend[]>();
        for (int k = 0; k <= 14; k++)
        {
            for (int a = 0; a < 8; a++)
            {
                float angle = a * MathF.PI / 4f;
                var p = new Vector3(0.05f * MathF.Sin(angle), -0.03f * k, 0.06f * MathF.Cos(angle));
                points.Add(p);
                blends.Add(k == 14 ? [] : [new SkinBlend(1, 0.3f, p + new Vector3(0f, -0.42f, 0f)), new SkinBlend(2, 0.7f, p)]);
            }
        }

        SkinBlend[][] probes = MeshDefaults.BlendedExtremes(points, blends);
        Vector3[] at = [.. probes.Select(b => b.Single(part => part.Joint == 2).Point)];
        Assert.Multiple(() =>
        {
            Assert.That(at.Where(p => p.Z <= -0.04f).Min(p => MathF.Abs(p.Y + 0.21f)), Is.LessThanOrEqualTo(0.05f), "the back is probed near the middle of the bone");
            Assert.That(at, Has.None.Matches<Vector3>(p => p.Y < -0.40f), "the rigid ring is not a blended probe");
            Assert.That(probes, Has.All.Matches<SkinBlend[]>(b => MathF.Abs(b.Sum(part => part.Weight) - 1f) < 1e-6f), "each keeps its bones' shares");
            Assert.That(probes.Length, Is.LessThanOrEqualTo(MeshDefaults.BlendSlices * 14));
            Assert.That(MeshDefaults.BlendedExtremes(points, [.. blends.Select(_ => Array.Empty<SkinBlend>())]), Is.Empty, "no blended skin, no probes");
        });
    }
}
