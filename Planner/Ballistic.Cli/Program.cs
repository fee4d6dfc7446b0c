using System.Runtime.InteropServices;

namespace Ballistic.Cli;

/// <summary>Process entry point of the <c>ballistic</c> tool.</summary>
public static class Program
{
    /// <summary>
    /// Runs the tool on the process's console; the return value is the exit code (<see cref="ExitCode"/>). Ctrl-C and
    /// SIGTERM cancel the running job cleanly (exit code 130, previous output files intact).
    /// </summary>
    public static int Main(string[] args)
    {
        using var cancel = new CancellationTokenSource();
        void OnCancelKey(object? sender, ConsoleCancelEventArgs e)
        {
            e.Cancel = true;
            cancel.Cancel();
        }

        Console.CancelKeyPress += OnCancelKey;
        using PosixSignalRegistration terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM, context =>
        {
            context.Cancel = true;
            cancel.Cancel();
        });
        try
        {
            return BallisticCli.Run(args, Console.Out, Console.Error, cancel.Token);
        }
        finally
        {
            Console.CancelKeyPress -= OnCancelKey;
        }
    }
}
