using Ballistic.Planner.Animation;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Advances every agent along its path on the path's clock: each jump's takeoff, flight exactly on its parabola and
/// landing; each walk exactly along its ground path at its speed (<see cref="Walk.PoseAt(float)"/>); the stance after each
/// move in which limbs re-step; and so on to the end of the last move. Emits each move's start and end as it is
/// crossed (at its exact time, which may fall between ticks: <see cref="JumpEventKind.JumpStarted"/> and
/// <see cref="JumpEventKind.Landed"/> for a jump, <see cref="JumpEventKind.WalkStarted"/> and
/// <see cref="JumpEventKind.WalkFinished"/> for a walk), then the arrival. An agent asked to stop (a new target, a
/// cleared one) stops on the next stance of its path: the end of the move it is in (a landing, or a walk's last
/// stance), or, when standing between two moves, before the next one starts; with a target waiting it queues a path
/// request (<see cref="PathQueue"/>) for the path-request system. Allocates nothing.
/// </summary>
internal sealed class LocomotionSystem(AgentStore agents, EventBuffer events, PathQueue requests)
{
    public void Update(long tick, double time)
    {
        for (int slot = 0; slot < agents.HighWater; slot++)
        {
            if (!agents.Alive[slot] || agents.Path[slot] is not { } path)
            {
                continue;
            }

            try
            {
                Advance(slot, path, tick, time);
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                // Never expected; the agent stops where its path began rather than letting the tick fail.
                Stop(slot, path.Start, path.Start.Pose, 0f, path);
                if (agents.Request[slot] is null)
                {
                    agents.Navigate(slot, NavigationStatus.Failed, $"internal error while moving: {e.Message}");
                }

                events.Add(new JumpEvent(JumpEventKind.PathFailed, agents.HandleOf(slot), tick, time, -1, agents.Root[slot].Position, path.Target, default, 0f, PlannerStatus.NoPath, $"internal error while moving: {e.Message}"));
            }
        }
    }

    private void Advance(int slot, AgentPath path, long tick, double time)
    {
        double start = agents.PathStart[slot];
        float t = (float)(time - start);
        AgentHandle handle = agents.HandleOf(slot);
        int cursor = agents.Cursor[slot];
        int boundaries = 2 * path.Count;
        while (cursor < boundaries)
        {
            ref readonly PathMove move = ref path.Move(cursor >> 1);
            bool ending = (cursor & 1) == 1;
            float when = ending ? move.End : move.Start;
            if (when > t)
            {
                break;
            }

            if (!ending && move.Index > 0 && agents.StopAtStance[slot])
            {
                // Standing between two moves: stop before this one starts.
                agents.Cursor[slot] = cursor;
                Stop(slot, move.From, path.Move(move.Index - 1).EndPose, move.Start, path);
                return;
            }

            events.Add(MoveEvent(path, move, ending, handle, tick, start + when));
            cursor++;
            if (ending && agents.StopAtStance[slot] && cursor < boundaries)
            {
                agents.Cursor[slot] = cursor;
                Stop(slot, move.To, move.EndPose, move.End, path);
                return;
            }
        }

        agents.Cursor[slot] = cursor;
        if (cursor == boundaries)
        {
            ref readonly PathMove last = ref path.Move(path.Count - 1);
            if (t < path.Duration && !agents.StopAtStance[slot])
            {
                // Landed: the body absorbs the landing and stands up before the target counts as reached.
                agents.Root[slot] = path.Animation.RootAt(t, ref agents.Frame[slot]);
                agents.State[slot] = AgentState.Stance;
                return;
            }

            // Arrived; unless another target came during the last move, which is then planned from here.
            if (!agents.StopAtStance[slot])
            {
                agents.HasTarget[slot] = false;
                agents.Navigate(slot, NavigationStatus.Reached);
                events.Add(new JumpEvent(JumpEventKind.TargetReached, handle, tick, start + path.Duration, last.Index, last.EndPose.Position, path.Target, default, 0f, PlannerStatus.Exact, null, path));
                Stop(slot, last.To, last.EndPose, path.Duration, path);
                return;
            }

            Stop(slot, last.To, last.EndPose, last.End, path);
            return;
        }

        ref readonly PathMove current = ref path.Move(cursor >> 1);
        if ((cursor & 1) == 0)
        {
            // On the ground before this move starts (the crouch before a first jump, or the stance after the previous
            // move): the root sinks and rises with the animation, over the same stance.
            agents.Root[slot] = path.Animation.RootAt(t, ref agents.Frame[slot]);
            agents.State[slot] = AgentState.Stance;
        }
        else if (current.Walk is { } walk)
        {
            // Walking: exactly along the walk's path at its speed, the trunk raised by the animation's upright lift.
            // The walk's segment and the animation's frame are searched from where the last tick found them.
            agents.Root[slot] = JumpAnimation.Lifted(walk.PoseAt(MoveTime(time, start, current), ref agents.WalkSegment[slot]), path.Animation.WalkLift(t, ref agents.Frame[slot]));
            agents.State[slot] = AgentState.Walking;
        }
        else
        {
            // In the air: exactly on the parabola.
            agents.Root[slot] = current.Arc.PoseAt(FlightTime(time, start, current));
            agents.State[slot] = t < current.TakeoffEnd ? AgentState.Takeoff : t >= current.LandingStart ? AgentState.Landing : AgentState.Flight;
        }
    }

