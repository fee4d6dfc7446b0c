namespace Ballistic.Runtime.Core;

/// <summary>The outcome of a call on a <see cref="JumpWorld"/>: a status and, unless it is <see cref="RuntimeStatus.Ok"/>, one sentence saying why.</summary>
/// <param name="Status">What happened.</param>
/// <param name="Reason">Why the call failed, or a note on what it did; <c>null</c> when there is nothing to say.</param>
public readonly record struct RuntimeResult(RuntimeStatus Status, string? Reason)
{
    /// <summary>Why the call failed, or a note on what it did; <c>null</c> when there is nothing to say. One line: control characters in it (from a name in a file) are escaped.</summary>
    public string? Reason { get; init; } = Reason is null ? null : OneLine.Of(Reason);

    /// <summary>The plain success.</summary>
    public static RuntimeResult Success { get; } = new(RuntimeStatus.Ok, null);

    /// <summary>True when the status is <see cref="RuntimeStatus.Ok"/>.</summary>
    public bool Ok => Status == RuntimeStatus.Ok;

    /// <inheritdoc />
    public override string ToString() => Reason is null ? Status.ToString() : $"{Status}: {Reason}";
}
