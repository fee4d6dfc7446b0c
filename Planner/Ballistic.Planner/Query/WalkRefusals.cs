using System.Globalization;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Query;

/// <summary>
/// Why a path jumps where a user might expect a walk: for each jump of the path, the walk from its takeoff stance to
/// its landing stance steered as the bake and the query steer walks (straight, seen from above, over the ground
/// found), and what stopped it, in words with the character's own limits; or, where such a walk exists, that the
/// search found the jump cheaper (its cost: flight time plus the query's jump effort) or the body could not perform
/// the walk (the moves set aside say so).
/// </summary>
internal static class WalkRefusals
{
    /// <summary>For each jump of <paramref name="moves"/> (its index in the path): why no walk stands in for it, and the steering's verdict.</summary>
    public static IReadOnlyList<(int Move, WalkFailure Failure, string Reason)> Of(PlanningScene scene, IReadOnlyList<Move> moves)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(moves);
        var refusals = new List<(int, WalkFailure, string)>();
        for (int m = 0; m < moves.Count; m++)
        {
            if (moves[m] is not Jump jump)
            {
                continue;
            }

            WalkResult walk = scene.Walking.SteerRemembered(jump.From, jump.To);
            refusals.Add((m, walk.Failure, walk.Walk is Walk possible
                ? Text($"a walk there is possible ({possible.Length:0.0} m, {possible.Duration:0.0} s{Costly(scene, possible)}): the search found the jump cheaper, or the body could not perform the walk (see the moves set aside)")
                : Reason(walk.Failure, scene.Character.Walking)));
        }

        return refusals;
    }

    /// <summary>
    /// ", over MATERIAL (travel cost c, enter cost s)" for each costly material (<see cref="Levels.LevelMaterial.TravelCost"/>,
    /// <see cref="Levels.LevelMaterial.EnterCost"/>) the ground under <paramref name="walk"/> is made of; empty on a level without such costs.
    /// </summary>
    private static string Costly(PlanningScene scene, Walk walk) =>
        SurfaceCosts.Of(scene) is { } costs
            ? string.Concat(costs.Costly(walk.Path).Select(m => Text($", over '{IO.MessageText.Printable(m.Name)}' (travel cost {m.TravelCost:0.##}, enter cost {m.EnterCost:0.##} s)")))
            : "";

    /// <summary>Why the walking steering refused a walk, in words with <paramref name="limits"/>' numbers.</summary>
    public static string Reason(WalkFailure failure, WalkingLimits limits)
    {
        ArgumentNullException.ThrowIfNull(limits);
        return failure switch
        {
            WalkFailure.NotWalking => "the character does not walk: it has fewer than two feet, needs more limbs down than its feet (requiredContacts), or its walking speed is 0",
            WalkFailure.TooFar => "the stances lie farther apart than a walk may go",
            WalkFailure.Gap => Text($"the ground is missing on the way, or drops by more than the step height ({limits.StepHeight:0.00} m)"),
            WalkFailure.StepTooHigh => Text($"the ground rises by more than the step height ({limits.StepHeight:0.00} m) on the way, or something stands between the ground and the trunk"),
            WalkFailure.TooSteep => Text($"the ground on the way is steeper than the character walks ({limits.MaxSlopeAlongDegrees:0}° up or down, {limits.MaxSlopeDegrees:0}° across)"),
            WalkFailure.TrunkCollides => "the trunk at walking height touches the level on the way",
            WalkFailure.None => "a walk there is possible",
            _ => throw new ArgumentOutOfRangeException(nameof(failure), failure, "not a walk failure"),
        };
    }

    /// <summary>Failure names as the plan report writes them.</summary>
    public static string Name(WalkFailure failure) => failure switch
    {
        WalkFailure.None => "possible",
        WalkFailure.NotWalking => "not_walking",
        WalkFailure.TooFar => "too_far",
        WalkFailure.Gap => "gap",
        WalkFailure.StepTooHigh => "step_too_high",
        WalkFailure.TooSteep => "too_steep",
        WalkFailure.TrunkCollides => "trunk_collides",
        _ => throw new ArgumentOutOfRangeException(nameof(failure), failure, "not a walk failure"),
    };

    private static string Text(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
