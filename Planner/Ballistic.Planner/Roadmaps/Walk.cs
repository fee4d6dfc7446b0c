using System.Numerics;
using Ballistic.Planner.Geometry;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// One walk of a planned path: the trunk moves at a constant speed along a path on the ground from one stance to
/// the next while the legs step. The ground path runs from the first stance's contact centre to the second's; the
/// trunk keeps its stance offset above the ground (blended from the first stance's to the second's), faces the way it
/// walks, and turns from the first stance's orientation at the start to the second's at the end. Immutable.
/// </summary>
public sealed record Walk : Move
{
    /// <summary>The distance (metres) over which the trunk turns from a stance's orientation to the walking heading, at most.</summary>
    public const float TurnDistance = 0.5f;

    private readonly Vector3[] _path;
    private readonly float[] _distances;

    /// <summary>Creates a walk.</summary>
    /// <param name="from">The stance walked from.</param>
    /// <param name="to">The stance walked to.</param>
    /// <param name="path">Points on the ground, world metres, in order: the first under <paramref name="from"/>'s contacts, the last under <paramref name="to"/>'s (at least two).</param>
    /// <param name="speed">Walking speed along the path, m/s (positive).</param>
    /// <param name="via">
    /// The stances the walk passes through without stopping, in order, when it joins several walks of a search
    /// (their ground points lie on <paramref name="path"/>); <c>null</c> or empty for a walk straight from one stance to the next.
    /// </param>
    /// <exception cref="ArgumentException">Fewer than two points, a point not finite, or a speed not positive.</exception>
    public Walk(RoadmapNode from, RoadmapNode to, IReadOnlyList<Vector3> path, float speed, IReadOnlyList<RoadmapNode>? via = null)
    {
        ArgumentNullException.ThrowIfNull(from);
        ArgumentNullException.ThrowIfNull(to);
        ArgumentNullException.ThrowIfNull(path);
        if (path.Count < 2)
        {
            throw new ArgumentException($"A walk needs at least two path points, not {path.Count}.", nameof(path));
        }

        if (!(speed > 0f) || !float.IsFinite(speed))
        {
            throw new ArgumentException($"The walking speed must be positive, not {speed}.", nameof(speed));
        }

        _path = [.. path];
        _distances = new float[_path.Length];
        for (int i = 0; i < _path.Length; i++)
        {
            Vector3 p = _path[i];
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z))
            {
                throw new ArgumentException($"Walk path point {i} is not finite.", nameof(path));
            }

