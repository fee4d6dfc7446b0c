using Ballistic.Cli;

namespace Ballistic.Planner.Tests.Cli;

public sealed class BallisticCliTests
{
    [Test]
    public void VersionPrintsTheAssemblyVersionAndSucceeds()
    {
        (int code, string output, _) = Run("--version");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero);
            Assert.That(output.Trim(), Does.StartWith("0.1.0"));
        });
    }

    [Test]
    public void HelpDescribesTheToolAndItsConventions()
    {
        (int code, string output, _) = Run("--help");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Zero);
            Assert.That(output, Does.Contain("ballistic jumps").And.Contain("Y up, metres, seconds"));
        });
    }

    [Test]
    public void AnUnknownCommandFailsAndNamesIt()
    {
        (int code, _, string error) = Run("fly-to-the-moon");
        Assert.Multiple(() =>
        {
            Assert.That(code, Is.Not.Zero);
            Assert.That(error, Does.Contain("fly-to-the-moon"));
        });
    }

    private static (int Code, string Output, string Error) Run(params string[] args)
    {
        using var output = new StringWriter();
        using var error = new StringWriter();
        int code = BallisticCli.Run(args, output, error);
        return (code, output.ToString(), error.ToString());
    }
}
