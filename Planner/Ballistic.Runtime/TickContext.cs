namespace Ballistic.Runtime;

/// <summary>The tick a <see cref="JumpWorld"/> is stepping, handed to each <see cref="IJumpSystem"/>.</summary>
/// <param name="Tick">The tick's number (<see cref="JumpWorld.Tick"/>, from 1).</param>
/// <param name="Time">World time at the end of the tick, seconds (<see cref="JumpWorld.Time"/>).</param>
/// <param name="DeltaSeconds">The tick's length, seconds (<see cref="Core.WorldSettings.TickSeconds"/>).</param>
public readonly record struct TickContext(long Tick, double Time, double DeltaSeconds);
