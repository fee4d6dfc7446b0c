using System.Numerics;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using System.Text.Json.Nodes;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Gltf;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// The limb spec (<c>ballistic.character/1</c> JSON) that turns any rigged glTF character into a
/// <see cref="CharacterModel"/>: for each limb its root bone, effector bone, contact point offset and contact normal
/// in the effector bone's frame, contact kind and normal filter; optionally the glTF scene's up and forward axes,
/// the degrees of freedom and limits of bones (degrees; limb bones not listed become ball joints of ±90°, other
/// bones are fixed), the trunk bones, bone radii and the reference poses. Bones are the glTF skin's joints, matched
/// by node name; a bone's rig parent is its nearest ancestor that is a bone (nodes in between, such as anchors, are
/// folded into its rest offset and rotation), and when the skin has several root bones the one with the most limb
/// bones below it is the rig's root joint, which the trunk box follows, the others hanging from it rigidly.
/// What the spec leaves out is derived from the skinned mesh in the rest pose (see the README's "Characters").
/// </summary>
public static class CharacterSpecFile
{
    /// <summary>The schema name of spec files.</summary>
    public const string Schema = "ballistic.character/1";

    /// <summary>Radius of a bone without skinned vertices when the spec gives none, metres.</summary>
    public const float DefaultBoneRadius = 0.03f;

    /// <summary>
    /// Loads a character from its limb spec alone: the rigged glTF is the one the spec's <c>rig</c> key names (relative to
    /// the spec's folder, and never outside it), or, without that key, <c>NAME.glb</c> or <c>NAME.gltf</c> beside a spec
    /// named <c>NAME.limbs.json</c> (or <c>NAME.json</c>). Otherwise as <see cref="Load(string, string, GltfLoadOptions?)"/>.
    /// </summary>
    /// <param name="specPath">The limb spec (<c>ballistic.character/1</c> JSON).</param>
    /// <param name="options">Limits on the bytes and vertices read; <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="RigException">The spec or its rig is unusable or missing; the message names the file and the key.</exception>
    public static (CharacterModel Model, ReducedCharacter Reduced) Load(string specPath, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(specPath);
        return Load(RigOf(specPath, options ?? GltfLoadOptions.Default), specPath, options);
    }

    /// <summary>The rigged glTF of the spec at <paramref name="specPath"/> (<see cref="Load(string, GltfLoadOptions?)"/>).</summary>
    private static string RigOf(string specPath, GltfLoadOptions options)
    {
        string printable = MessageText.Printable(specPath);
        byte[] bytes = InputFile.Read(specPath, options.MaxBytes, "GltfLoadOptions.MaxBytes", (phrase, e) => new RigException($"Limb spec {printable} {phrase}.", e!));
        CharacterSpec spec = CharacterSpecReader.Read(bytes, printable);
        string folder = Path.GetDirectoryName(Path.GetFullPath(specPath)) ?? ".";
        if (spec.Rig is string rig)
        {
            string path = ReferencedFile.Resolve(folder, rig, phrase => new RigException(MessageText.Printable($"{specPath}: key 'rig': '{rig}' {phrase.Replace("the glTF's folder", "the spec's folder", StringComparison.Ordinal)}.")));
            return File.Exists(path) ? path : throw new RigException(MessageText.Printable($"{specPath}: key 'rig' names '{rig}', which does not exist in the spec's folder."));
        }

        string name = Path.GetFileName(specPath);
        string stem = name.EndsWith(".limbs.json", StringComparison.OrdinalIgnoreCase) ? name[..^".limbs.json".Length]
            : name.EndsWith(".json", StringComparison.OrdinalIgnoreCase) ? name[..^".json".Length] : name;
        return new[] { stem + ".glb", stem + ".gltf" }.Select(f => Path.Combine(folder, f)).FirstOrDefault(File.Exists)
            ?? throw new RigException(MessageText.Printable($"{specPath} needs its rigged character: give its path as key 'rig', or put it beside the spec as {stem}.glb or {stem}.gltf."));
    }

