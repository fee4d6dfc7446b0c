using System.Numerics;
using System.Text;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The limb spec (<c>ballistic.character/1</c> JSON) that turns any rigged glTF character into a
/// <see cref="CharacterModel"/>: for each limb its root bone, effector bone, contact point offset and contact normal
/// in the effector bone's frame, contact kind and normal filter; optionally the degrees of freedom and limits of
/// bones (degrees; limb bones not listed become ball joints of ±90°, other bones are fixed), the trunk bones, bone
/// radii and the reference poses. Bones are the glTF skin's joints, matched by node name.
/// </summary>
public static class CharacterSpecFile
{
    /// <summary>The schema name of spec files.</summary>
    public const string Schema = "ballistic.character/1";

    /// <summary>Loads a character from a rigged glTF file and its limb spec.</summary>
    /// <exception cref="RigException">The spec or the glTF rig is unusable; the message names the file, bone or limb.</exception>
    public static (CharacterModel Model, ReducedCharacter Reduced) Load(string gltfPath, string specPath)
    {
        ArgumentNullException.ThrowIfNull(gltfPath);
        ArgumentNullException.ThrowIfNull(specPath);
        JsonObject spec;
        try
        {
            spec = JsonNode.Parse(File.ReadAllBytes(specPath)) as JsonObject ?? throw new RigException($"{specPath} is not a JSON object.");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException)
        {
            throw new RigException($"Limb spec {specPath} cannot be read: {e.Message}", e);
        }

        GltfDocument document;
        try
        {
            document = GltfDocument.Load(gltfPath);
        }
        catch (GltfException e)
        {
            throw new RigException(e.Message, e);
        }

        try
        {
            return Build(document, spec, specPath);
        }
        catch (Exception e) when (e is InvalidOperationException or FormatException or KeyNotFoundException or NullReferenceException or InvalidCastException)
        {
            throw new RigException($"Limb spec {specPath} is malformed ({e.Message}).", e);
        }
    }

    /// <summary>Writes the spec of <paramref name="model"/> with the planner parameters of <paramref name="reduced"/>.</summary>
    public static void Save(CharacterModel model, ReducedCharacter reduced, string path) => OutputFile.Write(path, ToBytes(model, reduced));

    /// <summary>The spec of <paramref name="model"/> as indented UTF-8 JSON.</summary>
    public static byte[] ToBytes(CharacterModel model, ReducedCharacter reduced)
    {
        ArgumentNullException.ThrowIfNull(model);
        ArgumentNullException.ThrowIfNull(reduced);
        Rig rig = model.Rig;
        var limbs = new JsonObject();
        foreach (RigLimb limb in model.Limbs)
        {
            limbs[limb.Name] = new JsonObject
            {
                ["rootBone"] = rig.Joints[limb.RootJoint].Name,
                ["effectorBone"] = rig.Joints[limb.EffectorJoint].Name,
                ["effectorOffset"] = Vec(limb.EffectorOffset),
                ["contactNormal"] = Vec(limb.ContactNormal),
                ["contact"] = limb.Kind == LimbKind.Foot ? "foot" : "hand",
                ["normalFilter"] = new JsonObject { ["direction"] = Vec(limb.Filter.Direction), ["minCosine"] = limb.Filter.MinCosine },
            };
        }

        var joints = new JsonObject();
        var radii = new JsonObject();
        for (int j = 0; j < rig.Joints.Count; j++)
        {
            radii[rig.Joints[j].Name] = model.BoneRadii[j];
            if (rig.DofsOf(j) == 0)
            {
                continue;
            }

            var axes = new JsonArray();
            foreach (JointAxis axis in rig.Joints[j].Axes)
            {
                axes.Add(new JsonObject { ["axis"] = Vec(axis.Axis), ["min"] = Degrees(axis.Min), ["max"] = Degrees(axis.Max) });
            }

            joints[rig.Joints[j].Name] = new JsonObject { ["axes"] = axes };
        }

        var root = new JsonObject
        {
            ["schema"] = Schema,
            ["name"] = model.Name,
            ["requiredContacts"] = reduced.RequiredContacts,
            ["takeoffSpeedMax"] = reduced.TakeoffSpeedMax,
            ["landingSpeedMax"] = reduced.LandingSpeedMax,
            ["friction"] = reduced.Friction,
            ["trunkBones"] = new JsonArray([.. model.TrunkJoints.Select(j => (JsonNode)JsonValue.Create(rig.Joints[j].Name))]),
            ["limbs"] = limbs,
            ["joints"] = joints,
            ["boneRadii"] = radii,
            ["poses"] = new JsonObject { ["contact"] = Pose(rig, model.ContactPose), ["flexion"] = Pose(rig, model.FlexionPose), ["extending"] = Pose(rig, model.ExtendingPose) },
        };
        return Encoding.UTF8.GetBytes(root.ToJsonString(new JsonSerializerOptions { WriteIndented = true }) + "\n");
    }

