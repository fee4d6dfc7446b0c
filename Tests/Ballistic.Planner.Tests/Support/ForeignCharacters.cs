using System.Numerics;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// Characters in the shapes other tools export, each with a limbs-only spec: a Mixamo/Blender-like human in
/// centimetres and Z up under a rotated, scaled armature (or in a Z-up scene that the spec turns upright); a dog with
/// anchor empties between its leg bones (one scaled, one bone written as a matrix), written as a .gltf with its buffer
/// and texture in separate files; and a tailed quadruped whose skin has three root bones under one armature node
/// (tail, IK target and hips) that faces +X; and a 4.5 cm rat whose tail lies on the ground. The dog's and the tailed
/// quadruped's specs give a full-size jumper's speeds (8 and 12 m/s: what these rigs are tested with since before
/// speeds scaled with size); the others give none.
/// </summary>
internal static class ForeignCharacters
{
    /// <summary>The character called <paramref name="name"/>: "human", "human-zup", "dog", "tailed", "rat", "spider" or "panda".</summary>
    public static ForeignCharacter Named(string name) => name switch
    {
        "human" => Human(zUpScene: false),
        "human-zup" => Human(zUpScene: true),
        "dog" => Dog(),
        "tailed" => TailedQuadruped(),
        "rat" => Rat(),
        "spider" => Spider(),
        "panda" => Panda(),
        _ => throw new ArgumentException($"no foreign character '{name}'", nameof(name)),
    };

    public static ForeignCharacter Human(bool zUpScene)
    {
        var r = new ForeignRig();
        const float Degree = MathF.PI / 180f;
        int arm = zUpScene
            ? r.Node("Armature", -1, new Vector3(0.5f, 0f, -0.2f), Quaternion.Identity, 0.01f)
            : r.Node("Armature", -1, Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitX, -90f * Degree), 0.01f);
        int hips = r.BoneAt("mixamorig:Hips", arm, arm, new(0, 0, 100), new(0, 0, 112));
        int spine = r.BoneAt("mixamorig:Spine", hips, arm, new(0, 0, 112), new(0, 0, 130));
        int chest = r.BoneAt("mixamorig:Spine1", spine, arm, new(0, 0, 130), new(0, 0, 150));
        int neck = r.BoneAt("mixamorig:Neck", chest, arm, new(0, 0, 150), new(0, 0, 158));
        int head = r.BoneAt("mixamorig:Head", neck, arm, new(0, 0, 158), new(0, 0, 182));
        r.Box(hips, arm, new(-16, -11, 88), new(16, 11, 112));
        r.Box(spine, arm, new(-15, -10, 112), new(15, 10, 130), hips);
        r.Box(chest, arm, new(-18, -11, 130), new(18, 11, 150), spine);
        r.Box(neck, arm, new(-5, -5, 150), new(5, 5, 158), chest);
        r.Box(head, arm, new(-9, -11, 158), new(9, 11, 182));
        var trunk = new List<string> { "mixamorig:Hips", "mixamorig:Spine", "mixamorig:Spine1" };
        var feet = new List<ForeignFoot>();
        foreach ((string side, float s) in new[] { ("Left", 1f), ("Right", -1f) })
        {
            int shoulder = r.BoneAt($"mixamorig:{side}Shoulder", chest, arm, new(3 * s, 0, 145), new(18 * s, 0, 145), twist: 0.2f);
            int upper = r.BoneAt($"mixamorig:{side}Arm", shoulder, arm, new(18 * s, 0, 145), new(45 * s, 0, 145));
            int fore = r.BoneAt($"mixamorig:{side}ForeArm", upper, arm, new(45 * s, 0, 145), new(70 * s, 0, 145), twist: -0.4f);
            int hand = r.BoneAt($"mixamorig:{side}Hand", fore, arm, new(70 * s, 0, 145), new(88 * s, 0, 145));
            int thigh = r.BoneAt($"mixamorig:{side}UpLeg", hips, arm, new(9 * s, 0, 95), new(9 * s, 0, 52));
            int shin = r.BoneAt($"mixamorig:{side}Leg", thigh, arm, new(9 * s, 0, 52), new(9 * s, 0, 10), twist: 0.3f);
            int foot = r.BoneAt($"mixamorig:{side}Foot", shin, arm, new(9 * s, 0, 10), new(9 * s, -12, 2));
            int toe = r.BoneAt($"mixamorig:{side}ToeBase", foot, arm, new(9 * s, -12, 2), new(9 * s, -20, 2));
            r.Box(shoulder, arm, new(MathF.Min(3 * s, 18 * s), -6, 140), new(MathF.Max(3 * s, 18 * s), 6, 150), chest, 0.2f);
            r.Box(upper, arm, new(MathF.Min(18 * s, 45 * s), -5, 140), new(MathF.Max(18 * s, 45 * s), 5, 150), shoulder);
            r.Box(fore, arm, new(MathF.Min(45 * s, 70 * s), -4, 141), new(MathF.Max(45 * s, 70 * s), 4, 149), upper);
            r.Box(hand, arm, new(MathF.Min(70 * s, 88 * s), -4.5f, 142), new(MathF.Max(70 * s, 88 * s), 4.5f, 147), fore, 0.2f);
            r.Box(thigh, arm, new((9 * s) - 6, -7, 52), new((9 * s) + 6, 7, 95), hips, 0.2f);
            r.Box(shin, arm, new((9 * s) - 5, -6, 10), new((9 * s) + 5, 6, 52), thigh);
            r.Box(foot, arm, new((9 * s) - 5, -12, 0), new((9 * s) + 5, 6, 12), shin, 0.2f);
            r.Box(toe, arm, new((9 * s) - 5, -20, 0), new((9 * s) + 5, -12, 4), foot);
            trunk.Add($"mixamorig:{side}Shoulder");
            feet.Add(new ForeignFoot($"{side.ToLowerInvariant()}_foot", [$"mixamorig:{side}Foot", $"mixamorig:{side}ToeBase"]));
        }

