namespace Ballistic.Runtime.Core;

/// <summary>The outcome of a call on a <see cref="JumpWorld"/>: calls never throw for bad handles or bad input.</summary>
public enum RuntimeStatus
{
    /// <summary>Done.</summary>
    Ok,

    /// <summary>The agent handle names no agent of this world (never assigned, or removed).</summary>
    UnknownAgent,

    /// <summary>The kind handle names no character kind of this world.</summary>
    UnknownKind,

    /// <summary>An argument is not usable (a non-finite coordinate, a null).</summary>
    InvalidArgument,

    /// <summary>No stance for the agent's character within tolerance of the point asked for.</summary>
    InvalidPosition,

    /// <summary>The roadmap was baked for another character, or the scene is of another level than the world's.</summary>
    Mismatch,

    /// <summary>The world was disposed: the call did nothing.</summary>
    Disposed,

    /// <summary>
    /// The world is stepping or changing: the call is refused from inside a system, or from another thread while the
    /// world's own thread steps or changes it (record it in <see cref="JumpWorld.Commands"/> instead).
    /// </summary>
    Busy,
}
