using Ballistic.Runtime.Core;

namespace Ballistic.Runtime.Kinds;

/// <summary>The outcome of <see cref="JumpWorld.AddKind"/>: the kind's handle, or why it was refused.</summary>
/// <param name="Result">Status and reason.</param>
/// <param name="Kind">The new kind; the default handle when the status is not <see cref="RuntimeStatus.Ok"/>.</param>
public readonly record struct AddKindResult(RuntimeResult Result, KindHandle Kind)
{
    /// <summary>True when the kind was added.</summary>
    public bool Ok => Result.Ok;
}
