namespace Ballistic.Planner.Planning;

/// <summary>Which moves a path may use.</summary>
public enum Locomotion
{
    /// <summary>Walks where the ground allows and jumps where it must (the default): walks cost their time, jumps their flight time plus <see cref="Query.QuerySettings.JumpEffort"/>.</summary>
    WalkAndJump,

    /// <summary>Jumps only, the paper's planner: paths of least total flight time.</summary>
    Jump,
}
