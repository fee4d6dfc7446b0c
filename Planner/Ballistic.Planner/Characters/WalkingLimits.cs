using System.Numerics;

namespace Ballistic.Planner.Characters;

/// <summary>
/// How a character walks: its walking speed, the steepest ground it walks on and the highest step it takes. A
/// character with a <see cref="Speed"/> of zero never walks (it only jumps, as in the paper). Ground is walked on when
/// it is no steeper than <see cref="MaxSlopeDegrees"/>, or when it is walked straight up or down: no steeper than
/// <see cref="MaxSlopeAlongDegrees"/>, falling to the side (across the walk) by at most <see cref="MaxSlopeDegrees"/>
/// (<see cref="IsWalkable"/>). Feet follow a slope ahead further than one to the side: an ankle bends more than it rolls.
/// </summary>
/// <param name="Speed">Walking speed of the trunk along the ground, m/s; 0: the character does not walk.</param>
/// <param name="MaxSlopeDegrees">Steepest ground walked on in any direction, degrees from horizontal (0 to 80).</param>
/// <param name="StepHeight">Highest rise or drop of the ground taken in one step, metres.</param>
public sealed record WalkingLimits(float Speed, float MaxSlopeDegrees, float StepHeight)
{
    private readonly float? _maxSlopeAlong;

    /// <summary>The walking speed as a share of √(g·leg length) squared (a Froude number of 0.25: a relaxed walk).</summary>
    public const float Froude = 0.25f;

    /// <summary>The step height as a share of the leg length.</summary>
    public const float StepShare = 0.25f;

    /// <summary>The default steepest slope, degrees.</summary>
    public const float DefaultMaxSlopeDegrees = 35f;

    /// <summary>
    /// The default average rate at which the trunk turns in place at either end of a walk, radians per second (86°/s):
    /// a walker's, whose feet stand under its trunk.
    /// </summary>
    public const float DefaultTurnRate = 1.5f;

    /// <summary>A character that never walks.</summary>
    public static WalkingLimits None { get; } = new(0f, DefaultMaxSlopeDegrees, 0f);

    /// <summary>True when the character walks (<see cref="Speed"/> &gt; 0).</summary>
    public bool CanWalk => Speed > 0f;

    /// <summary>
    /// Steepest ground walked straight up or down, degrees from horizontal (<see cref="MaxSlopeDegrees"/> to 80): its
    /// slope across the walk (the part falling to the character's side) stays within <see cref="MaxSlopeDegrees"/>.
    /// Unless set, <see cref="MaxSlopeDegrees"/>: the same limit whichever way the ground falls.
    /// </summary>
    public float MaxSlopeAlongDegrees
    {
        get => _maxSlopeAlong ?? MaxSlopeDegrees;
        init => _maxSlopeAlong = value;
    }

    /// <summary>
    /// True when ground of unit normal <paramref name="normal"/> (world, Y up; either side) can be walked on heading
    /// <paramref name="heading"/> (world; only its horizontal part matters): its slope is within
    /// <see cref="MaxSlopeAlongDegrees"/> and its slope across the heading within <see cref="MaxSlopeDegrees"/>. With
    /// no horizontal heading, only <see cref="MaxSlopeDegrees"/> applies.
    /// </summary>
    public bool IsWalkable(Vector3 normal, Vector3 heading) => new GroundSlopeTest(this).Accepts(normal, heading);

    /// <summary>
    /// Average rate at which the trunk turns in place at either end of a walk, radians per second
    /// (<see cref="DefaultTurnRate"/> unless set): slower for a rig whose feet stand far ahead of or behind its trunk,
    /// which a turn carries sideways under it.
    /// </summary>
    public float TurnRate { get; init; } = DefaultTurnRate;

    /// <summary>
    /// Half the distance (metres, along the trunk) between the character's foremost and hindmost feet when its walking
    /// trunk pitches with the ground, or 0 (the default) for a trunk that walks level: a quadruped's or a spider's
    /// trunk leans up a ramp or a flight of stairs as its front feet climb ahead of its hind ones, at the ground's
    /// grade between the points this far ahead of and behind the walk's ground point (<see cref="Roadmaps.Walk.PitchSpan"/>);
    /// a biped, whose feet stand side by side, stays upright.
    /// </summary>
    public float PitchSpan { get; init; }

    /// <summary>
    /// Half the distance (metres, across the trunk) between the character's leftmost and rightmost feet when its
    /// walking trunk rolls with the ground, or 0 (the default) for a trunk that walks level across: a spider or an
    /// ant, whose legs sprawl out to its sides, keeps its body parallel to a dune's side, its uphill feet no higher
    /// under it and its downhill feet no lower than on the level, at the ground's rise between the points this far
    /// left and right of the walk's ground point (<see cref="Roadmaps.Walk.CrossGradeAt(float)"/>); a mammal, whose legs stand
    /// under its hips, keeps its trunk level across and stretches its downhill legs.
    /// </summary>
    public float RollSpan { get; init; }

    /// <summary>Tangent of <see cref="MaxSlopeAlongDegrees"/>: the most the ground rises or drops per metre walked.</summary>
    public float MaxGrade => MathF.Tan(MaxSlopeAlongDegrees * MathF.PI / 180f);

    /// <summary>
    /// Walking derived from a leg: speed √(<see cref="Froude"/>·g·<paramref name="legLength"/>) (about 1.5 m/s for a
    /// 0.95 m human leg), step height <see cref="StepShare"/> of the leg, slope <see cref="DefaultMaxSlopeDegrees"/>.
    /// </summary>
    /// <param name="legLength">Height of the hip above the sole in stance, metres.</param>
    /// <param name="gravity">Magnitude of gravity, m/s².</param>
    public static WalkingLimits FromLeg(float legLength, float gravity = 9.81f) =>
        legLength > 0f && float.IsFinite(legLength)
            ? new WalkingLimits(MathF.Sqrt(Froude * gravity * legLength), DefaultMaxSlopeDegrees, StepShare * legLength)
            : None;

    /// <summary>The problem with these values, or <c>null</c> when they are usable.</summary>
    public string? Problem() =>
        !(Speed >= 0f) || !float.IsFinite(Speed) || Speed > 100f ? $"the walking speed must lie between 0 and 100 m/s, not {Speed}"
        : !(MaxSlopeDegrees >= 0f) || MaxSlopeDegrees > 80f ? $"the steepest walkable slope must lie between 0 and 80 degrees, not {MaxSlopeDegrees}"
        : !(MaxSlopeAlongDegrees >= MaxSlopeDegrees) || MaxSlopeAlongDegrees > 80f ? $"the steepest slope walked up or down must lie between the steepest walkable slope ({MaxSlopeDegrees}) and 80 degrees, not {MaxSlopeAlongDegrees}"
        : !(StepHeight >= 0f) || !float.IsFinite(StepHeight) || StepHeight > 100f ? $"the step height must lie between 0 and 100 m, not {StepHeight}"
        : CanWalk && StepHeight <= 0f ? "a walking character needs a positive step height"
        : !(TurnRate > 0f) || TurnRate > 100f ? $"the turn rate must lie between 0 and 100 radians per second, not {TurnRate}"
        : !(PitchSpan >= 0f) || !float.IsFinite(PitchSpan) || PitchSpan > 100f ? $"the span over which the trunk pitches with the ground must lie between 0 and 100 m, not {PitchSpan}"
        : !(RollSpan >= 0f) || !float.IsFinite(RollSpan) || RollSpan > 100f ? $"the span over which the trunk rolls with the ground must lie between 0 and 100 m, not {RollSpan}"
        : null;
}
