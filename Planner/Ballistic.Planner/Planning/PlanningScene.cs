using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Surfaces;
using Ballistic.Planner.Walking;

namespace Ballistic.Planner.Planning;

/// <summary>
/// Everything the planner derives from one level and one character, built once and shared by bakes and queries:
/// the collision hierarchy, contact surfaces, contact estimator, sampler and steering method. Validity is decided by
/// the estimator's built-in pose checks and optional <see cref="IPoseValidator"/>, and by the steering method's
/// <see cref="IArcValidator"/> (the trunk sweep, then an optional extra one). Thread-safe.
/// </summary>
public sealed class PlanningScene
{
    private PlanningScene(Level level, ReducedCharacter character, TriangleBvh bvh, SurfaceSet surfaces, ContactEstimator estimator, TrunkSampler sampler, ParabolaSteering steering, WalkSteering walking)
    {
        Level = level;
        Character = character;
        Bvh = bvh;
        Surfaces = surfaces;
        Estimator = estimator;
        Sampler = sampler;
        Steering = steering;
        Walking = walking;
    }

    /// <summary>The level.</summary>
    public Level Level { get; }

    /// <summary>The reduced character.</summary>
    public ReducedCharacter Character { get; }

    /// <summary>Collision hierarchy over the level's triangles.</summary>
    internal TriangleBvh Bvh { get; }

    /// <summary>Contact surfaces of the level.</summary>
    internal SurfaceSet Surfaces { get; }

    /// <summary>Contact and cone estimation.</summary>
    internal ContactEstimator Estimator { get; }

    /// <summary>Root pose sampler.</summary>
    internal TrunkSampler Sampler { get; }

    /// <summary>The parabola steering method with the character's limits.</summary>
    internal ParabolaSteering Steering { get; }

    /// <summary>The walking steering method with the character's walking limits (it finds no walk for a character that does not walk).</summary>
    internal WalkSteering Walking { get; }

    /// <summary>Placements, arcs and walks the scene keeps for good (<see cref="Query.PathQuery.Prepare"/>), in all.</summary>
    internal int KeptCount => Sampler.KeptCount + Steering.KeptCount + Walking.KeptCount;

    /// <summary>Gives back the spare room of what the scene keeps for good, once a preparation is done.</summary>
    internal void TrimKept()
    {
        Sampler.TrimKept();
        Steering.TrimKept();
        Walking.TrimKept();
    }

    /// <summary>Builds the scene.</summary>
    /// <param name="level">The level.</param>
    /// <param name="character">The character.</param>
    /// <param name="maxApexAboveLevel">
    /// How far above the level's highest point (metres) the trunk may rise at a jump's apex; <c>null</c> for no bound.
    /// </param>
    /// <param name="poseValidator">
    /// An extra test every node, start and goal pose must pass after the built-in ones; <c>null</c> for none. A roadmap
    /// baked with one is only valid with the same test: its file does not record it.
    /// </param>
    /// <param name="arcValidator">
    /// An extra test every jump arc must pass after the trunk sweep; <c>null</c> for none. Recorded no more than
    /// <paramref name="poseValidator"/>.
    /// </param>
    public static PlanningScene Create(
        Level level,
        ReducedCharacter character,
        float? maxApexAboveLevel = 4f,
        IPoseValidator? poseValidator = null,
        IArcValidator? arcValidator = null)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        if (TooBigFor(level, character) is { } problem)
        {
            throw new CharacterException(problem);
        }

        TriangleBvh bvh = level.Bvh;
        SurfaceSet surfaceSet = SurfaceSet.Build(level);
        var estimator = new ContactEstimator(level, bvh, surfaceSet, character, poseValidator);
        var trunkSampler = new TrunkSampler(level, bvh, surfaceSet, character, estimator);
        SteeringLimits limits = maxApexAboveLevel is float margin
            ? character.Limits with { MaxApexHeight = level.Bounds.Max.Y + margin }
            : character.Limits;
        var sweep = new TrunkSweepValidator(bvh, character.TrunkHalfExtents, limits.CollisionTolerance);
        var steering = new ParabolaSteering(limits, character.TrunkHalfExtents, arcValidator is null ? sweep : new BothArcValidators(sweep, arcValidator));
        return new PlanningScene(level, character, bvh, surfaceSet, estimator, trunkSampler, steering, new WalkSteering(bvh, character, limits.CollisionTolerance));
    }

    /// <summary>
    /// Why <paramref name="character"/> can stand nowhere on <paramref name="level"/> whatever the sampling, or
    /// <c>null</c>: its trunk is larger in every direction than the whole level (a rig scaled ×10,000, bone radii of
    /// hundreds of metres). Without this a bake of such a character spends its time pushing a trunk the size of the
    /// level out of every triangle, finding nothing, for many minutes.
    /// </summary>
    internal static string? TooBigFor(Level level, ReducedCharacter character)
    {
        if (level.Triangles.Count == 0)
        {
            return null;
        }

        Vector3 size = level.Bounds.Max - level.Bounds.Min;
        Vector3 trunk = 2f * character.TrunkHalfExtents;
        float levelExtent = MathF.Max(size.X, MathF.Max(size.Y, size.Z));
        float trunkLeast = MathF.Min(trunk.X, MathF.Min(trunk.Y, trunk.Z));
        return trunkLeast > levelExtent
            ? string.Create(CultureInfo.InvariantCulture,
                $"Character '{IO.MessageText.Printable(character.Name)}' can stand nowhere on {IO.MessageText.Printable(level.Source)}: its trunk ({trunk.X:0.###} × {trunk.Y:0.###} × {trunk.Z:0.###} m) is larger than the whole level ({size.X:0.###} × {size.Y:0.###} × {size.Z:0.###} m); check the rig's scale and its bone radii.")
            : null;
    }
}
