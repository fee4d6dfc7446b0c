namespace Ballistic.Runtime.Kinds;

/// <summary>
/// Names one character kind of a <see cref="JumpWorld"/> (<see cref="JumpWorld.AddKind"/>,
/// <see cref="JumpWorld.CreateKind"/>), with or without a roadmap, until <see cref="JumpWorld.RemoveKind"/>; a removed
/// kind's handle stays invalid when its index is reused (the generation differs). The default handle names none.
/// </summary>
/// <param name="Index">Index of the kind in the world, from zero.</param>
/// <param name="Generation">How many kinds used the index before, plus one; zero for the default handle.</param>
public readonly record struct KindHandle(int Index, int Generation)
{
    /// <summary>True for a handle the world returned (not necessarily still valid).</summary>
    public bool Assigned => Generation > 0;

    /// <inheritdoc />
    public override string ToString() => Assigned ? $"kind {Index}#{Generation}" : "no kind";
}
