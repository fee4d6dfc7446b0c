namespace Ballistic.Runtime.Skeletons;

/// <summary>The outcome of <see cref="SkeletonBinding.Create"/>: a binding, or one line saying why there is none.</summary>
/// <param name="Binding">The binding, or <c>null</c> on failure.</param>
/// <param name="Error">One sentence naming the missing bone or the problem; <c>null</c> on success.</param>
/// <param name="MissingRequired">Names of the runtime joints the animation needs (the root and every limb chain) that no bone matched; empty on success.</param>
public sealed record SkeletonBindingResult(SkeletonBinding? Binding, string? Error, IReadOnlyList<string> MissingRequired)
{
    /// <summary>True when a binding was made.</summary>
    public bool Ok => Binding is not null;

    /// <inheritdoc />
    public override string ToString() => Ok ? "bound" : $"not bound: {Error}";
}