    private static (CharacterModel, ReducedCharacter) Build(GltfDocument document, JsonObject spec, string specPath)
    {
        string schema = spec["schema"]?.GetValue<string>() ?? "";
        if (schema != Schema)
        {
            throw new RigException($"{specPath} is not a Ballistic limb spec (schema '{schema}', expected '{Schema}').");
        }

        string name = spec["name"]?.GetValue<string>() ?? Path.GetFileNameWithoutExtension(specPath);
        JsonArray skins = document.Array("skins");
        if (skins.Count == 0)
        {
            throw new RigException($"{document.Name} has no skin: a character needs a rigged (skinned) mesh.");
        }

        JsonArray nodes = document.Array("nodes");
        int[] skinJoints = [.. ((JsonArray)skins[0]!["joints"]!).Select(j => j!.GetValue<int>())];
        var parentNode = new int[nodes.Count];
        Array.Fill(parentNode, -1);
        for (int n = 0; n < nodes.Count; n++)
        {
            foreach (JsonNode? child in nodes[n]?["children"] as JsonArray ?? [])
            {
                parentNode[child!.GetValue<int>()] = n;
            }
        }

        var isJoint = new HashSet<int>(skinJoints);
        int[] roots = [.. skinJoints.Where(j => parentNode[j] < 0 || !isJoint.Contains(parentNode[j]))];
        if (roots.Length != 1)
        {
            throw new RigException($"{document.Name}: the skin's bones must form one hierarchy; it has {roots.Length} root bones.");
        }

        // Parents before children: the skin's own order when it already is, else breadth-first from the root bone.
        var order = new List<int>();
        var seen = new HashSet<int>();
        bool parentFirst = true;
        foreach (int j in skinJoints)
        {
            parentFirst &= j == roots[0] || seen.Contains(parentNode[j]);
            seen.Add(j);
        }

        var queue = new Queue<int>(parentFirst ? [] : [roots[0]]);
        if (parentFirst)
        {
            order.AddRange(skinJoints);
        }

        while (queue.Count > 0)
        {
            int node = queue.Dequeue();
            order.Add(node);
            foreach (JsonNode? child in nodes[node]?["children"] as JsonArray ?? [])
            {
                int c = child!.GetValue<int>();
                if (isJoint.Contains(c))
                {
                    queue.Enqueue(c);
                }
            }
        }

        string NodeName(int node) => nodes[node]?["name"]?.GetValue<string>() ?? $"node {node}";
        var index = new Dictionary<int, int>();
        for (int i = 0; i < order.Count; i++)
        {
            index[order[i]] = i;
        }

        // Bones on limb chains move by default; the spec may give any bone its own axes.
        JsonObject limbs = spec["limbs"] as JsonObject ?? throw new RigException($"{specPath} has no limbs.");
        var chainBones = new HashSet<string>(StringComparer.Ordinal);
        foreach ((string limbName, JsonNode? limbNode) in limbs)
        {
            string rootBone = limbNode?["rootBone"]?.GetValue<string>() ?? throw new RigException($"{specPath}: limb '{limbName}' has no rootBone.");
            string effectorBone = limbNode["effectorBone"]?.GetValue<string>() ?? throw new RigException($"{specPath}: limb '{limbName}' has no effectorBone.");
            int effector = order.FindIndex(n => NodeName(n) == effectorBone);
            if (effector < 0)
            {
                throw new RigException($"{specPath}: limb '{limbName}' names the effector bone '{effectorBone}', which is not a bone of {document.Name}.");
            }

            if (!order.Any(n => NodeName(n) == rootBone))
            {
                throw new RigException($"{specPath}: limb '{limbName}' names the root bone '{rootBone}', which is not a bone of {document.Name}.");
            }

            for (int node = order[effector]; node >= 0 && isJoint.Contains(node); node = parentNode[node])
            {
                chainBones.Add(NodeName(node));
                if (NodeName(node) == rootBone)
                {
                    break;
                }
            }
        }

        JsonObject jointSpecs = spec["joints"] as JsonObject ?? [];
        var joints = new List<Joint>();
        var radii = new List<float>();
        JsonObject radiusSpecs = spec["boneRadii"] as JsonObject ?? [];
        float defaultRadius = spec["boneRadius"]?.GetValue<float>() ?? 0.03f;
        foreach (int node in order)
        {
            string bone = NodeName(node);
            var json = (JsonObject)nodes[node]!;
            if (json["scale"] is JsonArray scale && scale.Any(v => MathF.Abs(v!.GetValue<float>() - 1f) > 1e-3f))
            {
                throw new RigException($"{document.Name}: bone '{bone}' is scaled; apply the scale before exporting.");
            }

            Matrix4x4 local = document.LocalTransform(json);
            Vector3 offset = local.Translation;
            Quaternion rest = Quaternion.CreateFromRotationMatrix(local);
            if (node == roots[0])
            {
                // The root bone's frame in world space: its ancestors' transforms folded in.
                Matrix4x4 world = local;
                for (int p = parentNode[node]; p >= 0; p = parentNode[p])
                {
                    world *= document.LocalTransform((JsonObject)nodes[p]!);
                }

                rest = Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(world));
                offset = Vector3.Zero;
            }

            JointAxis[] axes = jointSpecs[bone] is JsonObject js
                ? [.. ((JsonArray)js["axes"]!).Select(a => new JointAxis(Vector3.Normalize(Vec3(a!["axis"]!)), Radians(a["min"]!.GetValue<float>()), Radians(a["max"]!.GetValue<float>())))]
                : chainBones.Contains(bone) && node != roots[0]
                    ? [new JointAxis(Vector3.UnitX, Radians(-90f), Radians(90f)), new JointAxis(Vector3.UnitY, Radians(-90f), Radians(90f)), new JointAxis(Vector3.UnitZ, Radians(-90f), Radians(90f))]
                    : [];
            joints.Add(new Joint(bone, node == roots[0] ? -1 : index[parentNode[node]], offset, rest, axes));
            radii.Add(radiusSpecs[bone]?.GetValue<float>() ?? defaultRadius);
        }

