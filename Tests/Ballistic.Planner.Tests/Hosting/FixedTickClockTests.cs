using Ballistic.Runtime.Hosting;

namespace Ballistic.Planner.Tests.Hosting;

/// <summary>The Godot server's fixed-tick clock: whole ticks per frame, capped, and never stopped by a bad delta.</summary>
public sealed class FixedTickClockTests
{
    private const double Tick = 1.0 / 60.0;

    [Test]
    public void FramesOfOneTickStepOnceEachAndHalfTicksEveryOtherFrame()
    {
        var clock = new FixedTickClock(Tick);
        Assert.That(Enumerable.Range(0, 600).Sum(_ => clock.Advance(Tick)), Is.EqualTo(600), "60 Hz frames at 60 Hz ticks: one each, none lost to rounding");
        var half = new FixedTickClock(Tick);
        int[] steps = [.. Enumerable.Range(0, 8).Select(_ => half.Advance(Tick / 2))];
        Assert.That(steps, Is.EqualTo(new[] { 0, 1, 0, 1, 0, 1, 0, 1 }));
    }

    [Test]
    public void AHitchStepsAtMostTheCapAndDropsTheRest()
    {
        var clock = new FixedTickClock(Tick, maxTicksPerFrame: 4);
        Assert.That(clock.Advance(2.0), Is.EqualTo(4));
        Assert.That(clock.Accumulated, Is.LessThan(Tick));
        Assert.That(clock.Advance(Tick), Is.EqualTo(1), "and goes on at the normal rate");
    }

    [TestCase(double.NaN)]
    [TestCase(double.PositiveInfinity)]
    [TestCase(double.NegativeInfinity)]
    [TestCase(-1e9)]
    [TestCase(-0.5)]
    public void ABadDeltaAddsNothingAndTheClockGoesOn(double bad)
    {
        var clock = new FixedTickClock(Tick);
        clock.Advance(Tick / 2);
        Assert.That(clock.Advance(bad), Is.Zero);
        Assert.That(clock.Accumulated, Is.EqualTo(Tick / 2), "the bad frame changed nothing");
        Assert.That(Enumerable.Range(0, 60).Sum(_ => clock.Advance(Tick)), Is.EqualTo(60), "the next frames step as ever");
    }

    [Test]
    public void ATickThatIsNotPositiveOrACapBelowOneIsRefused()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => _ = new FixedTickClock(0.0));
        Assert.Throws<ArgumentOutOfRangeException>(() => _ = new FixedTickClock(double.NaN));
        Assert.Throws<ArgumentOutOfRangeException>(() => _ = new FixedTickClock(Tick, 0));
    }
}
