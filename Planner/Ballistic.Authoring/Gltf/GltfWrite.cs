using System.Buffers.Binary;
using System.Numerics;
using Ballistic.Planner.Gltf;
using SharpGLTF.Memory;
using SharpGLTF.Schema2;
using SharpGLTF.Validation;

namespace Ballistic.Authoring.Gltf;

/// <summary>
/// What our GLB writers add to a SharpGLTF <see cref="ModelRoot"/>: accessors over little-endian copies of our arrays
/// (positions with the bounds glTF requires; every number checked finite first), and the binary file itself, written
/// by the library after its own validation. The same calls give the same bytes.
/// </summary>
internal static class GltfWrite
{
    /// <summary>What our files name as their generator.</summary>
    public const string Generator = "Ballistic";

    /// <summary>An empty model whose asset names <see cref="Generator"/>.</summary>
    public static ModelRoot Create()
    {
        ModelRoot root = ModelRoot.CreateModel();
        root.Asset.Generator = Generator;
        root.Asset.Copyright = null;
        return root;
    }

    /// <summary>
    /// A non-metallic PBR material of base colour <paramref name="color"/> (linear RGBA) and roughness
    /// <paramref name="roughness"/> (0 … 1), seen from both sides with <paramref name="doubleSided"/>.
    /// </summary>
    public static Material Material(ModelRoot root, string name, Vector4 color, float roughness, bool doubleSided = false)
    {
        Material material = root.CreateMaterial(name);
        material.InitializePBRMetallicRoughness();
        material.DoubleSided = doubleSided;
        MaterialChannel baseColor = material.FindChannel("BaseColor")!.Value;
        baseColor.Color = color;
        MaterialChannel surface = material.FindChannel("MetallicRoughness")!.Value;
        surface.SetFactor("MetallicFactor", 0f);
        surface.SetFactor("RoughnessFactor", roughness);
        return material;
    }

    /// <summary>A VEC3 float accessor (vertex data, or animation output with <paramref name="vertex"/> false), with min and max.</summary>
    /// <exception cref="GltfException">A coordinate is not finite.</exception>
    public static Accessor Vectors(ModelRoot root, ReadOnlySpan<Vector3> values, bool vertex = true)
    {
        float[] flat = new float[values.Length * 3];
        for (int i = 0; i < values.Length; i++)
        {
            (flat[3 * i], flat[(3 * i) + 1], flat[(3 * i) + 2]) = (values[i].X, values[i].Y, values[i].Z);
        }

        return Floats(root, flat, DimensionType.VEC3, vertex);
    }

    /// <summary>A float accessor of <paramref name="type"/> (SCALAR, VEC4, MAT4…); vertex data with <paramref name="vertex"/>.</summary>
    /// <exception cref="GltfException">A value is not finite.</exception>
    public static Accessor Floats(ModelRoot root, ReadOnlySpan<float> values, DimensionType type, bool vertex = false)
    {
        byte[] bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++)
        {
            if (!float.IsFinite(values[i]))
            {
                throw new GltfException($"Cannot write value {values[i]} (element {i}) to glTF: every number must be finite.");
            }

            BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(4 * i), values[i]);
        }

        int components = type switch { DimensionType.SCALAR => 1, DimensionType.VEC2 => 2, DimensionType.VEC3 => 3, DimensionType.VEC4 => 4, DimensionType.MAT4 => 16, _ => throw new ArgumentOutOfRangeException(nameof(type)) };
        Accessor accessor = root.CreateAccessor();
        if (vertex)
        {
            accessor.SetVertexData(root.UseBufferView(bytes, 0, null, 0, BufferMode.ARRAY_BUFFER), 0, values.Length / components, new AttributeFormat(type, EncodingType.FLOAT, false));
        }
        else
        {
            accessor.SetData(root.UseBufferView(bytes), 0, values.Length / components, new AttributeFormat(type, EncodingType.FLOAT, false));
        }

        return accessor;
    }

    /// <summary>A triangle index accessor: 16-bit when every index fits, else 32-bit.</summary>
    public static Accessor Indices(ModelRoot root, ReadOnlySpan<int> indices)
    {
        int largest = 0;
        foreach (int i in indices)
        {
            largest = Math.Max(largest, i);
        }

        bool small = largest < ushort.MaxValue;
        byte[] bytes = new byte[indices.Length * (small ? 2 : 4)];
        for (int i = 0; i < indices.Length; i++)
        {
            if (small)
            {
                BinaryPrimitives.WriteUInt16LittleEndian(bytes.AsSpan(2 * i), (ushort)indices[i]);
            }
            else
            {
                BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(4 * i), (uint)indices[i]);
            }
        }

        Accessor accessor = root.CreateAccessor();
        accessor.SetIndexData(root.UseBufferView(bytes, 0, null, 0, BufferMode.ELEMENT_ARRAY_BUFFER), 0, indices.Length, small ? IndexEncodingType.UNSIGNED_SHORT : IndexEncodingType.UNSIGNED_INT);
        return accessor;
    }

    /// <summary>An unsigned-byte VEC4 vertex accessor (skin joint indices, four per vertex).</summary>
    public static Accessor Joints(ModelRoot root, ReadOnlySpan<byte> joints)
    {
        Accessor accessor = root.CreateAccessor();
        accessor.SetVertexData(root.UseBufferView(joints.ToArray(), 0, null, 0, BufferMode.ARRAY_BUFFER), 0, joints.Length / 4, new AttributeFormat(DimensionType.VEC4, EncodingType.UNSIGNED_BYTE, false));
        return accessor;
    }

    /// <summary>
    /// The model as one self-contained GLB (buffers merged, images embedded), validated by SharpGLTF as it writes.
    /// </summary>
    /// <exception cref="GltfException">The library refuses the model (a bug of the writer, said in one line).</exception>
    public static byte[] Glb(ModelRoot root)
    {
        try
        {
            return root.WriteGLB(new WriteSettings { Validation = ValidationMode.Strict, MergeBuffers = true, ImageWriting = ResourceWriteMode.BufferView }).ToArray();
        }
        catch (Exception e) when (e is SharpGLTF.Validation.ModelException or InvalidOperationException or ArgumentException)
        {
            throw new GltfException($"Cannot write the GLB: {e.Message.ReplaceLineEndings(" ")}", e);
        }
    }
}