    /// <summary>
    /// Loads a character from a rigged glTF file and its limb spec. The model's <see cref="CharacterModel.Source"/>
    /// is the glTF, so the animated GLB carries its meshes.
    /// </summary>
    /// <param name="gltfPath">The rigged <c>.glb</c> or <c>.gltf</c>.</param>
    /// <param name="specPath">The limb spec (<c>ballistic.character/1</c> JSON).</param>
    /// <param name="options">Limits on the bytes and vertices read (the spec is held to <see cref="GltfLoadOptions.MaxBytes"/> too); <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="RigException">The spec or the glTF rig is unusable; the message names the file, the limb or bone and the key.</exception>
    public static (CharacterModel Model, ReducedCharacter Reduced) Load(string gltfPath, string specPath, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(gltfPath);
        ArgumentNullException.ThrowIfNull(specPath);
        try
        {
            return LoadFiles(gltfPath, specPath, options ?? GltfLoadOptions.Default);
        }
        catch (RigException e) when (e.Message.Any(char.IsControl))
        {
            // A limb, bone or node name from the files may hold a line break: the message stays one line.
            throw new RigException(MessageText.Printable(e.Message), e);
        }
    }

    /// <summary>
    /// Loads a character from the bytes of a rigged glTF and of its limb spec, read by the caller (e.g. an exported
    /// game reading its packed files): the same checks and result as <see cref="Load(string, string, GltfLoadOptions?)"/>.
    /// The glTF must hold its buffers (a <c>.glb</c>, or a <c>.gltf</c> with data URIs): with no folder to resolve
    /// them against, a reference to an external file is refused.
    /// </summary>
    /// <param name="gltfBytes">The rigged <c>.glb</c> (or self-contained <c>.gltf</c>) content.</param>
    /// <param name="gltfName">Names the glTF in messages (e.g. its <c>res://</c> path).</param>
    /// <param name="specBytes">The limb spec's content (<c>ballistic.character/1</c> JSON).</param>
    /// <param name="specName">Names the limb spec in messages (e.g. its <c>res://</c> path).</param>
    /// <param name="options">Limits on the bytes and vertices read; <c>null</c> for <see cref="GltfLoadOptions.Default"/>.</param>
    /// <exception cref="RigException">The spec or the glTF rig is unusable; the message names the file, the limb or bone and the key.</exception>
    public static (CharacterModel Model, ReducedCharacter Reduced) FromBytes(byte[] gltfBytes, string gltfName, byte[] specBytes, string specName, GltfLoadOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(gltfBytes);
        ArgumentNullException.ThrowIfNull(gltfName);
        ArgumentNullException.ThrowIfNull(specBytes);
        ArgumentNullException.ThrowIfNull(specName);
        GltfLoadOptions limits = options ?? GltfLoadOptions.Default;
        try
        {
            if (specBytes.LongLength > limits.MaxBytes)
            {
                throw new RigException($"Limb spec {specName} is {specBytes.LongLength} bytes, more than the {limits.MaxBytes} bytes allowed (GltfLoadOptions.MaxBytes).");
            }

            return LoadParts(specBytes, specName, () => GltfModel.Parse(gltfBytes, gltfName, null, limits));
        }
        catch (RigException e) when (e.Message.Any(char.IsControl))
        {
            throw new RigException(MessageText.Printable(e.Message), e);
        }
    }

    private static (CharacterModel Model, ReducedCharacter Reduced) LoadFiles(string gltfPath, string specPath, GltfLoadOptions options)
    {
        byte[] bytes = InputFile.Read(specPath, options.MaxBytes, "GltfLoadOptions.MaxBytes", (problem, e) => new RigException($"Limb spec {specPath} {problem}.", e!));
        return LoadParts(bytes, specPath, () => GltfModel.Load(gltfPath, options));
    }

