using System.CommandLine;
using System.CommandLine.Invocation;

namespace Ballistic.Cli;

/// <summary>Prints <see cref="BallisticCli.Version"/> for <c>--version</c>.</summary>
internal sealed class PrintVersionAction : SynchronousCommandLineAction
{
    /// <inheritdoc />
    public override int Invoke(ParseResult parseResult)
    {
        parseResult.InvocationConfiguration.Output.WriteLine(BallisticCli.Version);
        return 0;
    }
}
