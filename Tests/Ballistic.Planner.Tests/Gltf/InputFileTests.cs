using System.Diagnostics;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Tests.Gltf;

/// <summary>
/// How input files are told apart before they are opened: with <c>statx</c> on Linux, and where it is missing by the
/// size an entry reports (pipes and devices report none, so they are refused unopened there too).
/// </summary>
public sealed class InputFileTests
{
    private string _folder = "";

    [SetUp]
    public void MakeFolder()
    {
        _folder = Path.Combine(Path.GetTempPath(), $"ballistic-input-{Guid.NewGuid():N}");
        Directory.CreateDirectory(_folder);
    }

    [TearDown]
    public void RemoveFolder() => Directory.Delete(_folder, recursive: true);

    [Test]
    public void PipesDevicesFoldersAndLinksAreToldApart()
    {
        Assume.That(OperatingSystem.IsLinux(), "named pipes and /dev/zero are made the Linux way");
        string pipe = Path.Combine(_folder, "pipe");
        using (var mkfifo = Process.Start(new ProcessStartInfo("mkfifo", [pipe]) { UseShellExecute = false })!)
        {
            mkfifo.WaitForExit();
        }

        string regular = Path.Combine(_folder, "regular.bin");
        File.WriteAllBytes(regular, [1, 2, 3]);
        string empty = Path.Combine(_folder, "empty.bin");
        File.WriteAllBytes(empty, []);
        string zero = Path.Combine(_folder, "zero");
        File.CreateSymbolicLink(zero, "/dev/zero");
        string link = Path.Combine(_folder, "link.bin");
        File.CreateSymbolicLink(link, regular);
        string dangling = Path.Combine(_folder, "dangling.bin");
        File.CreateSymbolicLink(dangling, Path.Combine(_folder, "nothing.bin"));
        Assert.Multiple(() =>
        {
            Assert.That(InputFile.StatxProblem(pipe), Is.EqualTo("is a named pipe, not a regular file"));
            Assert.That(InputFile.StatxProblem(zero), Is.EqualTo("is a character device, not a regular file"));
            Assert.That(InputFile.StatxProblem(_folder), Is.EqualTo("is a folder, not a file"));
            Assert.That(InputFile.StatxProblem(regular), Is.Null);
            Assert.That(InputFile.StatxProblem(empty), Is.Null, "an empty regular file is read (and found not to be glTF)");
            Assert.That(InputFile.StatxProblem(link), Is.Null);
            Assert.That(InputFile.StatxProblem(dangling), Is.EqualTo("cannot be read: it does not exist"));

            Assert.That(InputFile.PortableProblem(pipe), Does.StartWith("is empty, or not a regular file"));
            Assert.That(InputFile.PortableProblem(zero), Does.StartWith("is empty, or not a regular file"));
            Assert.That(InputFile.PortableProblem(_folder), Is.EqualTo("is a folder, not a file"));
            Assert.That(InputFile.PortableProblem(regular), Is.Null);
            Assert.That(InputFile.PortableProblem(link), Is.Null);
            Assert.That(InputFile.PortableProblem(dangling), Is.EqualTo("cannot be read: it does not exist"));
        });
    }

    [Test]
    public void AFileIsReadWholeUpToTheLimit()
    {
        string file = Path.Combine(_folder, "data.bin");
        byte[] data = [.. Enumerable.Range(0, 1000).Select(i => (byte)i)];
        File.WriteAllBytes(file, data);
        static Exception Fail(string problem, Exception? inner) => new InvalidDataException(problem, inner);
        Assert.Multiple(() =>
        {
            Assert.That(InputFile.Read(file, 1000, "the test's limit", Fail), Is.EqualTo(data));
            Assert.That(() => InputFile.Read(file, 999, "the test's limit", Fail), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("is 1000 bytes, more than the 999 bytes allowed (the test's limit)"));
            Assert.That(() => InputFile.Read(Path.Combine(_folder, "none.bin"), 1000, "the test's limit", Fail), Throws.TypeOf<InvalidDataException>().With.Message.EqualTo("cannot be read: it does not exist"));
        });
    }
}
