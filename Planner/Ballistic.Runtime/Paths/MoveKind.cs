namespace Ballistic.Runtime.Paths;

/// <summary>How a move of a path is performed. Today every move is a jump; walking joins later without changing the systems' shape.</summary>
public enum MoveKind
{
    /// <summary>A ballistic jump: the trunk centre flies on a parabola from one stance to the next.</summary>
    Jump,
}
