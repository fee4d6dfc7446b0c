using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Gltf;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;
using SharpGLTF.Schema2;

namespace Ballistic.Authoring.Levels;

/// <summary>Writes level meshes as a binary glTF file that Godot, Blender and <see cref="GltfLevelLoader"/> read.</summary>
public static class GltfLevelWriter
{
    /// <summary>The meshes as GLB bytes: one node per mesh, smooth vertex normals, one material per distinct material.</summary>
    /// <exception cref="GltfException">A coordinate is not finite.</exception>
    public static byte[] ToBytes(IReadOnlyList<LevelMesh> meshes)
    {
        ArgumentNullException.ThrowIfNull(meshes);
        ModelRoot root = GltfWrite.Create();
        Scene scene = root.UseScene("level");
        var materials = new Dictionary<(LevelMaterial, Vector4), Material>();
        foreach (LevelMesh mesh in meshes)
        {
            if (!materials.TryGetValue((mesh.Material, mesh.Color), out Material? material))
            {
                material = GltfWrite.Material(root, mesh.Material.Name, mesh.Color, roughness: 0.9f);
                var extras = new JsonObject();
                if (mesh.Material.Friction is float friction)
                {
                    extras["friction"] = friction;
                }

                if (mesh.Material.TravelCost != 1f)
                {
                    extras["travelCost"] = mesh.Material.TravelCost;
                }

                if (mesh.Material.EnterCost != 0f)
                {
                    extras["enterCost"] = mesh.Material.EnterCost;
                }

                if (extras.Count > 0)
                {
                    material.Extras = extras;
                }

                materials.Add((mesh.Material, mesh.Color), material);
            }

            Mesh written = root.CreateMesh(mesh.Name);
            MeshPrimitive primitive = written.CreatePrimitive();
            primitive.SetVertexAccessor("POSITION", GltfWrite.Vectors(root, mesh.Positions));
            primitive.SetVertexAccessor("NORMAL", GltfWrite.Vectors(root, SmoothNormals(mesh.Positions, mesh.Indices)));
            primitive.SetIndexAccessor(GltfWrite.Indices(root, mesh.Indices));
            primitive.Material = material;
            scene.CreateNode(mesh.Name).Mesh = written;
        }

        return GltfWrite.Glb(root);
    }

    /// <summary>Writes the meshes to <paramref name="path"/>.</summary>
    public static void Save(string path, IReadOnlyList<LevelMesh> meshes)
    {
        ArgumentNullException.ThrowIfNull(path);
        OutputFile.Write(path, ToBytes(meshes));
    }

    private static Vector3[] SmoothNormals(Vector3[] positions, int[] indices)
    {
        var normals = new Vector3[positions.Length];
        for (int i = 0; i + 2 < indices.Length; i += 3)
        {
            Vector3 n = Vector3.Cross(positions[indices[i + 1]] - positions[indices[i]], positions[indices[i + 2]] - positions[indices[i]]);
            normals[indices[i]] += n;
            normals[indices[i + 1]] += n;
            normals[indices[i + 2]] += n;
        }

        for (int i = 0; i < normals.Length; i++)
        {
            normals[i] = normals[i].LengthSquared() > 0f ? Vector3.Normalize(normals[i]) : Vector3.UnitY;
        }

        return normals;
    }
}
