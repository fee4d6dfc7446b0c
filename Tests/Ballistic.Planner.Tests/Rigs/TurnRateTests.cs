using System.Globalization;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// How fast a rig turns in place comes from where its feet stand (<see cref="ReducedModelBuilder.TurnRate"/>): a turn
/// carries a foot standing ahead of or behind the trunk's centre sideways under it.
/// </summary>
public sealed class TurnRateTests
{
    [Test]
    public void AnAntTurnsSlowerThanRigsWhoseFeetStandUnderTheirTrunk()
    {
        Assert.Multiple(() =>
        {
            Assert.That(CharacterPresets.Get("skeleton").Walking.TurnRate, Is.EqualTo(WalkingLimits.DefaultTurnRate), "a biped's feet stand beside its trunk's centre");
            Assert.That(CharacterPresets.Get("jumperman").Walking.TurnRate, Is.EqualTo(WalkingLimits.DefaultTurnRate));
            Assert.That(CharacterPresets.Get("ant").Walking.TurnRate, Is.LessThan(0.5f * WalkingLimits.DefaultTurnRate), "its front and hind feet stand about twice its leg ahead of and behind its centre");
        });
    }

    [Test]
    public void TheReadmeGivesTheAntsTurnRate()
    {
        string rate = string.Create(CultureInfo.InvariantCulture, $"the ant turns at {CharacterPresets.Get("ant").Walking.TurnRate:0.0} rad/s");
        string readme = string.Join(' ', File.ReadAllText(Path.Combine(RepositoryFiles.Root, "README.md")).Split((char[])[' ', '\n', '\r'], StringSplitOptions.RemoveEmptyEntries));
        Assert.That(readme.Contains(rate, StringComparison.Ordinal), Is.True, $"the README says \"{rate}\"");
    }

    [Test]
    public void NoFootIsCarriedSidewaysFasterThanTheSweepAllows()
    {
        // Checked from the contact pose directly: at the rate derived, each foot standing d ahead of (or behind) the
        // trunk's centre moves sideways at rate·d, within TurnSweep of its leg per second, and the fastest foot at it.
        CharacterModel model = CharacterPresets.Model("ant");
        float rate = ReducedModelBuilder.TurnRate(model);
        var positions = new Vector3[model.Rig.Joints.Count];
        var rotations = new Quaternion[model.Rig.Joints.Count];
        model.Rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, positions, rotations);
        float worst = 0f;
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            float hip = positions[limb.RootJoint].Y;
            float leg = MathF.Max(hip - limb.EffectorPosition(positions, rotations).Y, 0f);
            worst = MathF.Max(worst, rate * MathF.Abs(limb.EffectorPosition(positions, rotations).Z) / leg);
        }

        Assert.That(worst, Is.EqualTo(ReducedModelBuilder.TurnSweep).Within(0.01f));
    }

    [Test]
    public void ASpecGivingItsWalkingSpeedKeepsTheRigsTurnRate()
    {
        // The bundled ant's spec sets walkSpeed: the walking limits it builds keep the rate derived from its feet.
        CharacterModel model = CharacterPresets.Model("ant");
        Assert.That(CharacterPresets.Get("ant").Walking.TurnRate, Is.EqualTo(ReducedModelBuilder.TurnRate(model)));
    }
}
