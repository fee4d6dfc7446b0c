using System.Numerics;
using Ballistic.Runtime.Skeletons;

namespace Ballistic.Planner.Tests.Skeletons;

/// <summary>
/// What an engine skeleton shows after a binding's output is applied as the addon applies it: the driven bones'
/// pose rotations and the positioned bones' pose positions set, every other bone at its rest; world transforms by
/// forward kinematics from the skeleton node's global transform (scale, then rotation, then translation).
/// </summary>
internal static class TargetPose
{
    public static (Vector3[] Positions, Quaternion[] Rotations) World(SkeletonBinding binding, BoneTransform global, Quaternion[] rotations, Vector3[] positions)
    {
        TargetSkeleton skeleton = binding.Target;
        int n = skeleton.BoneCount;
        var worldPositions = new Vector3[n];
        var worldRotations = new Quaternion[n];
        var scales = new float[n];
        for (int b = 0; b < n; b++)
        {
            BoneTransform rest = skeleton.Rests[b];
            Quaternion local = binding.DrivenBones.Contains(b) ? rotations[b] : rest.Rotation;
            Vector3 translation = binding.PositionedBones.Contains(b) ? positions[b] : rest.Position;
            int p = skeleton.Parents[b];
            Vector3 parentPosition = p < 0 ? global.Position : worldPositions[p];
            Quaternion parentRotation = p < 0 ? global.Rotation : worldRotations[p];
            float parentScale = p < 0 ? global.Scale.X : scales[p];
            worldPositions[b] = parentPosition + Vector3.Transform(translation * parentScale, parentRotation);
            worldRotations[b] = Quaternion.Normalize(parentRotation * local);
            scales[b] = parentScale * rest.Scale.X;
        }

        return (worldPositions, worldRotations);
    }
}