        int[] trunk = spec["trunkBones"] is JsonArray tb
            ? [.. tb.Select(b => joints.FindIndex(j => j.Name == b!.GetValue<string>()) is int i && i >= 0 ? i : throw new RigException($"{specPath}: trunk bone '{b}' is not a bone of {document.Name}."))]
            : [0];
        var rig0 = new Rig(joints, Vector3.Zero);
        float[] Pose0(string poseName) => PoseFrom(rig0, spec["poses"]?[poseName] as JsonObject);
        (Vector3 centre, _) = ReducedModelBuilder.TrunkBox(joints, trunk, radii, Pose0("contact"));
        var rig = new Rig(joints, -centre);
        var rigLimbs = new List<RigLimb>();
        foreach ((string limbName, JsonNode? limbNode) in limbs)
        {
            JsonObject filter = limbNode!["normalFilter"] as JsonObject ?? [];
            rigLimbs.Add(new RigLimb(
                rig,
                limbName,
                limbNode["contact"]?.GetValue<string>() == "hand" ? LimbKind.Hand : LimbKind.Foot,
                limbNode["rootBone"]!.GetValue<string>(),
                limbNode["effectorBone"]!.GetValue<string>(),
                limbNode["effectorOffset"] is JsonNode eo ? Vec3(eo) : Vector3.Zero,
                limbNode["contactNormal"] is JsonNode cn ? Vec3(cn) : -Vector3.UnitY,
                filter.Count == 0 ? NormalFilter.None : new NormalFilter(Vector3.Normalize(Vec3(filter["direction"]!)), filter["minCosine"]!.GetValue<float>())));
        }

        var model = new CharacterModel(name, rig, rigLimbs, trunk, radii, PoseFrom(rig, spec["poses"]?["contact"] as JsonObject), PoseFrom(rig, spec["poses"]?["flexion"] as JsonObject), PoseFrom(rig, spec["poses"]?["extending"] as JsonObject));
        ReducedCharacter reduced;
        try
        {
            reduced = ReducedModelBuilder.Derive(
                model,
                spec["requiredContacts"]?.GetValue<int>() ?? Math.Min(2, rigLimbs.Count),
                spec["takeoffSpeedMax"]?.GetValue<float>() ?? 8f,
                spec["landingSpeedMax"]?.GetValue<float>() ?? 12f,
                spec["friction"]?.GetValue<float>() ?? 0.5f);
        }
        catch (CharacterException e)
        {
            throw new RigException($"{specPath}: {e.Message}", e);
        }

        return (model, reduced);
    }

    private static float[] PoseFrom(Rig rig, JsonObject? pose)
    {
        float[] q = rig.Neutral();
        if (pose is null)
        {
            return q;
        }

        foreach ((string bone, JsonNode? values) in pose)
        {
            int j = rig.IndexOf(bone);
            if (j < 0)
            {
                throw new RigException($"A pose names the bone '{bone}', which is not in the rig.");
            }

            var list = (JsonArray)values!;
            for (int k = 0; k < list.Count && k < rig.DofsOf(j); k++)
            {
                int d = rig.FirstDof(j) + k;
                q[d] = rig.Dofs[d].Clamp(Radians(list[k]!.GetValue<float>()));
            }
        }

        return q;
    }

    private static JsonObject Pose(Rig rig, float[] q)
    {
        var pose = new JsonObject();
        for (int j = 0; j < rig.Joints.Count; j++)
        {
            if (rig.DofsOf(j) > 0)
            {
                var values = new JsonArray();
                for (int d = rig.FirstDof(j); d < rig.FirstDof(j) + rig.DofsOf(j); d++)
                {
                    values.Add(MathF.Round(Degrees(q[d]), 4));
                }

                pose[rig.Joints[j].Name] = values;
            }
        }

        return pose;
    }

    private static JsonArray Vec(Vector3 v) => new(Round(v.X), Round(v.Y), Round(v.Z));

    private static float Round(float v) => MathF.Round(v, 6) + 0f; // + 0 turns −0 into 0

    private static Vector3 Vec3(JsonNode node) => new(node[0]!.GetValue<float>(), node[1]!.GetValue<float>(), node[2]!.GetValue<float>());

    private static float Degrees(float radians) => MathF.Round(radians * 180f / MathF.PI, 4);

    private static float Radians(float degrees) => degrees * MathF.PI / 180f;
}
