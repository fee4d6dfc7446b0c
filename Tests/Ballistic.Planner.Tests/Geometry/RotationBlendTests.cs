using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Tests.Geometry;

/// <summary>
/// <see cref="RotationBlend"/>: the rotation at any amount is the one <see cref="Quaternion.Slerp"/> gives for the same
/// pair, to the bit, for rotations far apart, in opposite hemispheres, a hair apart (blended linearly), equal and
/// opposite, at the ends and between; so a flight, a walk's turn and the root between frames read the same poses as
/// before their angles were worked out once.
/// </summary>
public sealed class RotationBlendTests
{
    [Test]
    public void EveryAmountGivesTheSlerpOfThePairToTheBit()
    {
        var random = new Random(17);
        Quaternion Unit() => Quaternion.Normalize(new Quaternion(Signed(), Signed(), Signed(), Signed()));
        float Signed() => (float)(random.NextDouble() * 2.0) - 1f;
        int compared = 0;
        var kinds = new int[5];
        for (int pair = 0; pair < 20_000; pair++)
        {
            Quaternion from = Unit();
            int kind = pair % 5;
            Quaternion to = kind switch
            {
                0 => Unit(),
                1 => -Unit(),
                2 => Quaternion.Normalize(from + new Quaternion(1e-4f * Signed(), 1e-4f * Signed(), 0f, 1e-4f * Signed())),
                3 => from,
                _ => -from,
            };

            RotationBlend blend = RotationBlend.Between(from, to);
            for (int k = 0; k < 12; k++)
            {
                float amount = k switch { 0 => 0f, 1 => 1f, 2 => 0.5f, _ => (float)random.NextDouble() };
                Quaternion expected = Quaternion.Slerp(from, to, amount);
                Quaternion actual = blend.At(from, to, amount);
                if (!SameBits(expected, actual))
                {
                    Assert.Fail($"pair {pair} (kind {kind}) at {amount:R}: slerp {expected}, blend {actual}");
                }

                compared++;
            }

            kinds[kind]++;
        }

        Assert.That(compared, Is.EqualTo(240_000));
        Assert.That(kinds, Is.All.EqualTo(4_000));
    }

    [Test]
    public void AJumpsTrunkTurnsAsTheSlerpOfItsTakeoffAndLandingRotations()
    {
        // A jump's arc reads its turn from the blend; it turns from takeoff to landing rotation over the flight.
        var takeoff = new RootPose(Vector3.Zero, Quaternion.Identity);
        var landing = new RootPose(new Vector3(2f, 0f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI * 0.9f));
        var arc = new BallisticArc(takeoff, landing, new Vector3(2f, 4.905f, 0f), 1f, 9.81f);
        for (int i = 0; i <= 20; i++)
        {
            float t = i / 20f;
            Assert.That(SameBits(arc.RotationAt(t), Quaternion.Slerp(takeoff.Rotation, landing.Rotation, t)), Is.True, $"t = {t}");
        }

        Assert.That(SameBits(arc.RotationAt(-1f), Quaternion.Slerp(takeoff.Rotation, landing.Rotation, 0f)), Is.True, "clamped before takeoff");
        Assert.That(SameBits(arc.RotationAt(2f), Quaternion.Slerp(takeoff.Rotation, landing.Rotation, 1f)), Is.True, "clamped after landing");
    }

    private static bool SameBits(Quaternion a, Quaternion b) =>
        BitConverter.SingleToInt32Bits(a.X) == BitConverter.SingleToInt32Bits(b.X)
        && BitConverter.SingleToInt32Bits(a.Y) == BitConverter.SingleToInt32Bits(b.Y)
        && BitConverter.SingleToInt32Bits(a.Z) == BitConverter.SingleToInt32Bits(b.Z)
        && BitConverter.SingleToInt32Bits(a.W) == BitConverter.SingleToInt32Bits(b.W);
}
