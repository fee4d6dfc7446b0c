// Fixtures run two at a time (the machines have two cores; many tests use one thread most of the time). Tests within a
// fixture run in order. Fixtures that measure wall-clock time or send signals to processes are [NonParallelizable].
[assembly: Parallelizable(ParallelScope.Fixtures)]
[assembly: LevelOfParallelism(2)]
