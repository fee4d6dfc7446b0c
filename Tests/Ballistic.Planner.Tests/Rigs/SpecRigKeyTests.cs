using System.Text.Json.Nodes;
using Ballistic.Cli;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Rigs;

/// <summary>
/// A limb spec may name its rig (<c>"rig": "rigs/hero.glb"</c>), so that two specs share one rig without a copy; the
/// path stays inside the spec's folder, like a .gltf's buffers.
/// </summary>
public sealed class SpecRigKeyTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-rigkey-{Guid.NewGuid():N}");
        Directory.CreateDirectory(Path.Combine(_folder, "specs", "rigs"));
        File.Copy(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.glb"), Path.Combine(_folder, "specs", "rigs", "hero.glb"));
        File.Copy(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.glb"), Path.Combine(_folder, "outside.glb"));
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    /// <summary>The frog's spec saved as <paramref name="name"/> in the specs folder, with <paramref name="rig"/> as its rig key (none when <c>null</c>).</summary>
    private string Spec(string name, string? rig)
    {
        JsonObject spec = JsonNode.Parse(File.ReadAllText(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.limbs.json")))!.AsObject();
        if (rig is not null)
        {
            spec["rig"] = rig;
        }

        string path = Path.Combine(_folder, "specs", name);
        File.WriteAllText(path, spec.ToJsonString());
        return path;
    }

    [Test]
    public void TwoSpecsShareTheRigTheirRigKeyNames()
    {
        (CharacterModel heavy, _) = CharacterSpecFile.Load(Spec("heavy.limbs.json", "rigs/hero.glb"));
        (CharacterModel light, _) = CharacterSpecFile.Load(Spec("light.limbs.json", "./rigs/hero.glb"));
        Assert.That(heavy.Rig.Joints.Select(j => j.Name), Is.EqualTo(light.Rig.Joints.Select(j => j.Name)));

        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(["bake", "--level", RepositoryFiles.Level("gap-course"), "--character", Path.Combine(_folder, "specs", "heavy.limbs.json"), "--max-nodes", "10", "--out", Path.Combine(_folder, "heavy.roadmap")], output, error);
        Assert.That(code, Is.Zero, error.ToString());
    }

    [TestCase("../outside.glb", "key 'rig': '../outside.glb' leads out of the spec's folder")]
    [TestCase("/tmp/hero.glb", "is an absolute path")]
    [TestCase("rigs/hero.fbx", "key 'rig'", "not a .glb or .gltf file")]
    [TestCase("rigs/villain.glb", "key 'rig' names 'rigs/villain.glb', which does not exist in the spec's folder")]
    public void ARigKeyOutsideTheFolderOrMissingIsRefusedInOneLine(string rig, params string[] fragments)
    {
        string spec = Spec("bad.limbs.json", rig);
        RigException e = Assert.Throws<RigException>(() => CharacterSpecFile.Load(spec))!;
        Assert.That(e.Message, Does.Contain("bad.limbs.json").And.Not.Contain("\n"));
        foreach (string fragment in fragments)
        {
            Assert.That(e.Message, Does.Contain(fragment));
        }
    }

    [Test]
    public void WithoutARigKeyTheRigBesideTheSpecIsUsedOrItsAbsenceSaid()
    {
        string spec = Spec("lonely.limbs.json", rig: null);
        Assert.That(() => CharacterSpecFile.Load(spec), Throws.TypeOf<RigException>().With.Message.Contains("needs its rigged character: give its path as key 'rig', or put it beside the spec as lonely.glb or lonely.gltf"));
        File.Copy(Path.Combine(_folder, "specs", "rigs", "hero.glb"), Path.Combine(_folder, "specs", "lonely.glb"));
        Assert.That(CharacterSpecFile.Load(spec).Model.Rig.Joints, Is.Not.Empty);
    }
}
