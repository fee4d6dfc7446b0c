namespace Ballistic.Cli;

/// <summary>Process entry point of the <c>ballistic</c> tool.</summary>
public static class Program
{
    /// <summary>Runs the tool on the process's console; the return value is the exit code (0 only on success).</summary>
    public static int Main(string[] args) => BallisticCli.Run(args, Console.Out, Console.Error);
}
