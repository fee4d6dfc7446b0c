using BenchmarkDotNet.Running;

namespace Ballistic.Benchmarks;

/// <summary>Entry point: every benchmark class of this assembly, selectable with BenchmarkDotNet's --filter.</summary>
public static class Program
{
    /// <summary>Runs the benchmarks chosen on the command line.</summary>
    public static void Main(string[] args) => BenchmarkSwitcher.FromAssembly(typeof(Program).Assembly).Run(args);
}
