namespace Ballistic.Runtime.Agents;

/// <summary>Where one agent's pose lies in the world's pose pools: its joint angles' and joint rotations' offsets and lengths.</summary>
internal readonly record struct PoseSlice(int Angles, int AngleCount, int Rotations, int RotationCount);
