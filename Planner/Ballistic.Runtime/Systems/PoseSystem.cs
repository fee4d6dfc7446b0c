using Ballistic.Planner.Rigs;
using Ballistic.Runtime.Agents;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// Fills each agent's slices of the world's pose pools from its whole-body animation at its path time: one angle per
/// degree of freedom and one local rotation per joint (relative to the parent joint; the root joint's relative to the
/// root pose), agents in slot order over two shared arrays. A
/// standing agent keeps the pose it stopped in and costs nothing. Allocates nothing: the animation was solved when
/// the path was found.
/// </summary>
internal sealed class PoseSystem(AgentStore agents)
{
    public void Update(double time)
    {
        for (int slot = 0; slot < agents.HighWater; slot++)
        {
            if (!agents.Alive[slot] || !agents.PoseEnabled[slot])
            {
                continue;
            }

            Span<float> angles = agents.AnglesOf(slot);
            if (agents.Path[slot] is { } path)
            {
                float t = Math.Clamp((float)(time - agents.PathStart[slot]), 0f, path.Duration);
                path.Animation.Sample(t, angles);
            }
            else if (!agents.PoseDirty[slot])
            {
                continue;
            }

            Rig rig = agents.Character[slot]!.Model.Rig;
            Span<System.Numerics.Quaternion> rotations = agents.RotationsOf(slot);
            for (int j = 0; j < rotations.Length; j++)
            {
                rotations[j] = rig.LocalRotation(j, angles);
            }

            agents.PoseDirty[slot] = false;
        }
    }
}
