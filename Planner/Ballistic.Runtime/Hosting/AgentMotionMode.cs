namespace Ballistic.Runtime.Hosting;

/// <summary>Who moves the character of a <see cref="JumpAgentLogic"/>.</summary>
public enum AgentMotionMode
{
    /// <summary>The node moves its parent <c>Node3D</c> each physics tick to <see cref="JumpAgentLogic.BodyPosition"/> and <see cref="JumpAgentLogic.BodyRotation"/>.</summary>
    MoveParent,

    /// <summary>
    /// The node only reports: the user moves their own body (a <c>CharacterBody3D</c>) toward
    /// <see cref="JumpAgentLogic.BodyPosition"/> at <see cref="JumpAgentLogic.BodyVelocity"/>, and tells where it
    /// stands with <see cref="JumpAgentLogic.SyncBodyPosition"/>.
    /// </summary>
    ReportOnly,
}
