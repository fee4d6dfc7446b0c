using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Support;

/// <summary>A foot of a <see cref="ForeignCharacter"/>: its limb and the bones its vertices belong to.</summary>
internal sealed record ForeignFoot(string Limb, string[] Bones);

/// <summary>
/// A rig written as another tool would (<see cref="ForeignRig"/>) with its limbs-only spec, the rotation that takes
/// its glTF scene into Ballistic's frame (worked out by hand), its root and head bones, a bone behind and one ahead
/// of it (to check it faces forward), the bones the derived trunk should hold, and its feet.
/// </summary>
internal sealed record ForeignCharacter(string Name, ForeignRig Rig, string Spec, Quaternion ToBallistic, string Root, string Head, string Behind, string Ahead, string[] TrunkBones, ForeignFoot[] Feet, bool External, bool ByteWeights)
{
    /// <summary>Writes the glTF (a GLB, or a .gltf with its .bin and .png beside it) and the spec into <paramref name="folder"/>; returns both paths.</summary>
    public (string Gltf, string Spec) Write(string folder)
    {
        string gltf;
        if (External)
        {
            gltf = Rig.WriteGltf(folder, Name);
        }
        else
        {
            gltf = Path.Combine(folder, Name + ".glb");
            File.WriteAllBytes(gltf, Rig.ToGlb(ByteWeights));
        }

        string spec = Path.Combine(folder, Name + ".limbs.json");
        File.WriteAllText(spec, Spec);
        return (gltf, spec);
    }

    /// <summary>Writes the files into a temporary folder, loads them as a user's would be, and removes the folder.</summary>
    public (CharacterModel Model, ReducedCharacter Reduced) Load()
    {
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-{Name}-{Guid.NewGuid():N}");
        try
        {
            return Load(folder);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    /// <summary>Writes the files into <paramref name="folder"/> (created) and loads them; the folder stays, for writers that read the rig's images again.</summary>
    public (CharacterModel Model, ReducedCharacter Reduced) Load(string folder)
    {
        Directory.CreateDirectory(folder);
        (string gltf, string spec) = Write(folder);
        return CharacterSpecFile.Load(gltf, spec);
    }

    /// <summary>Scene positions of the vertices of the named bones.</summary>
    public Vector3[] Vertices(params string[] bones) => Rig.VerticesOf([.. bones.Select(b => Rig[b])]);

    /// <summary>A bone's head in the glTF scene.</summary>
    public Vector3 BonePosition(string bone) => Rig.World(Rig[bone]).Translation;
}
