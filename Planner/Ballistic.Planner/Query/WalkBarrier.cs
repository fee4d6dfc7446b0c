using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Roadmaps;

namespace Ballistic.Planner.Query;

/// <summary>
/// Ground a request no longer walks over (<see cref="QuerySettings.NoWalkSpots"/>): a walk whose ground path passes,
/// seen from above, within <see cref="Radius"/> of one of the spots is not taken, whether the roadmap holds it or the
/// path's post-processing would make it (shortcut, cut from a jump, hop, turn); the request jumps there instead. The
/// radius is the body's: a walk the body failed on (a spider's legs, 1.3 m across, meeting a 0.9 m door's jambs)
/// fails as well a little to the side of where it failed.
/// </summary>
internal sealed class WalkBarrier
{
    private readonly Vector3[] _spots;

    private WalkBarrier(Vector3[] spots, float radius)
    {
        _spots = spots;
        Radius = radius;
    }

    /// <summary>How near (metres, seen from above) a walk's ground path may come to a spot.</summary>
    public float Radius { get; }

    /// <summary>The barrier of <paramref name="spots"/> for <paramref name="character"/> (<see cref="RadiusOf"/>), or <c>null</c> when there are none.</summary>
    public static WalkBarrier? Of(IReadOnlyList<Vector3>? spots, ReducedCharacter character) =>
        spots is { Count: > 0 } ? new WalkBarrier([.. spots], RadiusOf(character)) : null;

    /// <summary>
    /// The body's half-width about its trunk seen from above as it walks (metres): the farthest any foot's contact is
    /// held from the trunk's centre, horizontally, in its contact pose (<see cref="Limb.Home"/>, else the middle of its
    /// workspace; every limb's for a character without feet), at least <see cref="JumpTightener.SpotRadius"/>.
    /// </summary>
    public static float RadiusOf(ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(character);
        float radius = JumpTightener.SpotRadius;
        bool feet = character.Limbs.Any(l => l.Kind == LimbKind.Foot);
        foreach (Limb limb in character.Limbs.Where(l => !feet || l.Kind == LimbKind.Foot))
        {
            Vector3 home = limb.Home ?? limb.WorkspaceCenter;
            radius = MathF.Max(radius, new Vector2(home.X, home.Z).Length());
        }

        return radius;
    }

    /// <summary>True when <paramref name="walk"/>'s ground path passes within <see cref="Radius"/> of a spot.</summary>
    public bool Bars(Walk walk)
    {
        ArgumentNullException.ThrowIfNull(walk);
        IReadOnlyList<Vector3> path = walk.Path;
        if (path.Count == 1)
        {
            return Bars(path[0], path[0]);
        }

        for (int i = 0; i + 1 < path.Count; i++)
        {
            if (Bars(path[i], path[i + 1]))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>True when the segment from <paramref name="a"/> to <paramref name="b"/> passes within <see cref="Radius"/> of a spot, seen from above.</summary>
    public bool Bars(Vector3 a, Vector3 b)
    {
        var ab = new Vector2(b.X - a.X, b.Z - a.Z);
        float flat = ab.LengthSquared();
        foreach (Vector3 spot in _spots)
        {
            var ap = new Vector2(spot.X - a.X, spot.Z - a.Z);
            float u = flat > 1e-12f ? Math.Clamp(Vector2.Dot(ap, ab) / flat, 0f, 1f) : 0f;
            if ((ap - (u * ab)).Length() <= Radius)
            {
                return true;
            }
        }

        return false;
    }
}
