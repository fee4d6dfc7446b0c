using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Writes each agent's body point (<see cref="BodyPoint"/>) from its path at this tick, after locomotion: in a jump,
/// on the body point's parabola (<see cref="BodyMotion.InJump"/>); in a walk, along the ground path
/// (<see cref="BodyMotion.InWalk"/>); on a stance (standing, or between two moves of the path), its contact centre.
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
                if (agents.Stance[slot] is { } stance)
                {
                    agents.Body[slot] = Standing(stance.ContactCentre, agents.Root[slot], agents.Body[slot].Heading);
                }

                continue;
            }

            int cursor = agents.Cursor[slot];
            double start = agents.PathStart[slot];
            Vector3 position;
            Vector3 velocity = Vector3.Zero;
            if (cursor >= 2 * path.Count)
            {
                position = path.Move(path.Count - 1).To.ContactCentre;
            }
            else if ((cursor & 1) == 0)
            {
                position = path.Move(cursor >> 1).From.ContactCentre;
            }
            else
            {
                ref readonly PathMove move = ref path.Move(cursor >> 1);
                (position, velocity) = move.Walk is null
                    ? BodyMotion.InJump(move, LocomotionSystem.FlightTime(time, start, move))
                    : BodyMotion.InWalk(move, LocomotionSystem.MoveTime(time, start, move));
            }

            agents.Body[slot] = new BodyPoint(position, velocity, Heading(agents.Root[slot], agents.Body[slot].Heading));
        }
    }

    /// <summary>The body point standing at <paramref name="centre"/> (a stance's contact centre) with the trunk at <paramref name="root"/>.</summary>
    public static BodyPoint Standing(Vector3 centre, in RootPose root, Quaternion heading) => new(centre, Vector3.Zero, Heading(root, heading));

    /// <summary>The heading of a trunk at <paramref name="root"/>: about +Y, +Z turned toward its forward axis on the ground; <paramref name="previous"/> when it faces straight up or down.</summary>
    private static Quaternion Heading(in RootPose root, Quaternion previous)
    {
        Vector3 forward = root.Forward;
        return (forward.X * forward.X) + (forward.Z * forward.Z) > 1e-8f
            ? Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(forward.X, forward.Z))
            : previous;
    }
}
