using System.Diagnostics;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Tests.IO;

/// <summary>Writes replace regular files only, follow links, and never leave temporary files behind.</summary>
public sealed class OutputFileTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-out-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    private string[] Leftovers() => Directory.GetFiles(_folder, "*.tmp", SearchOption.AllDirectories);

    [Test]
    public void AWriteReplacesTheFileWholeAndCreatesItsFolder()
    {
        string path = Path.Combine(_folder, "deep", "er", "report.json");
        OutputFile.Write(path, "first"u8);
        OutputFile.Write(path, "second"u8);
        Assert.That(File.ReadAllText(path), Is.EqualTo("second"));
        Assert.That(Leftovers(), Is.Empty);
    }

    [Test]
    public void DevicesPipesAndFoldersAreNeverReplaced()
    {
        Assert.That(() => OutputFile.Write(_folder, "x"u8), Throws.TypeOf<OutputFileException>().With.Message.Contains("folder"));
        if (!OperatingSystem.IsLinux())
        {
            return;
        }

        foreach (string device in new[] { "/dev/null", "/dev/full" })
        {
            Assert.That(() => OutputFile.Write(device, "x"u8), Throws.TypeOf<OutputFileException>().With.Message.EqualTo($"Refusing to replace {device}: it is not a regular file (a device, pipe or socket)."));
            Assert.That(new FileInfo(device).Exists, Is.True);
        }

        // /dev/full is still a device: writing to it still fails as a device does (it was not turned into a file).
        Assert.That(() => File.WriteAllText("/dev/full", "x"), Throws.InstanceOf<IOException>());

        string fifo = Path.Combine(_folder, "pipe");
        using (var mkfifo = Process.Start(new ProcessStartInfo("mkfifo", fifo) { UseShellExecute = false })!)
        {
            mkfifo.WaitForExit();
        }

        Assert.That(() => OutputFile.Write(fifo, "x"u8), Throws.TypeOf<OutputFileException>().With.Message.Contains("not a regular file"));
        Assert.That(Leftovers(), Is.Empty);
    }

    [Test]
    public void ASymbolicLinkIsFollowedAndStaysALink()
    {
        string target = Path.Combine(_folder, "real.json");
        string link = Path.Combine(_folder, "link.json");
        File.WriteAllText(target, "old");
        File.CreateSymbolicLink(link, target);
        OutputFile.Write(link, "new"u8);
        Assert.Multiple(() =>
        {
            Assert.That(File.ReadAllText(target), Is.EqualTo("new"), "the file the link points to is written");
            Assert.That(new FileInfo(link).LinkTarget, Is.EqualTo(target), "the link is still a link");
            Assert.That(Leftovers(), Is.Empty);
        });

        // A dangling link: the file it names is created.
        string dangling = Path.Combine(_folder, "dangling.json");
        string missing = Path.Combine(_folder, "made.json");
        File.CreateSymbolicLink(dangling, missing);
        OutputFile.Write(dangling, "made"u8);
        Assert.That(File.ReadAllText(missing), Is.EqualTo("made"));
    }

    [Test]
    public void TemporaryFilesOfKilledWritersAreCleanedAndAFailedWriteLeavesTheOldFile()
    {
        string path = Path.Combine(_folder, "roadmap.bin");
        File.WriteAllText(path, "previous");

        // A writer that was killed: its process id no longer exists.
        string stale = Path.Combine(_folder, $".roadmap.bin.{int.MaxValue - 7}.0123456789abcdef0123456789abcdef.tmp");
        File.WriteAllText(stale, "half");
        OutputFile.Write(path, "next"u8);
        Assert.That(File.Exists(stale), Is.False, "a dead writer's temporary file is removed");
        Assert.That(File.ReadAllText(path), Is.EqualTo("next"));

        // A failed write (the folder is read-only for this user unless root: use a file in place of a folder instead).
        string blocked = Path.Combine(_folder, "file-not-folder");
        File.WriteAllText(blocked, "x");
        Assert.That(() => OutputFile.Write(Path.Combine(blocked, "out.json"), "y"u8), Throws.TypeOf<OutputFileException>().With.Message.Contains(Path.Combine(blocked, "out.json")));
        Assert.That(Leftovers(), Is.Empty);
    }

    [Test]
    public void ACheckWritesNothingButSaysWhatCannotBeWritten()
    {
        string path = Path.Combine(_folder, "new", "report.json");
        OutputFile.Check(path);
        Assert.That(Directory.Exists(Path.Combine(_folder, "new")), Is.True, "its folder is made");
        Assert.That(Directory.GetFileSystemEntries(Path.Combine(_folder, "new")), Is.Empty, "and nothing written in it");

        string existing = Path.Combine(_folder, "kept.json");
        File.WriteAllText(existing, "kept");
        OutputFile.Check(existing);
        Assert.That(File.ReadAllText(existing), Is.EqualTo("kept"), "an existing file is not touched");

        string blocked = Path.Combine(_folder, "blocked");
        File.WriteAllText(blocked, "x");
        Assert.That(() => OutputFile.Check(Path.Combine(blocked, "out.json")), Throws.TypeOf<OutputFileException>().With.Message.Contains(Path.Combine(blocked, "out.json")));
        Assert.That(() => OutputFile.Check(_folder), Throws.TypeOf<OutputFileException>().With.Message.Contains("folder"));
        Assert.That(Leftovers(), Is.Empty);
    }
}