            _distances[i] = i == 0 ? 0f : _distances[i - 1] + Vector3.Distance(_path[i - 1], p);
        }

        From = from;
        To = to;
        Via = via is null ? [] : [.. via];
        Speed = speed;
        Length = _distances[^1];
        StartOffset = from.Pose.Position - _path[0];
        EndOffset = to.Pose.Position - _path[^1];
    }

    /// <inheritdoc />
    public override RoadmapNode From { get; }

    /// <inheritdoc />
    public override RoadmapNode To { get; }

    /// <summary>The stances passed through without stopping, in order (empty for a walk from one stance straight to the next).</summary>
    public IReadOnlyList<RoadmapNode> Via { get; }

    /// <summary>The node pairs (from id, to id) of the walks this one joins: (From, To) alone, or through each of <see cref="Via"/>.</summary>
    public IEnumerable<(int From, int To)> Segments
    {
        get
        {
            RoadmapNode previous = From;
            foreach (RoadmapNode node in Via)
            {
                yield return (previous.Id, node.Id);
                previous = node;
            }

            yield return (previous.Id, To.Id);
        }
    }

    /// <summary>Points on the ground the walk follows, world metres, in order.</summary>
    public IReadOnlyList<Vector3> Path => _path;

    /// <summary>Walking speed along the path, m/s.</summary>
    public float Speed { get; }

    /// <summary>Length of the ground path, metres (3D, along the polyline).</summary>
    public float Length { get; }

    /// <summary>Length over speed, seconds.</summary>
    public override float Duration => Length / Speed;

    /// <summary>The trunk centre's offset from the path's first point at the start (the first stance's), world metres.</summary>
    public Vector3 StartOffset { get; }

    /// <summary>The trunk centre's offset from the path's last point at the end (the second stance's), world metres.</summary>
    public Vector3 EndOffset { get; }

    /// <summary>Distance walked along the path at <paramref name="time"/> seconds after the walk starts (clamped to the walk), metres.</summary>
    public float DistanceAt(float time) => Math.Clamp(time * Speed, 0f, Length);

    /// <summary>The ground point at <paramref name="distance"/> metres along the path (clamped), world metres.</summary>
    public Vector3 PointAt(float distance)
    {
        distance = Math.Clamp(distance, 0f, Length);
        int i = Array.BinarySearch(_distances, distance);
        if (i >= 0)
        {
            return _path[i];
        }

        i = ~i;
        if (i >= _path.Length)
        {
            return _path[^1];
        }

        float span = _distances[i] - _distances[i - 1];
        return span > 0f ? Vector3.Lerp(_path[i - 1], _path[i], (distance - _distances[i - 1]) / span) : _path[i];
    }

    /// <summary>
    /// The horizontal unit direction of travel at <paramref name="distance"/> metres along the path, smoothed over
    /// 0.25 m either way; the first stance's facing when the path has no horizontal extent.
    /// </summary>
    public Vector3 HeadingAt(float distance)
    {
        const float window = 0.25f;
        Vector3 d = PointAt(distance + window) - PointAt(distance - window);
        d.Y = 0f;
        if (d.LengthSquared() < 1e-8f)
        {
            d = PointAt(Length) - PointAt(0f);
            d.Y = 0f;
        }

        if (d.LengthSquared() < 1e-8f)
        {
            d = From.Pose.Forward;
            d.Y = 0f;
        }

        return d.LengthSquared() < 1e-8f ? Vector3.UnitZ : Vector3.Normalize(d);
    }

    /// <summary>
    /// The trunk's pose <paramref name="distance"/> metres along the path: the ground point plus the stance offset
    /// (blended smoothly from the start's to the end's), facing <see cref="HeadingAt"/> upright, turning from the
    /// first stance's orientation over the first <see cref="TurnDistance"/> (at most a third of the walk) and to the
    /// second stance's over the last. Exactly <see cref="From"/>'s pose at 0 and <see cref="To"/>'s at the end.
    /// </summary>
    public RootPose PoseAtDistance(float distance)
    {
        distance = Math.Clamp(distance, 0f, Length);
        float u = Length > 0f ? distance / Length : 1f;
        Vector3 position = PointAt(distance) + Vector3.Lerp(StartOffset, EndOffset, Smooth(u));
        if (distance <= 0f)
        {
            return From.Pose;
        }

        if (distance >= Length)
        {
            return To.Pose;
        }

        Vector3 h = HeadingAt(distance);
        Quaternion heading = Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(h.X, h.Z));
        float turn = MathF.Min(TurnDistance, Length / 3f);
        float a = Smooth(distance / turn);
        float b = Smooth((distance - (Length - turn)) / turn);
        Quaternion rotation = Quaternion.Normalize(Quaternion.Slerp(Quaternion.Slerp(From.Pose.Rotation, heading, a), To.Pose.Rotation, b));
        return new RootPose(position, rotation);
    }

    /// <summary>The trunk's pose <paramref name="time"/> seconds after the walk starts (clamped to the walk): <see cref="PoseAtDistance"/> at <see cref="DistanceAt"/>.</summary>
    public RootPose PoseAt(float time) => PoseAtDistance(DistanceAt(time));

    private static float Smooth(float x)
    {
        x = Math.Clamp(x, 0f, 1f);
        return x * x * (3f - (2f * x));
    }
}
