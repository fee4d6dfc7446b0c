using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Writes each agent's body point (<see cref="BodyPoint"/>) from its path at this tick, after locomotion: in a jump,
/// on the body point's parabola (<see cref="BodyMotion.InJump(in PathMove, float)"/>); in a walk, along the ground path
/// (<see cref="BodyMotion.InWalk(in PathMove, float)"/>); on a stance (standing, or between two moves of the path), its contact centre.
/// The clocks are locomotion's (<see cref="LocomotionSystem.FlightTime"/>, <see cref="LocomotionSystem.MoveTime"/>),
/// so the point is exact to the bit with the arc and walk the agent is on. Allocates nothing.
/// </summary>
internal sealed class BodyPointSystem(AgentStore agents)
{
    public void Update(double time)
    {
        for (int slot = 0; slot < agents.HighWater; slot++)
        {
            if (!agents.Alive[slot])
            {
                continue;
            }

            if (agents.Path[slot] is not { } path)
            {
                // Standing still: the point changes only when the agent stops on a stance (placed at once otherwise).
                if (agents.BodyStale[slot] && agents.Stance[slot] is { } stance)
                {
                    agents.Body[slot] = Standing(stance.ContactCentre, agents.Root[slot], agents.Body[slot].Heading);
                    agents.BodyStale[slot] = false;
                }

                continue;
            }

            int cursor = agents.Cursor[slot];
            double start = agents.PathStart[slot];
            Vector3 position;
            Vector3 velocity = Vector3.Zero;
            if (cursor >= 2 * path.Count)
            {
                position = path.StanceCentre(path.Count);
            }
            else if ((cursor & 1) == 0)
            {
                position = path.StanceCentre(cursor >> 1);
            }
            else
            {
                ref readonly PathMove move = ref path.Move(cursor >> 1);
                (position, velocity) = move.Walk is null
                    ? path.BodyInJump(cursor >> 1, LocomotionSystem.FlightTime(time, start, move))
                    : path.BodyInWalk(cursor >> 1, LocomotionSystem.MoveTime(time, start, move), agents.WalkSegment[slot]);
            }

            agents.Body[slot] = new BodyPoint(position, velocity, Heading(agents.Root[slot], agents.Body[slot].Heading));
        }
    }

    /// <summary>The body point standing at <paramref name="centre"/> (a stance's contact centre) with the trunk at <paramref name="root"/>.</summary>
    public static BodyPoint Standing(Vector3 centre, in RootPose root, Quaternion heading) => new(centre, Vector3.Zero, Heading(root, heading));

    /// <summary>
    /// The heading of a trunk at <paramref name="root"/>: about +Y, +Z turned toward its forward axis on the ground;
    /// <paramref name="previous"/> when it faces straight up or down. From the half-angle identities (no trigonometric
    /// call): it runs for every moving agent every tick.
    /// </summary>
    private static Quaternion Heading(in RootPose root, Quaternion previous)
    {
        // The trunk's forward (+Z turned by the rotation), on the ground plane.
        Quaternion q = root.Rotation;
        float x = 2f * ((q.X * q.Z) + (q.W * q.Y));
        float z = 1f - (2f * ((q.X * q.X) + (q.Y * q.Y)));
        float across = (x * x) + (z * z);
        if (!(across > 1e-8f))
        {
            return previous;
        }

        float cos = Math.Clamp(z / MathF.Sqrt(across), -1f, 1f);
        return new Quaternion(0f, MathF.CopySign(MathF.Sqrt(0.5f * (1f - cos)), x), 0f, MathF.Sqrt(0.5f * (1f + cos)));
    }
}
