using System.Numerics;
using System.Text.Json.Nodes;
using Ballistic.Authoring.Gltf;
using Ballistic.Planner.IO;
using Ballistic.Planner.Levels;

namespace Ballistic.Authoring.Levels;

/// <summary>Writes level meshes as a binary glTF file that Godot, Blender and <see cref="GltfLevelLoader"/> read.</summary>
public static class GltfLevelWriter
{
    /// <summary>The meshes as GLB bytes: one node per mesh, smooth vertex normals, one material per distinct material.</summary>
    public static byte[] ToBytes(IReadOnlyList<LevelMesh> meshes)
    {
        ArgumentNullException.ThrowIfNull(meshes);
        var writer = new GlbWriter();
        var materials = new Dictionary<(LevelMaterial, Vector4), int>();
        var sceneNodes = new JsonArray();
        foreach (LevelMesh mesh in meshes)
        {
            if (!materials.TryGetValue((mesh.Material, mesh.Color), out int material))
            {
                var json = new JsonObject
                {
                    ["name"] = mesh.Material.Name,
                    ["pbrMetallicRoughness"] = new JsonObject
                    {
                        ["baseColorFactor"] = new JsonArray(mesh.Color.X, mesh.Color.Y, mesh.Color.Z, mesh.Color.W),
                        ["metallicFactor"] = 0f,
                        ["roughnessFactor"] = 0.9f,
                    },
                };
                if (mesh.Material.Friction is float friction)
                {
                    json["extras"] = new JsonObject { ["friction"] = friction };
                }

                material = writer.Add("materials", json);
                materials.Add((mesh.Material, mesh.Color), material);
            }

            int positions = writer.AddVector3(mesh.Positions);
            int normals = writer.AddVector3(SmoothNormals(mesh.Positions, mesh.Indices));
            int indices = writer.AddIndices(mesh.Indices);
            int meshIndex = writer.Add("meshes", new JsonObject
            {
                ["name"] = mesh.Name,
                ["primitives"] = new JsonArray(new JsonObject
                {
                    ["attributes"] = new JsonObject { ["POSITION"] = positions, ["NORMAL"] = normals },
                    ["indices"] = indices,
                    ["material"] = material,
                }),
            });
            sceneNodes.Add(writer.Add("nodes", new JsonObject { ["name"] = mesh.Name, ["mesh"] = meshIndex }));
        }

        writer.Root["scene"] = writer.Add("scenes", new JsonObject { ["name"] = "level", ["nodes"] = sceneNodes });
        return writer.ToBytes();
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
