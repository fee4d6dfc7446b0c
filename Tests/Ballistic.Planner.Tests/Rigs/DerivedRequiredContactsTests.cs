using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>A spec without <c>requiredContacts</c> gets half its feet, rounded up: a six-legged rig does not stand on two legs (before: 2 for any rig).</summary>
public sealed class DerivedRequiredContactsTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-required-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [TestCase("ant", 6, 3)]
    [TestCase("skeleton", 2, 2)]
    public void ASpecWithoutRequiredContactsNeedsHalfItsFeet(string name, int feet, int required)
    {
        string characters = Path.Combine(RepositoryFiles.Root, "Scenes", "characters");
        JsonObject spec = JsonNode.Parse(File.ReadAllText(Path.Combine(characters, name + ".limbs.json")))!.AsObject();
        Assert.That(spec.Remove("requiredContacts"), Is.True, "the bundled spec gives it");
        string path = Path.Combine(_folder, name + ".limbs.json");
        File.WriteAllText(path, spec.ToJsonString());
        (CharacterModel model, ReducedCharacter reduced) = CharacterSpecFile.Load(Path.Combine(characters, name + ".glb"), path);
        Assert.That(model.Limbs.Count(l => l.Kind == LimbKind.Foot), Is.EqualTo(feet));
        Assert.That(reduced.RequiredContacts, Is.EqualTo(required));
    }
}
