namespace Ballistic.Runtime.Kinds;

/// <summary>Names one character kind of a <see cref="JumpWorld"/> (returned by <see cref="JumpWorld.AddKind"/>); the default handle names none.</summary>
/// <param name="Index">Index of the kind in the world, from zero.</param>
/// <param name="Assigned">True for a handle returned by <see cref="JumpWorld.AddKind"/>.</param>
public readonly record struct KindHandle(int Index, bool Assigned)
{
    /// <inheritdoc />
    public override string ToString() => Assigned ? $"kind {Index}" : "no kind";
}
