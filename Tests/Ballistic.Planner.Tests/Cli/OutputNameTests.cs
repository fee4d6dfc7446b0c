using System.Text.Json.Nodes;
using Ballistic.Cli;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Cli;

public sealed class OutputNameTests
{
    [TestCase("frog", "frog")]
    [TestCase("mixamo_human", "mixamo_human")]
    [TestCase("../../../../../../tmp/x/evil", "tmp_x_evil")]
    [TestCase("a/b", "a_b")]
    [TestCase(@"C:\Windows\evil", "C__Windows_evil")]
    [TestCase(".hidden", "hidden")]
    [TestCase("..", "fallback")]
    [TestCase("", "fallback")]
    [TestCase("\u001b[2J", "2J")]
    [TestCase("Fröschlein 2", "Fr_schlein_2")]
    public void ANameFromAFileBecomesASlugThatIsNoPath(string name, string slug) =>
        Assert.That(OutputName.Slug(name, "fallback"), Is.EqualTo(slug));

    [Test]
    public void ALongNameIsCutAndNoSlugIsEverAPath()
    {
        string slug = OutputName.Slug(new string('a', 500) + "/..", "fallback");
        Assert.Multiple(() =>
        {
            Assert.That(slug, Has.Length.EqualTo(OutputName.MaxLength));
            foreach (string name in new[] { "../x", "x/../../y", "/etc/passwd", "..\\..\\z", "a\0b", "x/." })
            {
                string s = OutputName.Slug(name, "fallback");
                Assert.That(s, Does.Not.Contain('/').And.Not.Contain('\\').And.Not.StartWith("."), name);
                Assert.That(Path.GetFileName(s), Is.EqualTo(s), name);
            }
        });
    }

    [Test]
    public void APlaytestWritesOnlyIntoItsOutFolderWhateverTheSpecIsNamed()
    {
        string root = Path.Combine(Path.GetTempPath(), "ballistic-outname-" + Guid.NewGuid().ToString("N"));
        string mods = Path.Combine(root, "a", "b", "mods");
        string output = Path.Combine(mods, "out");
        Directory.CreateDirectory(mods);
        try
        {
            // A mod's copy of the frog whose spec names it with a path out of the output folder.
            JsonNode spec = JsonNode.Parse(File.ReadAllText(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.limbs.json")))!;
            spec["name"] = "../../../escape/evil";
            File.WriteAllText(Path.Combine(mods, "mod.limbs.json"), spec.ToJsonString());
            File.Copy(Path.Combine(RepositoryFiles.Root, "Scenes", "characters", "frog.glb"), Path.Combine(mods, "mod.glb"));
            using var stdout = new StringWriter();
            using var stderr = new StringWriter();
            int code = BallisticCli.Run(
                ["playtest", "--level", RepositoryFiles.Level("pond"), "--character", Path.Combine(mods, "mod.limbs.json"), "--agents", "1", "--seconds", "0.5",
                 "--max-nodes", "20", "--threads", "1", "--out", output], stdout, stderr);
            string[] written = [.. Directory.EnumerateFiles(root, "*", SearchOption.AllDirectories).Select(f => Path.GetRelativePath(root, f)).Order()];
            Assert.Multiple(() =>
            {
                Assert.That(code, Is.Zero, stderr.ToString());
                Assert.That(written, Is.EqualTo(new[]
                {
                    Path.Combine("a", "b", "mods", "mod.glb"),
                    Path.Combine("a", "b", "mods", "mod.limbs.json"),
                    Path.Combine("a", "b", "mods", "out", "pond-escape_evil-playtest.json"),
                    Path.Combine("a", "b", "mods", "out", "pond-escape_evil-playtest.png"),
                    Path.Combine("a", "b", "mods", "out", "pond-escape_evil-playtest.svg"),
                }));
                Assert.That(Directory.Exists(Path.Combine(root, "escape")) || Directory.Exists(Path.Combine(root, "a", "escape")), Is.False, "no folder made outside --out");
            });
        }
        finally
        {
            Directory.Delete(root, recursive: true);
        }
    }

    [Test]
    public void APlaytestThatCannotWriteItsOutputsSaysSoBeforeBakingOrSimulating()
    {
        string root = Path.Combine(Path.GetTempPath(), "ballistic-outcheck-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(root);
        try
        {
            // --out names a file: no folder can be made there.
            string notAFolder = Path.Combine(root, "out");
            File.WriteAllText(notAFolder, "a file, not a folder");
            using var stdout = new StringWriter();
            using var stderr = new StringWriter();
            int code = BallisticCli.Run(
                ["playtest", "--level", RepositoryFiles.Level("pond"), "--character", "frog", "--agents", "1", "--seconds", "0.5",
                 "--max-nodes", "20", "--threads", "1", "--out", notAFolder], stdout, stderr);
            Assert.Multiple(() =>
            {
                Assert.That(code, Is.EqualTo(ExitCode.Output), stderr.ToString());
                Assert.That(stderr.ToString(), Does.Contain("pond-frog-playtest.json"));
                Assert.That(stderr.ToString().TrimEnd().Split('\n'), Has.Length.EqualTo(1), "one line");
                Assert.That(stdout.ToString(), Does.Not.Contain("roadmap:"), "refused before the bake");
                Assert.That(File.ReadAllText(notAFolder), Is.EqualTo("a file, not a folder"));
            });
        }
        finally
        {
            Directory.Delete(root, recursive: true);
        }
    }
}