        string axes = zUpScene ? "\"upAxis\":\"+Z\",\"forwardAxis\":\"-Y\"," : "";
        string spec = "{\"schema\":\"ballistic.character/1\",\"name\":\"mixamo_human\"," + axes + """

             "limbs":{
               "left_foot":{"rootBone":"mixamorig:LeftUpLeg","effectorBone":"mixamorig:LeftFoot"},
               "right_foot":{"rootBone":"mixamorig:RightUpLeg","effectorBone":"mixamorig:RightFoot"},
               "left_hand":{"rootBone":"mixamorig:LeftArm","effectorBone":"mixamorig:LeftHand","contact":"hand"},
               "right_hand":{"rootBone":"mixamorig:RightArm","effectorBone":"mixamorig:RightHand","contact":"hand"}}}
            """;
        Quaternion toBallistic = zUpScene ? Quaternion.CreateFromAxisAngle(Vector3.UnitX, -90f * Degree) : Quaternion.Identity;
        return new ForeignCharacter(zUpScene ? "human-zup" : "human", r, spec, toBallistic, "mixamorig:Hips", "mixamorig:Head", "mixamorig:LeftFoot", "mixamorig:LeftToeBase", [.. trunk], [.. feet], External: false, ByteWeights: false);
    }

    public static ForeignCharacter Dog()
    {
        var r = new ForeignRig();
        const float Degree = MathF.PI / 180f;
        int pelvis = r.BoneAt("pelvis", -1, -1, new(0, 0.55f, -0.3f), new(0, 0.56f, 0));
        int spine = r.BoneAt("spine", pelvis, -1, new(0, 0.56f, 0), new(0, 0.58f, 0.3f));
        int chest = r.BoneAt("chest", spine, -1, new(0, 0.58f, 0.3f), new(0, 0.66f, 0.42f), asMatrix: true);
        int neck = r.BoneAt("neck", chest, -1, new(0, 0.66f, 0.42f), new(0, 0.74f, 0.5f));
        int head = r.BoneAt("head", neck, -1, new(0, 0.74f, 0.5f), new(0, 0.74f, 0.66f));
        r.Box(pelvis, -1, new(-0.12f, 0.45f, -0.42f), new(0.12f, 0.62f, -0.15f));
        r.Box(spine, -1, new(-0.12f, 0.46f, -0.15f), new(0.12f, 0.63f, 0.15f), pelvis);
        r.Box(chest, -1, new(-0.13f, 0.46f, 0.15f), new(0.13f, 0.66f, 0.42f), spine);
        r.Box(neck, -1, new(-0.05f, 0.62f, 0.42f), new(0.05f, 0.74f, 0.5f));
        r.Box(head, -1, new(-0.07f, 0.68f, 0.48f), new(0.07f, 0.8f, 0.7f));
        var feet = new List<ForeignFoot>();
        foreach ((string side, float s) in new[] { ("left", 1f), ("right", -1f) })
        {
            float x = 0.1f * s;
            int hip = r.BoneAt($"{side}_hip", pelvis, -1, new(x, 0.5f, -0.3f), new(x, 0.3f, -0.25f));
            int knee = r.BoneAt($"{side}_knee", hip, -1, new(x, 0.3f, -0.25f), new(x, 0.12f, -0.33f), twist: 0.5f);
            int hock = r.BoneAt($"{side}_hock", knee, -1, new(x, 0.12f, -0.33f), new(x, 0.05f, -0.3f));
            int anchor = r.Node($"{side}_hind_foot_anchor", hock, new(0f, 0.04f, 0.01f), Quaternion.CreateFromAxisAngle(Vector3.UnitX, 25f * Degree));
            if (s > 0f)
            {
                anchor = r.Node($"{side}_hind_foot_anchor_offset", anchor, new(0.005f, 0.01f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 10f * Degree));
            }

            int paw = r.BoneAt($"{side}_hind_paw", anchor, -1, new(x, 0.04f, -0.29f), new(x, 0.03f, -0.2f), twist: 0.3f);
            int toes = r.BoneAt($"{side}_hind_toes", paw, -1, new(x, 0.03f, -0.2f), new(x, 0.02f, -0.16f));
            r.Box(hip, -1, new(x - 0.04f, 0.3f, -0.33f), new(x + 0.04f, 0.52f, -0.2f), pelvis, 0.2f);
            r.Box(knee, -1, new(x - 0.03f, 0.12f, -0.36f), new(x + 0.03f, 0.3f, -0.22f));
            r.Box(hock, -1, new(x - 0.025f, 0.05f, -0.35f), new(x + 0.025f, 0.12f, -0.28f), knee);
            r.Box(paw, -1, new(x - 0.035f, 0f, -0.33f), new(x + 0.035f, 0.05f, -0.2f), hock, 0.2f);
            r.Box(toes, -1, new(x - 0.035f, 0f, -0.2f), new(x + 0.035f, 0.03f, -0.16f), paw);
            feet.Add(new ForeignFoot($"{side}_hind", [$"{side}_hind_paw", $"{side}_hind_toes"]));

            int shoulder = r.BoneAt($"{side}_shoulder", chest, -1, new(x, 0.5f, 0.3f), new(x, 0.3f, 0.28f));
            int elbow = r.BoneAt($"{side}_elbow", shoulder, -1, new(x, 0.3f, 0.28f), new(x, 0.1f, 0.3f));
            int wrist = r.BoneAt($"{side}_wrist", elbow, -1, new(x, 0.1f, 0.3f), new(x, 0.04f, 0.32f), twist: -0.6f);

            // The right front anchor is scaled by half (a uniform scale on a non-bone node, as some exporters write).
            int frontAnchor = r.Node($"{side}_front_foot_anchor", wrist, new(0f, 0.03f, 0f), Quaternion.CreateFromAxisAngle(Vector3.UnitX, -20f * Degree), s > 0f ? 1f : 0.5f);
            int frontPaw = r.BoneAt($"{side}_front_paw", frontAnchor, -1, new(x, 0.04f, 0.32f), new(x, 0.03f, 0.38f));
            r.Box(shoulder, -1, new(x - 0.04f, 0.3f, 0.22f), new(x + 0.04f, 0.52f, 0.34f), chest, 0.2f);
            r.Box(elbow, -1, new(x - 0.03f, 0.1f, 0.24f), new(x + 0.03f, 0.3f, 0.33f));
            r.Box(wrist, -1, new(x - 0.025f, 0.04f, 0.27f), new(x + 0.025f, 0.1f, 0.35f), elbow);
            r.Box(frontPaw, -1, new(x - 0.035f, 0f, 0.28f), new(x + 0.035f, 0.04f, 0.4f), wrist, 0.2f);
            feet.Add(new ForeignFoot($"{side}_front", [$"{side}_front_paw"]));
        }

        string spec = """
            {"schema":"ballistic.character/1","name":"dog","requiredContacts":2,"takeoffSpeedMax":8,"landingSpeedMax":12,
             "limbs":{
               "left_hind":{"rootBone":"left_hip","effectorBone":"left_hind_paw"},
               "right_hind":{"rootBone":"right_hip","effectorBone":"right_hind_paw","contact":"foot"},
               "left_front":{"rootBone":"left_shoulder","effectorBone":"left_front_paw"},
               "right_front":{"rootBone":"right_shoulder","effectorBone":"right_front_paw"}}}
            """;
        return new ForeignCharacter("dog", r, spec, Quaternion.Identity, "pelvis", "head", "pelvis", "head", ["pelvis", "spine", "chest"], [.. feet], External: true, ByteWeights: false);
    }

    public static ForeignCharacter TailedQuadruped()
    {
        var r = new ForeignRig();
        const float Degree = MathF.PI / 180f;
        int arm = r.Node("Armature", -1, new Vector3(1f, 0f, 2f), Quaternion.CreateFromAxisAngle(Vector3.UnitY, 90f * Degree), asMatrix: true);
        int tailRoot = r.BoneAt("tail_root", arm, arm, new(0, 0.3f, -0.3f), new(0, 0.28f, -0.5f));
        int tail1 = r.BoneAt("tail_1", tailRoot, arm, new(0, 0.28f, -0.5f), new(0, 0.25f, -0.7f));
        int tail2 = r.BoneAt("tail_2", tail1, arm, new(0, 0.25f, -0.7f), new(0, 0.22f, -0.9f));
        int ik = r.BoneAt("ik_target", arm, arm, new(0, 0f, 0.6f), new(0, 0.1f, 0.6f));
        int hips = r.BoneAt("hips", arm, arm, new(0, 0.3f, -0.2f), new(0, 0.32f, 0.2f));
        int chest = r.BoneAt("chest", hips, arm, new(0, 0.32f, 0.2f), new(0, 0.34f, 0.4f));
        int head = r.BoneAt("head", chest, arm, new(0, 0.34f, 0.4f), new(0, 0.36f, 0.55f));
        r.Box(hips, arm, new(-0.1f, 0.22f, -0.3f), new(0.1f, 0.38f, 0f));
        r.Box(chest, arm, new(-0.1f, 0.24f, 0f), new(0.1f, 0.4f, 0.4f), hips);
        r.Box(head, arm, new(-0.06f, 0.3f, 0.4f), new(0.06f, 0.4f, 0.6f));
        r.Box(tailRoot, arm, new(-0.05f, 0.25f, -0.5f), new(0.05f, 0.33f, -0.3f));
        r.Box(tail1, arm, new(-0.04f, 0.22f, -0.7f), new(0.04f, 0.3f, -0.5f), tailRoot);
        r.Box(tail2, arm, new(-0.03f, 0.2f, -0.9f), new(0.03f, 0.26f, -0.7f), tail1);
        var feet = new List<ForeignFoot>();
        var legs = new List<int>();
        foreach ((string side, float s) in new[] { ("left", 1f), ("right", -1f) })
        {
            float x = 0.09f * s;
            int thigh = r.BoneAt($"{side}_thigh", hips, arm, new(x, 0.28f, -0.2f), new(x, 0.15f, -0.22f));
            int shin = r.BoneAt($"{side}_shin", thigh, arm, new(x, 0.15f, -0.22f), new(x, 0.04f, -0.2f));
            int foot = r.BoneAt($"{side}_foot", shin, arm, new(x, 0.04f, -0.2f), new(x, 0.02f, -0.12f));
            int upper = r.BoneAt($"{side}_upper_arm", chest, arm, new(x, 0.3f, 0.2f), new(x, 0.15f, 0.22f));
            int fore = r.BoneAt($"{side}_forearm", upper, arm, new(x, 0.15f, 0.22f), new(x, 0.04f, 0.22f));
            int hand = r.BoneAt($"{side}_hand", fore, arm, new(x, 0.04f, 0.22f), new(x, 0.02f, 0.3f));
            r.Box(thigh, arm, new(x - 0.03f, 0.15f, -0.24f), new(x + 0.03f, 0.3f, -0.16f), hips, 0.2f);
            r.Box(shin, arm, new(x - 0.025f, 0.04f, -0.25f), new(x + 0.025f, 0.15f, -0.17f));
            r.Box(foot, arm, new(x - 0.035f, 0f, -0.24f), new(x + 0.035f, 0.04f, -0.08f), shin, 0.2f);
            r.Box(upper, arm, new(x - 0.03f, 0.15f, 0.17f), new(x + 0.03f, 0.3f, 0.25f), chest, 0.2f);
            r.Box(fore, arm, new(x - 0.025f, 0.04f, 0.18f), new(x + 0.025f, 0.15f, 0.26f));
            r.Box(hand, arm, new(x - 0.035f, 0f, 0.18f), new(x + 0.035f, 0.04f, 0.34f), fore, 0.2f);
            legs.AddRange([thigh, shin, foot, upper, fore, hand]);
            feet.Add(new ForeignFoot($"{side}_hind", [$"{side}_foot"]));
            feet.Add(new ForeignFoot($"{side}_front", [$"{side}_hand"]));
        }

        // The skin lists the tail chain and the IK target before the hips: three root bones under the armature.
        r.SkinOrder = [tailRoot, tail1, tail2, ik, hips, chest, head, .. legs];
        string spec = """
            {"schema":"ballistic.character/1","name":"tailed","forwardAxis":"+X","requiredContacts":3,"takeoffSpeedMax":8,"landingSpeedMax":12,
             "limbs":{
               "left_hind":{"rootBone":"left_thigh","effectorBone":"left_foot"},
               "right_hind":{"rootBone":"right_thigh","effectorBone":"right_foot"},
               "left_front":{"rootBone":"left_upper_arm","effectorBone":"left_hand"},
               "right_front":{"rootBone":"right_upper_arm","effectorBone":"right_hand"}}}
            """;
        return new ForeignCharacter("tailed", r, spec, Quaternion.CreateFromAxisAngle(Vector3.UnitY, -90f * Degree), "hips", "head", "hips", "head", ["hips", "chest"], [.. feet], External: false, ByteWeights: true);
    }

    /// <summary>
    /// A rat 17 cm long (hips 4.5 cm above the ground) whose tail, a chain of four bones, rests on the ground behind it
    /// in the rest pose, as a modeller leaves a tail lying on the floor: the skin of its last three bones reaches 1–2 mm below its soles. Its
    /// limbs-only spec gives no speeds, no poses and nothing for the tail.
    /// </summary>
    public static ForeignCharacter Rat()
    {
        var r = new ForeignRig();
        int hips = r.BoneAt("pelvis", -1, -1, new(0, 0.045f, -0.05f), new(0, 0.047f, 0.02f));
        int chest = r.BoneAt("spine", hips, -1, new(0, 0.047f, 0.02f), new(0, 0.05f, 0.07f));
        int head = r.BoneAt("skull", chest, -1, new(0, 0.05f, 0.07f), new(0, 0.045f, 0.12f));
        r.Box(hips, -1, new(-0.028f, 0.025f, -0.07f), new(0.028f, 0.065f, 0.02f));
        r.Box(chest, -1, new(-0.026f, 0.027f, 0.02f), new(0.026f, 0.066f, 0.07f), hips);
        r.Box(head, -1, new(-0.018f, 0.03f, 0.07f), new(0.018f, 0.062f, 0.12f), chest);
        int tail = hips;
        Vector3 from = new(0, 0.04f, -0.07f);
        Vector3[] tailPoints = [new(0, 0.022f, -0.11f), new(0, 0.004f, -0.15f), new(0, 0.002f, -0.19f), new(0, 0.001f, -0.23f)];
        for (int i = 0; i < tailPoints.Length; i++)
        {
            int bone = r.BoneAt($"tail_{i + 1:00}", tail, -1, from, tailPoints[i]);
            float w = 0.006f - (0.001f * i);
            Vector3 lo = Vector3.Min(from, tailPoints[i]);
            Vector3 hi = Vector3.Max(from, tailPoints[i]);
            r.Box(bone, -1, new(-w, lo.Y - w, lo.Z), new(w, hi.Y + w, hi.Z), tail == hips ? -1 : tail);
            tail = bone;
            from = tailPoints[i];
        }

        var feet = new List<ForeignFoot>();
        foreach ((string side, float s) in new[] { ("l", 1f), ("r", -1f) })
        {
            float x = 0.022f * s;
            int thigh = r.BoneAt($"thigh_{side}", hips, -1, new(x, 0.04f, -0.045f), new(x, 0.024f, -0.035f));
            int shin = r.BoneAt($"shin_{side}", thigh, -1, new(x, 0.024f, -0.035f), new(x, 0.008f, -0.048f));
            int foot = r.BoneAt($"hindpaw_{side}", shin, -1, new(x, 0.008f, -0.048f), new(x, 0.003f, -0.028f));
            int upper = r.BoneAt($"humerus_{side}", chest, -1, new(x, 0.042f, 0.05f), new(x, 0.025f, 0.045f));
            int fore = r.BoneAt($"radius_{side}", upper, -1, new(x, 0.025f, 0.045f), new(x, 0.007f, 0.05f));
            int hand = r.BoneAt($"forepaw_{side}", fore, -1, new(x, 0.007f, 0.05f), new(x, 0.003f, 0.062f));
            r.Box(thigh, -1, new(x - 0.008f, 0.024f, -0.05f), new(x + 0.008f, 0.042f, -0.03f), hips, 0.2f);
            r.Box(shin, -1, new(x - 0.006f, 0.008f, -0.054f), new(x + 0.006f, 0.024f, -0.032f));
            r.Box(foot, -1, new(x - 0.008f, 0f, -0.054f), new(x + 0.008f, 0.008f, -0.024f), shin, 0.2f);
            r.Box(upper, -1, new(x - 0.007f, 0.025f, 0.038f), new(x + 0.007f, 0.044f, 0.056f), chest, 0.2f);
            r.Box(fore, -1, new(x - 0.006f, 0.007f, 0.04f), new(x + 0.006f, 0.025f, 0.056f));
            r.Box(hand, -1, new(x - 0.007f, 0f, 0.044f), new(x + 0.007f, 0.007f, 0.066f), fore, 0.2f);
            feet.Add(new ForeignFoot($"{side}_hind", [$"hindpaw_{side}"]));
            feet.Add(new ForeignFoot($"{side}_front", [$"forepaw_{side}"]));
        }

        string spec = """
            {"schema":"ballistic.character/1","name":"rat",
             "limbs":{
               "l_hind":{"rootBone":"thigh_l","effectorBone":"hindpaw_l"},
               "r_hind":{"rootBone":"thigh_r","effectorBone":"hindpaw_r"},
               "l_front":{"rootBone":"humerus_l","effectorBone":"forepaw_l"},
               "r_front":{"rootBone":"humerus_r","effectorBone":"forepaw_r"}}}
            """;
        return new ForeignCharacter("rat", r, spec, Quaternion.Identity, "pelvis", "skull", "pelvis", "skull", ["pelvis", "spine"], [.. feet], External: false, ByteWeights: false);
    }

    /// <summary>
    /// A giant spider (a game's enemy: 1.5 m across its legs, its body 0.35 m above the ground) with eight legs spread
    /// in its rest pose, each a femur rising to a knee above the body and a tibia and tarsus falling to the ground, as
    /// spiders are modelled; each segment's skin a box along its bone. Its limbs-only spec gives nothing but the legs.
    /// </summary>
    public static ForeignCharacter Spider()
    {
        var r = new ForeignRig();
        const float Degree = MathF.PI / 180f;
        int thorax = r.BoneAt("cephalothorax", -1, -1, new(0, 0.35f, -0.05f), new(0, 0.36f, 0.2f));
        int abdomen = r.BoneAt("abdomen", thorax, -1, new(0, 0.37f, -0.05f), new(0, 0.4f, -0.45f));
        r.Box(thorax, -1, new(-0.14f, 0.28f, -0.08f), new(0.14f, 0.42f, 0.22f));
        r.Box(abdomen, -1, new(-0.15f, 0.3f, -0.5f), new(0.15f, 0.5f, -0.08f), thorax);
        var feet = new List<ForeignFoot>();
        var limbs = new List<string>();
        foreach ((string side, float s) in new[] { ("l", 1f), ("r", -1f) })
        {
            float[] angles = [35f, 70f, 105f, 140f];
            for (int n = 0; n < angles.Length; n++)
            {
                Vector3 d = new(s * MathF.Sin(angles[n] * Degree), 0f, MathF.Cos(angles[n] * Degree));
                Vector3 p0 = new Vector3(0f, 0.34f, 0.07f) + (d * 0.12f);
                Vector3 p1 = p0 + (d * 0.22f) + new Vector3(0f, 0.18f, 0f);
                Vector3 p2 = p1 + (d * 0.3f) + new Vector3(0f, -0.44f, 0f);
                Vector3 p3 = p2 + (d * 0.06f) + new Vector3(0f, -0.08f, 0f);
                string leg = $"{side}{n + 1}";
                int femur = r.BoneAt($"leg_{leg}_femur", thorax, -1, p0, p1);
                int tibia = r.BoneAt($"leg_{leg}_tibia", femur, -1, p1, p2);
                int tarsus = r.BoneAt($"leg_{leg}_tarsus", tibia, -1, p2, p3);
                foreach ((int bone, float length, float radius, int blend) in new[] { (femur, Vector3.Distance(p0, p1), 0.03f, thorax), (tibia, Vector3.Distance(p1, p2), 0.025f, femur), (tarsus, Vector3.Distance(p2, p3), 0.018f, tibia) })
                {
                    r.BoxAlong(bone, length, radius, blend, 0.2f);
                }

                feet.Add(new ForeignFoot(leg, [$"leg_{leg}_tarsus"]));
                limbs.Add($"\"{leg}\":{{\"rootBone\":\"leg_{leg}_femur\",\"effectorBone\":\"leg_{leg}_tarsus\"}}");
            }
        }

        string spec = "{\"schema\":\"ballistic.character/1\",\"name\":\"spider\",\"limbs\":{" + string.Join(",", limbs) + "}}";
        return new ForeignCharacter("spider", r, spec, Quaternion.Identity, "cephalothorax", "cephalothorax", "abdomen", "cephalothorax", ["cephalothorax", "abdomen"], [.. feet], External: false, ByteWeights: false);
    }

    /// <summary>
    /// A stocky quadruped 1.2 m long rigged as Rigify and similar tools rig one (issue 24's panda): a root bone on the
    /// ground carrying the torso and, beside it, a foot IK helper and a knee pole for each leg (bones with no skin,
    /// outside the legs' chains), bone names with ".L"/".R", and modelled mid-stride: the left front and right hind
    /// feet a step ahead of their hips, the other two a step behind, so its rest pose (its default contact pose) is not
    /// symmetric. Its limbs-only spec names the legs from thigh to foot and nothing else.
    /// </summary>
    public static ForeignCharacter Panda()
    {
        var r = new ForeignRig();
        int root = r.BoneAt("root", -1, -1, new(0, 0, -0.3f), new(0, 0, 0.1f));
        int torso = r.BoneAt("torso", root, -1, new(0, 0.6f, -0.35f), new(0, 0.62f, 0f));
        int chest = r.BoneAt("chest", torso, -1, new(0, 0.62f, 0f), new(0, 0.64f, 0.35f));
        int neck = r.BoneAt("neck", chest, -1, new(0, 0.64f, 0.35f), new(0, 0.72f, 0.48f));
        int head = r.BoneAt("head", neck, -1, new(0, 0.72f, 0.48f), new(0, 0.74f, 0.7f));
        r.Box(torso, -1, new(-0.24f, 0.42f, -0.5f), new(0.24f, 0.8f, 0f));
        r.Box(chest, -1, new(-0.24f, 0.44f, 0f), new(0.24f, 0.82f, 0.38f), torso);
        r.Box(neck, -1, new(-0.1f, 0.6f, 0.36f), new(0.1f, 0.8f, 0.5f), chest);
        r.Box(head, -1, new(-0.15f, 0.6f, 0.48f), new(0.15f, 0.88f, 0.74f));
        var feet = new List<ForeignFoot>();
        foreach ((string end, float z) in new[] { ("front", 0.25f), ("hind", -0.38f) })
        {
            foreach ((string side, float s) in new[] { ("L", 1f), ("R", -1f) })
            {
                // Mid-stride: the left front and the right hind foot ahead, the others behind.
                float stride = (end == "front") == (s > 0f) ? 0.16f : -0.16f;
                float x = 0.16f * s;
                int parent = end == "front" ? chest : torso;
                string thighName = end == "front" ? "upper_arm" : "thigh";
                string shinName = end == "front" ? "forearm" : "shin";
                string footName = end == "front" ? "hand" : "foot";
                Vector3 hip = new(x, 0.5f, z);
                Vector3 knee = new(x, 0.27f, z + (0.45f * stride) + (end == "front" ? -0.02f : 0.05f));
                Vector3 ankle = new(x, 0.06f, z + stride);
                Vector3 toe = new(x, 0.02f, z + stride + 0.14f);
                int thigh = r.BoneAt($"{thighName}.{side}", parent, -1, hip, knee);
                int shin = r.BoneAt($"{shinName}.{side}", thigh, -1, knee, ankle);
                int foot = r.BoneAt($"{footName}.{side}", shin, -1, ankle, toe);
                r.BoxAlong(thigh, Vector3.Distance(hip, knee), 0.07f, parent, 0.2f);
                r.BoxAlong(shin, Vector3.Distance(knee, ankle), 0.055f, thigh);
                r.Box(foot, -1, new(x - 0.07f, 0f, z + stride - 0.06f), new(x + 0.07f, 0.08f, z + stride + 0.16f), shin, 0.2f);
                r.BoneAt($"{footName}_ik.{side}", root, -1, ankle, ankle + new Vector3(0f, 0f, 0.12f));
                r.BoneAt($"{(end == "front" ? "elbow" : "knee")}_pole.{side}", root, -1, knee + new Vector3(0f, 0f, end == "front" ? -0.4f : 0.4f), knee + new Vector3(0f, 0f, end == "front" ? -0.5f : 0.5f));
                feet.Add(new ForeignFoot($"{end}_{side}", [$"{footName}.{side}"]));
            }
        }

        string spec = """
            {"schema":"ballistic.character/1","name":"panda",
             "limbs":{
               "front_L":{"rootBone":"upper_arm.L","effectorBone":"hand.L"},
               "front_R":{"rootBone":"upper_arm.R","effectorBone":"hand.R"},
               "hind_L":{"rootBone":"thigh.L","effectorBone":"foot.L"},
               "hind_R":{"rootBone":"thigh.R","effectorBone":"foot.R"}}}
            """;
        return new ForeignCharacter("panda", r, spec, Quaternion.Identity, "root", "head", "torso", "head", ["torso", "chest"], [.. feet], External: false, ByteWeights: false);
    }
}
