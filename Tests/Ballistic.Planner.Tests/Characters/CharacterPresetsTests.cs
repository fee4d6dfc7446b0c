using Ballistic.Authoring.Characters;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Tests.Characters;

public sealed class CharacterPresetsTests
{
    [TestCase("skeleton", 0.5f, 8f, 12f, 4, 2)]
    [TestCase("frog", 1.2f, 5f, 9f, 4, 4)]
    [TestCase("ant", 1.2f, 8f, 11f, 6, 3)]
    [TestCase("jumperman", 1.2f, 30f, 30f, 4, 2)]
    public void PresetsFollowTheOriginalScenarios(string name, float mu, float takeoff, float landing, int limbs, int required)
    {
        ReducedCharacter c = CharacterPresets.Get(name);
        Assert.Multiple(() =>
        {
            Assert.That(c.Name, Is.EqualTo(name));
            Assert.That(c.Friction, Is.EqualTo(mu));
            Assert.That(c.TakeoffSpeedMax, Is.EqualTo(takeoff));
            Assert.That(c.LandingSpeedMax, Is.EqualTo(landing));
            Assert.That(c.Limbs, Has.Count.EqualTo(limbs));
            Assert.That(c.RequiredContacts, Is.EqualTo(required));
            // Every workspace reaches below the trunk, or the character could never stand.
            Assert.That(c.Reach, Is.GreaterThan(c.TrunkHalfExtents.Y));
        });
    }

    [Test]
    public void UnknownPresetListsTheKnownOnes()
    {
        Assert.That(() => CharacterPresets.Get("dragon"), Throws.TypeOf<CharacterException>().With.Message.Contains("dragon").And.Message.Contains("skeleton, frog, ant, jumperman"));
    }

    [Test]
    public void InvalidCharactersAreRejectedByName()
    {
        ReducedCharacter s = CharacterPresets.Skeleton();
        Assert.Multiple(() =>
        {
            Assert.That(() => new ReducedCharacter("x", s.TrunkHalfExtents, s.Limbs, 5, 8f, 12f, 0.5f), Throws.TypeOf<CharacterException>().With.Message.Contains("5 required contacts"));
            Assert.That(() => new ReducedCharacter("x", s.TrunkHalfExtents, [s.Limbs[0], s.Limbs[0]], 1, 8f, 12f, 0.5f), Throws.TypeOf<CharacterException>().With.Message.Contains("left_foot"));
            Assert.That(() => new ReducedCharacter("x", s.TrunkHalfExtents, s.Limbs, 2, -1f, 12f, 0.5f), Throws.TypeOf<CharacterException>().With.Message.Contains("takeoffSpeedMax"));
            Assert.That(() => new ReducedCharacter("x", s.TrunkHalfExtents, [], 1, 8f, 12f, 0.5f), Throws.TypeOf<CharacterException>().With.Message.Contains("no limbs"));
        });
    }

    [Test]
    public void FingerprintTracksEveryPlanningParameter()
    {
        ReducedCharacter s = CharacterPresets.Skeleton();
        var faster = new ReducedCharacter(s.Name, s.TrunkHalfExtents, s.Limbs, s.RequiredContacts, 8.5f, s.LandingSpeedMax, s.Friction);
        Assert.Multiple(() =>
        {
            Assert.That(CharacterPresets.Skeleton().Fingerprint, Is.EqualTo(s.Fingerprint));
            Assert.That(faster.Fingerprint, Is.Not.EqualTo(s.Fingerprint));
        });
    }
}
