using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Tests.Geometry;

/// <summary>
/// <see cref="SortedLookup"/>: the first value at or above a given one, found by slices or stepped to from a hint
/// (an agent's last tick), is the one a walk through the values finds, on values with repeats, runs and gaps, for
/// values below, between, on and above them, NaN and infinities, and hints anywhere.
/// </summary>
public sealed class SortedLookupTests
{
    [Test]
    public void TheFirstValueAtOrAboveIsFoundWhateverTheHint()
    {
        var random = new Random(11);
        for (int set = 0; set < 200; set++)
        {
            int n = 1 + random.Next(40);
            float[] values = new float[n];
            values[0] = (float)(random.NextDouble() * 10.0) - 5f;
            for (int i = 1; i < n; i++)
            {
                double roll = random.NextDouble();
                values[i] = values[i - 1] + (roll < 0.2 ? 0f : roll < 0.3 ? 1e-6f : roll < 0.4 ? 5f * (float)random.NextDouble() : 0.1f);
            }

            var lookup = new SortedLookup(values);

            // The reference: 0 at or below the first value (and for NaN), the last above the last, else the first at or above.
            int Reference(float value)
            {
                if (!(value > values[0]))
                {
                    return 0;
                }

                for (int i = 0; i < n; i++)
                {
                    if (values[i] >= value)
                    {
                        return i;
                    }
                }

                return n - 1;
            }

            var probes = values.Concat(values.Zip(values.Skip(1), (a, b) => 0.5f * (a + b)))
                .Concat(values.Select(v => BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(v) + 1)))
                .Concat(values.Select(v => v - 1e-6f))
                .Concat(Enumerable.Range(0, 50).Select(_ => values[0] - 1f + ((values[^1] - values[0] + 2f) * (float)random.NextDouble())))
                .Concat([float.NaN, float.NegativeInfinity, float.PositiveInfinity, values[0] - 1f, values[^1] + 1f]);
            int carried = 0;
            Assert.Multiple(() =>
            {
                foreach (float value in probes)
                {
                    int expected = Reference(value);
                    Assert.That(lookup.FirstAtOrAbove(value), Is.EqualTo(expected), $"set {set} ({n} values) at {value}");
                    foreach (int h in new[] { carried, -1, 0, n - 1, n, n / 2, int.MaxValue, int.MinValue, random.Next(-2, n + 2) })
                    {
                        int hint = h;
                        Assert.That(lookup.FirstAtOrAbove(value, ref hint), Is.EqualTo(expected), $"set {set} at {value} from {h}");
                        Assert.That(hint, Is.EqualTo(expected), "the hint is left on the answer");
                    }

                    carried = expected;
                }
            });
        }
    }
}
