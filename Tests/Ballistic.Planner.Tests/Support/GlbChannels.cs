using SharpGLTF.Schema2;

namespace Ballistic.Planner.Tests.Support;

/// <summary>The channels of a clip in a GLB as SharpGLTF reads them: per target node and path, the key times and values.</summary>
internal static class GlbChannels
{
    /// <summary>
    /// Every translation and rotation channel of <paramref name="clip"/>, by target node index and path
    /// ("translation", "rotation"): its key times (seconds) and values, flattened (3 floats a key for a translation, 4
    /// for a rotation, x y z w).
    /// </summary>
    public static Dictionary<(int Node, string Path), (float[] Times, float[] Values)> Of(SharpGLTF.Schema2.Animation clip)
    {
        var keyed = new Dictionary<(int Node, string Path), (float[] Times, float[] Values)>();
        foreach (AnimationChannel channel in clip.Channels)
        {
            int node = channel.TargetNode.LogicalIndex;
            switch (channel.TargetNodePath)
            {
                case PropertyPath.translation:
                    var translations = channel.GetTranslationSampler().GetLinearKeys().ToArray();
                    keyed[(node, "translation")] = ([.. translations.Select(k => k.Key)], [.. translations.SelectMany(k => new[] { k.Value.X, k.Value.Y, k.Value.Z })]);
                    break;
                case PropertyPath.rotation:
                    var rotations = channel.GetRotationSampler().GetLinearKeys().ToArray();
                    keyed[(node, "rotation")] = ([.. rotations.Select(k => k.Key)], [.. rotations.SelectMany(k => new[] { k.Value.X, k.Value.Y, k.Value.Z, k.Value.W })]);
                    break;
                default:
                    throw new AssertionException($"clip '{clip.Name}' keys node {node}'s {channel.TargetNodePath}, which our clips never do");
            }
        }

        return keyed;
    }
}