    /// <summary>Parses the spec, then reads the glTF with <paramref name="readDocument"/> and builds the character.</summary>
    private static (CharacterModel Model, ReducedCharacter Reduced) LoadParts(byte[] specBytes, string specPath, Func<GltfModel> readDocument)
    {
        CharacterSpec spec = CharacterSpecReader.Read(specBytes, specPath);
        GltfModel document;
        try
        {
            document = readDocument();
        }
        catch (GltfException e)
        {
            throw new RigException(e.Message, e);
        }

        try
        {
            return Build(document, spec, specPath);
        }
        catch (GltfException e)
        {
            throw new RigException(e.Message, e);
        }
        catch (CharacterException e)
        {
            throw new RigException($"{specPath}: {e.Message}", e);
        }
        catch (Exception e) when (e is not BallisticInputException and not OutOfMemoryException and not InsufficientExecutionStackException)
        {
            // A last guard so that a game never sees a runtime error from input: the fuzz tests fail on any input
            // that reaches it, so each such input gets its own check and message.
            throw new RigException($"{document.Name}: the rig cannot be read with {specPath}: the glTF's JSON has an unexpected shape ({e.GetType().Name}).", e);
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

        // A character loaded from a glTF leaves out the radii it derived from the mesh (a reload derives them again)
        // and lists its fixed limb bones (a reload would otherwise make them ball joints).
        CharacterSource? source = model.Source;
        var joints = new JsonObject();
        var radii = new JsonObject();
        for (int j = 0; j < rig.Joints.Count; j++)
        {
            if (source is null || j >= source.DerivedRadii.Count || !source.DerivedRadii[j])
            {
                radii[rig.Joints[j].Name] = model.BoneRadii[j];
            }

            if (rig.DofsOf(j) == 0)
            {
                if (source is not null && model.Limbs.Any(l => l.Chain.Contains(j)))
                {
                    joints[rig.Joints[j].Name] = new JsonObject { ["axes"] = new JsonArray() };
                }

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
            ["walkSpeed"] = reduced.Walking.Speed,
            ["maxSlope"] = reduced.Walking.MaxSlopeDegrees,
            ["maxSlopeAlong"] = reduced.Walking.MaxSlopeAlongDegrees,
            ["stepHeight"] = reduced.Walking.StepHeight,
            ["trunkBones"] = new JsonArray([.. model.TrunkJoints.Select(j => (JsonNode)JsonValue.Create(rig.Joints[j].Name))]),
            ["limbs"] = limbs,
            ["joints"] = joints,
            ["boneRadii"] = radii,
            ["poses"] = new JsonObject { ["contact"] = Pose(rig, model.ContactPose), ["flexion"] = Pose(rig, model.FlexionPose), ["extending"] = Pose(rig, model.ExtendingPose) },
        };
        if (source is not null && (source.UpAxis != "+Y" || source.ForwardAxis != "+Z"))
        {
            // The axes go third and fourth, after schema and name (JsonObject.Insert is .NET 9 and later).
            KeyValuePair<string, JsonNode?>[] entries = [.. root];
            root.Clear();
            for (int i = 0; i < entries.Length; i++)
            {
                if (i == 2)
                {
                    root["upAxis"] = source.UpAxis;
                    root["forwardAxis"] = source.ForwardAxis;
                }

                root.Add(entries[i]);
            }
        }

        return Encoding.UTF8.GetBytes(root.ToJsonString(new JsonSerializerOptions { WriteIndented = true, Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping }) + "\n");
    }

    private static (CharacterModel, ReducedCharacter) Build(GltfModel document, CharacterSpec spec, string specPath)
    {
        string file = document.Name;
        RigException Error(string where, string problem) => new($"{specPath}: {where}: {problem}");
        T Named<T>(Func<T> make)
        {
            try
            {
                return make();
            }
            catch (RigException e) when (!e.Message.StartsWith(specPath, StringComparison.Ordinal))
            {
                throw new RigException($"{specPath}: {e.Message}", e);
            }
        }

        Quaternion axes = AxesRotation(spec.UpAxis, spec.ForwardAxis);
        GltfSkeleton skeleton = GltfSkeleton.Read(document, axes, [.. spec.Limbs.SelectMany(l => new[] { l.RootBone, l.EffectorBone })]);
        string[] names = skeleton.Names;
        int IndexOf(string bone) => Array.IndexOf(names, bone);
        int Bone(string bone, string where) => IndexOf(bone) is int i && i >= 0 ? i : throw Error(where, $"'{bone}' is not a bone of {file}.");

        // Bones on limb chains move by default; the spec may give any bone its own axes.
        foreach (LimbSpec limb in spec.Limbs)
        {
            _ = IndexOf(limb.EffectorBone) is int e && e >= 0 ? e : throw Error($"limb '{limb.Name}'", $"names the effector bone '{limb.EffectorBone}', which is not a bone of {file}.");
            _ = IndexOf(limb.RootBone) is int r && r >= 0 ? r : throw Error($"limb '{limb.Name}'", $"names the root bone '{limb.RootBone}', which is not a bone of {file}.");
            if (string.Equals(limb.RootBone, limb.EffectorBone, StringComparison.Ordinal))
            {
                throw Error($"limb '{limb.Name}'", $"names '{limb.EffectorBone}' as both its rootBone and its effectorBone; the chain runs from the bone the limb starts at (a hip or shoulder) down to its effector: give that bone as rootBone.");
            }
        }

        CheckLimbChains(spec, skeleton.Parents, names, IndexOf, Error);

        foreach (string bone in spec.Joints.Keys)
        {
            Bone(bone, $"joints, bone '{bone}'");
        }

        foreach (string bone in spec.BoneRadii.Keys)
        {
            Bone(bone, $"boneRadii, bone '{bone}'");
        }

        // Limb bones the spec gives no axes: hips, hinges and ball joints derived from the rest pose (LimbJointAxes);
        // a spec that gives none at all also gets free bends for its tails and heads.
        Joint[] bare = [.. names.Select((n, j) => new Joint(n, skeleton.Parents[j], skeleton.Offsets[j], skeleton.RestRotations[j], []))];
        Dictionary<int, JointAxis[]> derivedAxes = LimbJointAxes.Derive(bare, [.. spec.Limbs.Select(l => (l.Kind, IndexOf(l.RootBone), IndexOf(l.EffectorBone)))], free: spec.Joints.Count == 0, trunk: spec.TrunkBones?.Select(IndexOf).ToArray());
        var joints = new List<Joint>();
        for (int j = 0; j < names.Length; j++)
        {
            JointAxis[] axesOf = spec.Joints.TryGetValue(names[j], out JointAxis[]? given) ? given : derivedAxes.TryGetValue(j, out JointAxis[]? derived) ? derived : [];
            joints.Add(bare[j] with { Axes = axesOf });
        }

        // Radii: the spec's, else from the skinned vertices, else the spec's boneRadius or the default.
        float?[] meshRadii = MeshDefaults.Radii(joints, skeleton.Points);
        float fallbackRadius = spec.BoneRadius ?? DefaultBoneRadius;
        float[] radii = [.. names.Select((n, j) => spec.BoneRadii.TryGetValue(n, out float r) ? r : meshRadii[j] ?? fallbackRadius)];
        bool[] derivedRadii = [.. names.Select((n, j) => !spec.BoneRadii.ContainsKey(n) && meshRadii[j] is not null)];

        // Trunk: the spec's bones, else the root and every bone above a limb's root bone.
        var trunk = new List<int>();
        if (spec.TrunkBones is not null)
        {
            foreach (string bone in spec.TrunkBones)
            {
                int j = IndexOf(bone) is int i && i >= 0 ? i : throw Error("key 'trunkBones'", $"trunk bone '{bone}' is not a bone of {file}.");
                if (!trunk.Contains(j))
                {
                    trunk.Add(j);
                }
            }
        }
        else
        {
            var above = new HashSet<int> { 0 };
            foreach (LimbSpec limb in spec.Limbs)
            {
                for (int j = skeleton.Parents[IndexOf(limb.RootBone)]; j >= 0; j = skeleton.Parents[j])
                {
                    above.Add(j);
                }
            }

            trunk.AddRange(above.Order());
        }

        Rig rig0 = Named(() => new Rig(joints, Vector3.Zero));
        float[] contact0 = PoseFrom(rig0, spec, "contact", specPath);

        // The trunk box bounds the trunk bones' skinned vertices in the contact pose; a bone whose radius the spec
        // gives, or without vertices, counts as a sphere of its radius around its joint.
        // Where some trunk bones are skinned, one with neither vertices nor a radius in the spec is a control, not
        // body (Rigify's root bone on the ground, an IK target): it does not stretch the box down to the floor.
        IReadOnlyList<Vector3>[] trunkPoints = [.. names.Select((n, j) => spec.BoneRadii.ContainsKey(n) ? (IReadOnlyList<Vector3>)[] : skeleton.Points[j])];
        bool skinned = trunk.Any(j => trunkPoints[j].Count > 0);
        int[] boxed = [.. trunk.Where(j => !skinned || trunkPoints[j].Count > 0 || spec.BoneRadii.ContainsKey(names[j]))];
        (Vector3 centre, Vector3 half) = ReducedModelBuilder.TrunkBox(joints, boxed, radii, contact0, trunkPoints);
        Rig rig = Named(() => new Rig(joints, -centre));
        var rigLimbs = new List<RigLimb>();
        foreach (LimbSpec limb in spec.Limbs)
        {
            int effector = IndexOf(limb.EffectorBone);
            Vector3 offset;
            Vector3 normal;
            if (limb.EffectorOffset is Vector3 givenOffset)
            {
                offset = givenOffset;
                normal = limb.ContactNormal ?? RestDown(rig, effector);
            }
            else
            {
                (offset, Vector3 derivedNormal) = MeshDefaults.Contact(rig, effector, skeleton.Points)
                    ?? throw Error($"limb '{limb.Name}'", $"gives no effectorOffset, and no skinned vertex of {file} is weighted mostly to its effector bone '{limb.EffectorBone}' or the bones below it to derive one from; give effectorOffset (metres, in the effector bone's frame).");
                normal = limb.ContactNormal ?? derivedNormal;
            }

            NormalFilter filter = limb.Filter ?? (limb.Kind == LimbKind.Foot ? NormalFilter.Upward(0.5f) : NormalFilter.None);
            rigLimbs.Add(Named(() => new RigLimb(rig, limb.Name, limb.Kind, limb.RootBone, limb.EffectorBone, offset, normal, filter)));
        }

        if (Lying(rig, rigLimbs, axes) is string seemsUp)
        {
            throw Error(
                $"keys 'upAxis' and 'forwardAxis' ({AxisName(spec.UpAxis)}, {AxisName(spec.ForwardAxis)})",
                $"in the rest pose the feet of {file} are not below its trunk along upAxis {AxisName(spec.UpAxis)}: the rig lies on its side or stands on its head; it seems to use {seemsUp} as up (set 'upAxis' to \"{seemsUp}\" and 'forwardAxis' to the way it faces).");
        }

        // Body bones: those whose parent carries vertices and is their ancestor in the file (helper bones are not).
        int[] nodeParents = document.NodeParents();
        bool[] bodyBones = new bool[names.Length];
        for (int j = 1; j < names.Length; j++)
        {
            int parentNode = skeleton.Nodes[skeleton.Parents[j]];
            bool ancestor = false;
            for (int n = nodeParents[skeleton.Nodes[j]]; n >= 0 && !ancestor; n = nodeParents[n])
            {
                ancestor = n == parentNode;
            }

            bodyBones[j] = ancestor && skeleton.Points[skeleton.Parents[j]].Count > 0;
        }

        var source = new CharacterSource(document, skeleton.Nodes, AxisName(spec.UpAxis), AxisName(spec.ForwardAxis))
        {
            DerivedRadii = derivedRadii,
            BodyBones = bodyBones,
            SkinProbes = [.. skeleton.Points.Select(MeshDefaults.Extremes)],
            SpreadProbes = [.. skeleton.Points.Select(MeshDefaults.Spread)],
            BlendProbes = [.. skeleton.Points.Select((points, j) => MeshDefaults.BlendedExtremes(points, skeleton.Blends[j]))],
        };
        // Flight poses the spec does not give are derived from the limbs' workspaces, not left in the bind pose.
        float[] contact = PoseFrom(rig, spec, "contact", specPath);
        (float[] tucked, float[] stretched) = spec.Poses.ContainsKey("flexion") && spec.Poses.ContainsKey("extending") ? (contact, contact) : FlightPoses.Derive(rig, rigLimbs, contact);
        float[] flexion = spec.Poses.ContainsKey("flexion") ? PoseFrom(rig, spec, "flexion", specPath) : tucked;
        float[] extending = spec.Poses.ContainsKey("extending") ? PoseFrom(rig, spec, "extending", specPath) : stretched;
        // A rig modelled with its arms out (a T- or A-pose) whose spec gives no contact pose stands with its free hands
        // hanging at its sides, not held out as in its bind pose.
        float[] hanging = spec.Poses.ContainsKey("contact") ? contact : HangingArms.Derive(rig, rigLimbs, contact);
        CharacterModel model = Named(() => new CharacterModel(spec.Name, rig, rigLimbs, trunk, radii, contact, flexion, extending) { Source = source, HangingPose = hanging });
        ReducedCharacter reduced = Named(() => ReducedModelBuilder.Derive(
            model,
            spec.RequiredContacts ?? DefaultRequiredContacts(rigLimbs),
            spec.TakeoffSpeedMax ?? 8f,
            spec.LandingSpeedMax ?? 12f,
            spec.Friction ?? 0.5f));

        // Derive bounds the trunk joints' spheres; where the trunk is skinned its box bounds the vertices instead.
        // Speeds the spec does not give scale with the rig's size (a rat does not jump like a person).
        HeightRange lift = skinned ? ReducedModelBuilder.StanceLift(model, reduced.RequiredContacts, half) : reduced.StanceLift;
        float size = JumpSpeedScale(lift.Max);
        float takeoff = spec.TakeoffSpeedMax ?? (8f * size);
        float landing = spec.LandingSpeedMax ?? (12f * size);
        if (skinned || takeoff != reduced.TakeoffSpeedMax || landing != reduced.LandingSpeedMax)
        {
            reduced = new ReducedCharacter(reduced.Name, skinned ? half : reduced.TrunkHalfExtents, reduced.Limbs, reduced.RequiredContacts, takeoff, landing, reduced.Friction)
            {
                StanceLift = lift,
                Walking = reduced.Walking,
            };
        }

        if (spec.WalkSpeed is not null || spec.MaxSlope is not null || spec.MaxSlopeAlong is not null || spec.StepHeight is not null)
        {
            WalkingLimits derived = reduced.Walking;
            float speed = spec.WalkSpeed ?? derived.Speed;
            float step = spec.StepHeight ?? reduced.StepReach;
            float slope = spec.MaxSlope ?? derived.MaxSlopeDegrees;

            // A spec that sets maxSlope alone gets one limit whichever way the ground falls.
            float along = spec.MaxSlopeAlong ?? (spec.MaxSlope is not null ? slope : MathF.Max(slope, derived.MaxSlopeAlongDegrees));
            if (along < slope)
            {
                throw Error("key 'maxSlopeAlong'", $"{along} degrees is below the steepest slope walked any way ({slope} degrees, {(spec.MaxSlope is null ? "derived from the rig" : "key 'maxSlope'")}); give at least that.");
            }

            reduced = Named(() => reduced.WithWalking(new WalkingLimits(speed, slope, step) { MaxSlopeAlongDegrees = along, TurnRate = derived.TurnRate, PitchSpan = derived.PitchSpan, RollSpan = derived.RollSpan }));
        }

        return (model, reduced);
    }

    /// <summary>The rotation taking the glTF scene's <paramref name="up"/> to +Y and <paramref name="forward"/> to +Z.</summary>
    private static Quaternion AxesRotation(Vector3 up, Vector3 forward)
    {
        Vector3 left = Vector3.Cross(up, forward);

        // Rows are the images of the scene's X, Y and Z axes in Ballistic's frame (row vectors).
        var m = new Matrix4x4(left.X, up.X, forward.X, 0f, left.Y, up.Y, forward.Y, 0f, left.Z, up.Z, forward.Z, 0f, 0f, 0f, 0f, 1f);
        return Quaternion.Normalize(Quaternion.CreateFromRotationMatrix(m));
    }

    /// <summary>
    /// Null when the rest pose's feet (the foot limbs' effector joints, on average) lie below the trunk centre within
    /// 60° of straight down along Ballistic's up; otherwise the glTF scene axis the rig seems to use as up (the one
    /// pointing from its feet to its trunk). A character without feet is not judged.
    /// </summary>
    private static string? Lying(Rig rig, IReadOnlyList<RigLimb> limbs, Quaternion axes)
    {
        RigLimb[] feet = [.. limbs.Where(l => l.Kind == LimbKind.Foot)];
        if (feet.Length == 0)
        {
            return null;
        }

        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[rig.DofCount], positions, rotations);
        Vector3 down = feet.Aggregate(Vector3.Zero, (sum, l) => sum + positions[l.EffectorJoint]) / feet.Length; // trunk centre at the origin
        float length = down.Length();
        if (length < 1e-4f || -down.Y >= 0.5f * length)
        {
            return null;
        }

        Vector3 scene = Vector3.Transform(-down, Quaternion.Inverse(axes)); // feet to trunk, in the scene's axes
        Vector3 abs = Vector3.Abs(scene);
        (float value, string letter) = abs.X >= abs.Y && abs.X >= abs.Z ? (scene.X, "X") : abs.Y >= abs.Z ? (scene.Y, "Y") : (scene.Z, "Z");
        return (value >= 0f ? "+" : "-") + letter;
    }

    private static string AxisName(Vector3 axis) => CharacterSpecReader.AxisNames.First(a => a.Value == axis).Key;

    /// <summary>The rest pose's down direction in the frame of joint <paramref name="joint"/>.</summary>
    private static Vector3 RestDown(Rig rig, int joint)
    {
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), new float[rig.DofCount], positions, rotations);
        return Vector3.Normalize(Vector3.Transform(-Vector3.UnitY, Quaternion.Conjugate(rotations[joint])));
    }

    /// <summary>
    /// The limbs' chains as the rig can move them: each limb's root bone an ancestor of its effector bone and below the
    /// rig's root bone (a limb rooted at the root would move the whole body), no bone on two limbs' chains (one bone
    /// cannot follow two feet), and no limb bone below a root bone among the spec's <c>trunkBones</c> (a trunk bone
    /// does not move with a limb; a hip or shoulder, where the limb joins the trunk, may be listed). Each mistake is refused here, in one line naming the limbs and bone, instead of failing later in a bake.
    /// </summary>
    private static void CheckLimbChains(CharacterSpec spec, IReadOnlyList<int> parents, string[] names, Func<string, int> indexOf, Func<string, string, RigException> error)
    {
        var owner = new Dictionary<int, string>();
        foreach (LimbSpec limb in spec.Limbs)
        {
            int root = indexOf(limb.RootBone);
            int effector = indexOf(limb.EffectorBone);
            if (parents[root] < 0)
            {
                throw error($"limb '{limb.Name}'", $"starts at '{limb.RootBone}', the rig's root bone, which carries the whole body: give the bone the limb hangs from (a hip or shoulder) as rootBone.");
            }

            var chain = new List<int>();
            for (int j = effector; j != root; j = parents[j])
            {
                if (j < 0)
                {
                    throw error($"limb '{limb.Name}'", $"runs from '{limb.RootBone}' to '{limb.EffectorBone}', but '{limb.RootBone}' is not above '{limb.EffectorBone}' in the rig: the effector bone must hang below the root bone.");
                }

                chain.Add(j);
            }

            chain.Add(root);
            foreach (int j in chain)
            {
                if (owner.TryGetValue(j, out string? other))
                {
                    throw error($"limbs '{other}' and '{limb.Name}'", $"both run through the bone '{names[j]}': each limb needs a chain of its own, from its root bone to its effector.");
                }

                owner[j] = limb.Name;
                if (j != root && spec.TrunkBones?.Contains(names[j], StringComparer.Ordinal) == true)
                {
                    throw error("key 'trunkBones'", $"lists '{names[j]}', a bone of limb '{limb.Name}' below its root bone: a trunk bone does not move with a limb; leave it out of trunkBones.");
                }
            }
        }
    }

    /// <summary>Standing root height (metres) for which the default jump speeds, 8 m/s up and 12 m/s down, were chosen: the bundled skeleton's.</summary>
    internal const float FullSizeStance = 0.96f;

    /// <summary>
    /// The share of the default jump speeds a rig standing with its root <paramref name="stance"/> metres above its
    /// contacts gets: √(stance ÷ <see cref="FullSizeStance"/>), at most 1 (a Froude rule: jumps of the same shape in
    /// proportion to the body: a 4.5 cm rat takes off at 1.7 m/s and hops about 0.3 m; a person is not made faster).
    /// </summary>
    internal static float JumpSpeedScale(float stance) => stance > 0f && float.IsFinite(stance) ? MathF.Min(1f, MathF.Sqrt(stance / FullSizeStance)) : 1f;

    /// <summary>
    /// How many limbs must touch when a spec does not say: half the feet, rounded up (2 for a biped or a quadruped, 3
    /// for six legs, 4 for eight: a spider does not stand on two of its legs), all of them for one or two feet; 2 (or
    /// 1 with one limb) for a rig without feet.
    /// </summary>
    internal static int DefaultRequiredContacts(IReadOnlyList<RigLimb> limbs)
    {
        int feet = limbs.Count(l => l.Kind == LimbKind.Foot);
        return feet switch
        {
            0 => Math.Min(2, limbs.Count),
            <= 2 => feet,
            _ => (feet + 1) / 2,
        };
    }

    private static float[] PoseFrom(Rig rig, CharacterSpec spec, string poseName, string specPath)
    {
        float[] q = rig.Neutral();
        if (!spec.Poses.TryGetValue(poseName, out IReadOnlyList<(string Bone, float[] Degrees)>? pose))
        {
            return q;
        }

        foreach ((string bone, float[] degrees) in pose)
        {
            string where = $"pose '{poseName}', bone '{bone}'";
            int j = rig.IndexOf(bone);
            if (j < 0)
            {
                throw new RigException($"{specPath}: {where}: is not a bone of the rig.");
            }

            if (rig.DofsOf(j) == 0)
            {
                throw new RigException($"{specPath}: {where}: the bone is fixed (it has no degrees of freedom), so a pose cannot turn it; give it axes under 'joints'.");
            }

            if (degrees.Length != rig.DofsOf(j))
            {
                throw new RigException($"{specPath}: {where}: gives {degrees.Length} angle{(degrees.Length == 1 ? "" : "s")}, but the bone has {rig.DofsOf(j)} degree{(rig.DofsOf(j) == 1 ? "" : "s")} of freedom.");
            }

            for (int k = 0; k < degrees.Length; k++)
            {
                int d = rig.FirstDof(j) + k;
                float angle = Radians(degrees[k]);
                if (angle < rig.Dofs[d].Min - Radians(0.01f) || angle > rig.Dofs[d].Max + Radians(0.01f))
                {
                    throw new RigException($"{specPath}: {where}: angle {k} ({degrees[k]}°) is outside the joint's limits [{Degrees(rig.Dofs[d].Min)}°, {Degrees(rig.Dofs[d].Max)}°].");
                }

                q[d] = rig.Dofs[d].Clamp(angle);
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

    private static float Degrees(float radians) => MathF.Round(radians * 180f / MathF.PI, 4);

    private static float Radians(float degrees) => degrees * MathF.PI / 180f;
}
