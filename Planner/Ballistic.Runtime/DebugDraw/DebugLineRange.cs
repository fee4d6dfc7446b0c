namespace Ballistic.Runtime.DebugDraw;

/// <summary>The segments one drawing call added to a <see cref="DebugLines"/>: segments <see cref="First"/> to <see cref="First"/> + <see cref="Count"/> − 1.</summary>
/// <param name="First">Index of the first segment added.</param>
/// <param name="Count">Number of segments added.</param>
public readonly record struct DebugLineRange(int First, int Count);
