using System.Text.Json.Nodes;
using Ballistic.Planner.Rigs;

namespace Ballistic.Planner.Tests.Support;

/// <summary>The foreign dog written as a .gltf with its spec, and edits of its glTF JSON that must fail to load.</summary>
internal sealed class BrokenDog
{
    private readonly string _gltf;
    private readonly string _spec;
    private readonly JsonObject _pristine;

    public BrokenDog(string folder)
    {
        ForeignCharacter dog = ForeignCharacters.Dog();
        _gltf = dog.Rig.WriteGltf(folder, "dog");
        _spec = Path.Combine(folder, "dog.limbs.json");
        File.WriteAllText(_spec, dog.Spec);
        _pristine = JsonNode.Parse(File.ReadAllText(_gltf))!.AsObject();
    }

    /// <summary>The glTF JSON as written, for reading node indices.</summary>
    public JsonObject Pristine => _pristine;

    /// <summary>Applies <paramref name="change"/> to a copy of the glTF, loads it and returns the RigException's message.</summary>
    public string Load(Action<JsonObject> change)
    {
        var json = (JsonObject)_pristine.DeepClone();
        change(json);
        File.WriteAllText(_gltf, json.ToJsonString());
        string message = Assert.Throws<RigException>(() => CharacterSpecFile.Load(_gltf, _spec))!.Message;
        TestContext.Out.WriteLine(message);
        return message;
    }

    /// <summary>
    /// As <see cref="Load"/>, <paramref name="change"/> also given the bytes of the glTF's buffer to change (read
    /// and written through <see cref="Bytes"/>); the buffer is put back as it was afterwards.
    /// </summary>
    public string LoadPatched(Action<JsonObject, byte[]> change)
    {
        string bin = Path.Combine(Path.GetDirectoryName(_gltf)!, _pristine["buffers"]![0]!["uri"]!.GetValue<string>());
        byte[] original = File.ReadAllBytes(bin);
        try
        {
            return Load(json =>
            {
                byte[] bytes = (byte[])original.Clone();
                change(json, bytes);
                File.WriteAllBytes(bin, bytes);
            });
        }
        finally
        {
            File.WriteAllBytes(bin, original);
        }
    }

    /// <summary>The bytes of accessor <paramref name="accessor"/>'s first element on in <paramref name="bin"/> (the buffer of <paramref name="json"/>), and its component type.</summary>
    public static (Memory<byte> Bytes, int ComponentType) Bytes(JsonObject json, byte[] bin, int accessor)
    {
        JsonNode a = json["accessors"]![accessor]!;
        JsonNode view = json["bufferViews"]![a["bufferView"]!.GetValue<int>()]!;
        int offset = (view["byteOffset"]?.GetValue<int>() ?? 0) + (a["byteOffset"]?.GetValue<int>() ?? 0);
        return (bin.AsMemory(offset), a["componentType"]!.GetValue<int>());
    }
}