    /// <summary>The event of <paramref name="move"/>'s (of <paramref name="path"/>) start or end (<paramref name="ending"/>) at world time <paramref name="when"/>.</summary>
    private static JumpEvent MoveEvent(AgentPath path, in PathMove move, bool ending, AgentHandle handle, long tick, double when)
    {
        if (move.Walk is { } walk)
        {
            return new JumpEvent(ending ? JumpEventKind.WalkFinished : JumpEventKind.WalkStarted, handle, tick, when, move.Index,
                move.From.Pose.Position, move.To.Pose.Position, default, walk.Duration, PlannerStatus.Exact, null, path);
        }

        return new JumpEvent(ending ? JumpEventKind.Landed : JumpEventKind.JumpStarted, handle, tick, when, move.Index,
            move.Arc.Start, move.Arc.End, move.Arc.TakeoffVelocity, move.Arc.FlightTime, PlannerStatus.Exact, null, path);
    }

    /// <summary>
    /// Seconds since the start of <paramref name="move"/> (a walk's first step), from world time: the formula every
    /// reader of the runtime's walks uses (<see cref="Paths.WalkInfo.StartTime"/> is <c>pathStart + move.Start</c>), so
    /// that an agent's root equals <c>walk.PoseAt((float)(time − startTime))</c> bit for bit, raised by the path's
    /// <see cref="JumpAnimation.WalkLift(float)"/>.
    /// </summary>
    public static float MoveTime(double time, double pathStart, in PathMove move) => (float)(time - (pathStart + move.Start));

    /// <summary>
    /// Seconds since the takeoff of <paramref name="move"/>, from world time: the one formula every reader of the
    /// runtime's arcs uses (<see cref="Paths.JumpInfo.TakeoffTime"/> is <c>pathStart + move.Start</c>), so that an
    /// agent's root equals <c>arc.PositionAt((float)(time − takeoffTime))</c> bit for bit.
    /// </summary>
    public static float FlightTime(double time, double pathStart, in PathMove move) => (float)(time - (pathStart + move.Start));

    /// <summary>Ends the path on <paramref name="stance"/>, holding the animation's pose at path time <paramref name="at"/>; queues the next request if a target waits.</summary>
    private void Stop(int slot, RoadmapNode stance, RootPose root, float at, AgentPath path)
    {
        agents.Path[slot] = null;
        agents.Stance[slot] = stance;
        agents.Root[slot] = root;
        agents.BodyStale[slot] = true;
        agents.StopAtStance[slot] = false;
        path.Animation.Sample(at, agents.AnglesOf(slot));
        agents.PoseDirty[slot] = true;
        agents.State[slot] = AgentState.Idle;
        if (agents.HasTarget[slot] && agents.Request[slot] is null)
        {
            agents.State[slot] = AgentState.Stance;
            requests.Request(slot);
        }
        else if (!agents.HasTarget[slot] && agents.Navigation[slot] == NavigationStatus.Following)
        {
            agents.Navigate(slot, NavigationStatus.Idle); // stopped on the stance after its target was cleared
        }
    }
}
