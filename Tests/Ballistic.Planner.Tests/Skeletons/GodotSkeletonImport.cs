using System.Numerics;
using Ballistic.Planner.Gltf;
using Ballistic.Runtime.Skeletons;

namespace Ballistic.Planner.Tests.Skeletons;

/// <summary>A skeleton as Godot's glTF importer would make it from a file, with where its node sits in the scene.</summary>
/// <param name="Skeleton">Bone names, parents and rests.</param>
/// <param name="Global">The Skeleton3D node's transform in the imported scene (the glTF transform of the root bones' parent).</param>
/// <param name="BoneNodes">The glTF node of each bone.</param>
internal sealed record GodotSkeleton(TargetSkeleton Skeleton, BoneTransform Global, int[] BoneNodes);

/// <summary>
/// Emulates the skeleton Godot 4's glTF importer builds from skin 0 (modules/gltf/skin_tool.cpp): the skin's joints,
/// raised to one common parent when it has several root bones; every node lying between joints (anchors, empties)
/// and every node below a joint except a childless skinned mesh becomes a bone too; bones are ordered depth first
/// from the roots sorted by node index, children by node index; names have ':' and '/' replaced by '_' and repeats
/// suffixed "_2"…; each bone's rest is its node's local transform; the Skeleton3D node sits where the roots' parent is.
/// </summary>
internal static class GodotSkeletonImport
{
    /// <summary>The skeleton Godot imports from the glTF file at <paramref name="path"/> (read through SharpGLTF by <see cref="GltfModel"/>).</summary>
    public static GodotSkeleton Import(string path) => Import(GltfModel.Load(path));

    public static GodotSkeleton Import(GltfModel model)
    {
        IReadOnlyList<SharpGLTF.Schema2.Node> nodes = model.Root.LogicalNodes;
        int[] parents = model.NodeParents();
        Matrix4x4[] world = model.WorldTransforms();
        int[] joints = [.. model.Root.LogicalSkins[0].Joints.Select(j => j.LogicalIndex)];
        int Height(int n)
        {
            int h = 0;
            for (int p = parents[n]; p >= 0; p = parents[p])
            {
                h++;
            }

            return h;
        }

        var members = new HashSet<int>(joints);

        // Several root bones: raise them to the same height, then to the same parent.
        List<int> roots = [.. members.Where(j => parents[j] < 0 || !members.Contains(parents[j])).Order()];
        if (roots.Count > 1)
        {
            int top = roots.Min(Height);
            for (int i = 0; i < roots.Count; i++)
            {
                while (Height(roots[i]) > top)
                {
                    roots[i] = parents[roots[i]];
                    members.Add(roots[i]);
                }
            }

            while (roots.Select(r => parents[r]).Distinct().Count() > 1)
            {
                for (int i = 0; i < roots.Count; i++)
                {
                    roots[i] = parents[roots[i]];
                    members.Add(roots[i]);
                }
            }
        }

        // Nodes between a joint and its root.
        var rootSet = new HashSet<int>(roots);
        foreach (int j in joints)
        {
            for (int n = j; n >= 0 && !rootSet.Contains(n); n = parents[n])
            {
                members.Add(n);
            }
        }

        // Every node below a member, but a childless skinned mesh.
        bool IsSkinnedLeaf(int n) => nodes[n].Mesh is not null && nodes[n].Skin is not null && !nodes[n].VisualChildren.Any();
        var stack = new Stack<int>(members);
        while (stack.Count > 0)
        {
            int n = stack.Pop();
            for (int c = 0; c < parents.Length; c++)
            {
                if (parents[c] == n && !members.Contains(c) && !IsSkinnedLeaf(c))
                {
                    members.Add(c);
                    stack.Push(c);
                }
            }
        }

        // Depth first from the sorted roots, children by node index.
        int[] finalRoots = [.. members.Where(m => parents[m] < 0 || !members.Contains(parents[m])).Order()];
        var order = new List<int>();
        void Visit(int n)
        {
            order.Add(n);
            for (int c = 0; c < parents.Length; c++)
            {
                if (parents[c] == n && members.Contains(c))
                {
                    Visit(c);
                }
            }
        }

        foreach (int r in finalRoots)
        {
            Visit(r);
        }

        var used = new HashSet<string>(StringComparer.Ordinal);
        var names = new string[order.Count];
        var boneParents = new int[order.Count];
        var rests = new BoneTransform[order.Count];
        for (int b = 0; b < order.Count; b++)
        {
            int n = order[b];
            string baseName = GodotBoneNames.Sanitize(nodes[n].Name ?? "");
            string name = baseName;
            for (int k = 2; !used.Add(name); k++)
            {
                name = $"{baseName}_{k}";
            }

            names[b] = name;
            boneParents[b] = parents[n] >= 0 && members.Contains(parents[n]) ? order.IndexOf(parents[n]) : -1;
            rests[b] = Decompose(model.LocalTransform(nodes[n]));
        }

        int skeletonParent = parents[finalRoots[0]];
        BoneTransform global = skeletonParent >= 0 ? Decompose(world[skeletonParent]) : BoneTransform.Identity;
        return new GodotSkeleton(new TargetSkeleton(names, boneParents, rests), global, [.. order]);
    }

    public static BoneTransform Decompose(Matrix4x4 m)
    {
        Assert.That(Matrix4x4.Decompose(m, out Vector3 scale, out Quaternion rotation, out Vector3 translation), Is.True, "a decomposable transform");
        return new BoneTransform(translation, Quaternion.Normalize(rotation), scale);
    }
}
