using System.Globalization;
using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using SharpGLTF.Schema2;
using GltfAnimation = SharpGLTF.Schema2.Animation;

namespace Ballistic.Planner.Tests.Support;

/// <summary>
/// What an animator sees in an animated GLB, read the way an importer reads it: SharpGLTF (not our own glTF code)
/// parses the file, and every bone's world transform at a time comes from the node hierarchy, the rest transforms and
/// the clip's channels. From the plan it takes only the timeline (when each move starts and ends, where each jump
/// goes) and the spec's inputs (which bones are a limb's hip and ankle, the rig's up and forward axes); never the
/// animator's own poses. L is the leg length: the longest leg's hip height above its sole standing, in the rest pose
/// (the ankle plus the height of the spec's contact point below it) or, where it stands higher (a rig modelled with
/// its legs spread flat), the spec's contact pose; heading is the trunk's forward on the ground plane. Skinned vertices are placed by linear blend skinning,
/// as a renderer places them.
/// </summary>
internal sealed class AnimatorEye
{
    /// <summary>Jumps travelling at least this far across (metres) must face their direction.</summary>
    public const float FacingDistance = 1f;

    /// <summary>Largest angle (degrees) between the heading at takeoff and the jump's direction across.</summary>
    public const float TakeoffFacing = 30f;

    /// <summary>Largest angle (degrees) between the heading at landing and the jump's direction across.</summary>
    public const float LandingFacing = 45f;

    /// <summary>Least dip before a takeoff and after a landing, in leg lengths.</summary>
    public const float LeastDip = 0.08f;

    /// <summary>Window (seconds) before a takeoff or after a landing in which the dip is looked for.</summary>
    public const float DipWindow = 0.6f;

    /// <summary>Least time (seconds) on the ground between a landing and the next takeoff.</summary>
    public const float LeastGroundTime = 0.2f;

    /// <summary>Farthest (metres) a held foot's lowest skinned vertex may be from the surface, above or below.</summary>
    public const float SoleTolerance = 0.015f;

    /// <summary>Flights at least this long (seconds) must show a flight pose at their apex.</summary>
    public const float FlightPoseTime = 0.4f;

    /// <summary>Least average angle (degrees) of the limbs' joints from their rest rotations at the apex.</summary>
    public const float ApexFromRest = 10f;

    /// <summary>Least average angle (degrees) the limbs' joints turn between takeoff and the apex.</summary>
    public const float ApexFromTakeoff = 5f;

    /// <summary>Farthest (metres) a left foot may be right of its right partner in the trunk's frame.</summary>
    public const float CrossTolerance = 0.05f;

    /// <summary>Farthest (metres) an animated foothold at a move boundary may lie from the stance contact the plan reports.</summary>
    public const float FootholdTolerance = 0.25f;

    /// <summary>Farthest a foot may move sideways of its own hip from where the contact pose holds it, in leg lengths.</summary>
    public const float SidewaysShare = 0.35f;

    /// <summary>Spacing (metres) at which the ground between a foot and its place is read (<see cref="GroundEnds"/>).</summary>
    public const float BrinkStep = 0.02f;

    /// <summary>Deepest (metres) any skinned vertex of the body may be inside the level at any frame.</summary>
    public const float InsideTolerance = 0.02f;

    /// <summary>Interval (seconds) at which the whole body's vertices are checked against the level.</summary>
    public const float InsideStep = 1f / 15f;

    /// <summary>Least median height of the hips above the held feet while a walk cruises on ground under 10°, in leg lengths (each hip in its own leg's).</summary>
    public const float UprightHips = 0.88f;

    /// <summary>Most foot placements per second of a biped cruising at its walk speed.</summary>
    public const float MostCadence = 2.6f;

    /// <summary>Least step (distance the trunk walks per foot placement) of a biped cruising, in leg lengths.</summary>
    public const float LeastStep = 0.5f;

    /// <summary>Least rise and fall (peak to peak) of the hips while a walk cruises, in leg lengths.</summary>
    public const float LeastBob = 0.02f;

    /// <summary>Most rise and fall (peak to peak) of the hips while a walk cruises, in leg lengths: a walker's pelvis bobs 4–5 cm, about 0.05 L; more reads as bouncing.</summary>
    public const float MostBob = 0.08f;

    /// <summary>Least fore-and-aft swing (peak to peak, degrees) of an arm about its shoulder while a walk cruises.</summary>
    public const float LeastArmSwing = 20f;

    /// <summary>
    /// Most angle (degrees) off straight down of a free arm (shoulder to wrist) while the body stands before its first
    /// move and after its last: arms held out there read as a rig left in its T- or A-pose, not a body at rest.
    /// </summary>
    public const float MostRestingArm = 45f;

    /// <summary>Frames a second at which a player shows the clip, for <see cref="LeastSnap"/>.</summary>
    public const float DisplayRate = 60f;

    /// <summary>
    /// Least turn (degrees) of a limb joint from one displayed frame to the next that reads as a snap
    /// (<see cref="SnapRatio"/>) for a rig of a grown person's size (legs <see cref="HumanLeg"/> long or longer); a
    /// smaller rig's is this times √(<see cref="HumanLeg"/> ÷ <see cref="Leg"/>) (<see cref="SnapFloor"/>).
    /// </summary>
    public const float LeastSnap = 15f;

    /// <summary>
    /// A grown person's leg length (metres, hip height above the sole): the size the reference figures are for
    /// (the animation notes give adult human values, to be scaled to a rig by its leg and dynamic similarity) and on
    /// which <see cref="LeastSnap"/> was judged (the skeleton's legs are 0.91 m, the armature human's 0.95 m).
    /// </summary>
    public const float HumanLeg = 0.9f;

    /// <summary>
    /// Least turn (degrees) of a limb joint from one displayed frame to the next that reads as a snap on this rig:
    /// <see cref="LeastSnap"/>, scaled for a rig whose legs are shorter than <see cref="HumanLeg"/> by
    /// √(<see cref="HumanLeg"/> ÷ <see cref="Leg"/>): animals of different sizes move alike at equal Froude numbers,
    /// their motions lasting in proportion to √(leg ÷ g), as the gait's least step time does
    /// (<see cref="WalkGait.FullSizeLeg"/>). A 4.2 cm rat's feet step about nine times a second, each swing two or three
    /// frames at 60 frames a second: a forearm's 24° in the frame its paw lifts is its motion, not a snap (its floor
    /// is 69°; a 0.5 m dog's 20°, the 0.36 m spider's 24°).
    /// </summary>
    public float SnapFloor => LeastSnap * MathF.Max(1f, MathF.Sqrt(HumanLeg / Leg));

    /// <summary>How many times as far as in the displayed frames either side a joint turns in a snap.</summary>
    public const float SnapRatio = 3f;

    /// <summary>Steepest ground (degrees) on which a cruising walk's hip height, bob, arms and cadence are judged.</summary>
    private const float FlatGround = 10f;

    /// <summary>Half the span (metres, along the heading) over which the ground's grade under a walk is judged.</summary>
    private const float GradeSpan = 0.5f;

    /// <summary>Least rise or drop (metres) of the ground under the trunk between two samples 1/60 s apart that is a step in it, not a slope.</summary>
    private const float GroundStep = 0.02f;

    /// <summary>How far (metres) from a vertex the level's surface is looked for: depths up to this are measured.</summary>
    private const float InsideProbe = 0.1f;

    /// <summary>Metres within which two triangles are equally near a vertex (an edge or corner they share), above single-precision rounding.</summary>
    private const float EdgeTie = 1e-4f;

    private const float Step = 1f / 120f;

    [ThreadStatic]
    private static List<(float Distance, float Front)>? s_ties;

    private readonly GltfAnimation _clip;
    private readonly Node _trunk;
    private readonly SkinnedVertex[] _vertices;
    private readonly string[] _owners;
    private readonly Dictionary<Node, Track> _tracks = [];
    private readonly (Node Joint, Matrix4x4 InverseBind)[] _bindings;
    private readonly int[][] _groups;
    private readonly Dictionary<string, int[]> _feet;
    private readonly Quaternion _restTrunk;
    private readonly Vector3 _restForward;

    private readonly Node[][] _limbJoints;
    private readonly Vector3 _restLeft;
    private readonly FootPair[] _pairs;
    private readonly (string Name, Node Hip, Node Ankle, float RestSideways)[] _legs;
    private readonly (string Name, Node Effector, float Offset)[] _effectors;
    private readonly (string Name, Node Shoulder, Node Wrist, int Leg)[] _arms;

    /// <summary>Per foot (by limb name), its own leg's length, metres (L is the longest).</summary>
    private readonly Dictionary<string, float> _legOf;

    private AnimatorEye(GltfAnimation clip, Node trunk, Vector3 restForward, float leg, SkinnedVertex[] vertices, (Node Joint, Matrix4x4 InverseBind)[] bindings, string[] owners, Dictionary<string, int[]> feet, Node[][] limbJoints, Vector3 restLeft, FootPair[] pairs, (string, Node, Node, float)[] legs, (string, Node, float)[] effectors, (string, Node, Node, int)[] arms, Dictionary<string, float> legOf)
    {
        _legOf = legOf;
        _arms = arms;
        _owners = owners;
        _bindings = bindings;
        _groups = [.. Enumerable.Range(0, owners.Length).GroupBy(v => owners[v], StringComparer.Ordinal).Select(g => g.ToArray())];
        _effectors = effectors;
        _clip = clip;
        _limbJoints = limbJoints;
        _restLeft = restLeft;
        _pairs = pairs;
        _legs = legs;
        _vertices = vertices;
        _feet = feet;
        _trunk = trunk;
        _restTrunk = Rotation(trunk.WorldMatrix);
        _restForward = restForward;
        Leg = leg;
    }

    /// <summary>The leg length read from the rest pose, metres.</summary>
    public float Leg { get; }

    /// <summary>Reads <paramref name="glb"/> (the file written for <paramref name="model"/>'s animation, its clip first).</summary>
    public static AnimatorEye Read(byte[] glb, CharacterModel model)
    {
        ModelRoot root = ModelRoot.ParseGLB(glb);
        GltfAnimation clip = root.LogicalAnimations[0];
        Node Named(string name) => root.LogicalNodes.First(n => n.Name == name);
        Rig rig = model.Rig;
        Node trunk = Named(rig.Joints[0].Name);
        Vector3 up = Axis(model.Source?.UpAxis ?? "+Y");
        Vector3 forward = Axis(model.Source?.ForwardAxis ?? "+Z");

        // Leg length: the greatest height of a foot's hip above its sole along the rig's up, standing: in the rest
        // pose (the hip above the ankle read from the file, plus how far the spec's contact point lies below the
        // ankle at rest: a paw's contact point ahead of its ankle lies less than its offset's length below it), or in
        // the spec's contact pose where that stands higher (a rig modelled with its legs spread flat, an insect's,
        // stands only in its contact pose). L is the longest leg's; each leg's own is kept for the hips' height
        // above their feet (a dog's hind legs are shorter than its front ones). The contact pose also says where it
        // holds each foot sideways of its hip (model frame: +X is the left).
        var contact = new Vector3[rig.Joints.Count];
        var contactTurns = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), model.ContactPose, contact, contactTurns);
        var rest = new Vector3[rig.Joints.Count];
        var restTurns = new Quaternion[rig.Joints.Count];
        rig.Solve(new RootPose(Vector3.Zero, Quaternion.Identity), rig.Neutral(), rest, restTurns);
        float leg = 0f;
        var legOf = new Dictionary<string, float>(StringComparer.Ordinal);
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            Vector3 hip = Named(rig.Joints[limb.RootJoint].Name).WorldMatrix.Translation;
            Vector3 ankle = Named(rig.Joints[limb.EffectorJoint].Name).WorldMatrix.Translation;
            float sole = rest[limb.EffectorJoint].Y - limb.EffectorPosition(rest, restTurns).Y;
            float own = MathF.Max(Vector3.Dot(hip - ankle, up) + sole, contact[limb.RootJoint].Y - limb.EffectorPosition(contact, contactTurns).Y);
            legOf[limb.Name] = own;
            leg = MathF.Max(leg, own);
        }

        // The skinned vertices (linear blend skinning: joint world matrices times inverse bind matrices), and for each
        // foot, the vertices mostly skinned to its effector bone or a bone below it.
        var vertices = new List<SkinnedVertex>();
        var bindings = new List<(Node Joint, Matrix4x4 InverseBind)>();
        var bindingOf = new Dictionary<(int Skin, int Joint), int>();
        var owner = new List<Node>();
        foreach (Node node in root.LogicalNodes.Where(n => n.Mesh is not null && n.Skin is not null))
        {
            Skin skin = node.Skin;
            var joints = new (Node Joint, Matrix4x4 InverseBind)[skin.JointsCount];
            for (int j = 0; j < joints.Length; j++)
            {
                joints[j] = skin.GetJoint(j);
            }

            foreach (MeshPrimitive primitive in node.Mesh.Primitives)
            {
                var positions = primitive.GetVertexAccessor("POSITION").AsVector3Array();
                var jointIndices = primitive.GetVertexAccessor("JOINTS_0").AsVector4Array();
                var weights = primitive.GetVertexAccessor("WEIGHTS_0").AsVector4Array();
                for (int v = 0; v < positions.Count; v++)
                {
                    Vector4 ji = jointIndices[v];
                    Vector4 w = weights[v];
                    var influences = new (Node, Matrix4x4, float)[4];
                    int[] bound = new int[4];
                    float[] ws = [w.X, w.Y, w.Z, w.W];
                    float[] js = [ji.X, ji.Y, ji.Z, ji.W];
                    for (int k = 0; k < 4; k++)
                    {
                        (Node joint, Matrix4x4 inverse) = joints[(int)js[k]];
                        influences[k] = (joint, inverse, ws[k]);
                        if (!bindingOf.TryGetValue((skin.LogicalIndex, (int)js[k]), out bound[k]))
                        {
                            bound[k] = bindingOf[(skin.LogicalIndex, (int)js[k])] = bindings.Count;
                            bindings.Add((joint, inverse));
                        }
                    }

                    vertices.Add(new SkinnedVertex(positions[v], influences, bound));
                    owner.Add(influences.MaxBy(i => i.Item3).Item1);
                }
            }
        }

        var feet = new Dictionary<string, int[]>(StringComparer.Ordinal);
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            Node effector = Named(rig.Joints[limb.EffectorJoint].Name);
            feet[limb.Name] = [.. Enumerable.Range(0, vertices.Count).Where(v => Below(owner[v], effector))];
        }

        // Limb joints (the chain from each limb's root bone to its effector bone), and the feet in pairs: each side's
        // feet ordered from front to back in the rest pose, left (the rig's own left of its trunk) with right.
        Node[][] limbJoints = [.. model.Limbs.Select(l => l.Chain.Select(j => Named(rig.Joints[j].Name)).ToArray())];
        Vector3 left = Vector3.Cross(up, forward);
        Vector3 trunkRest = trunk.WorldMatrix.Translation;

        var legs = new List<(string, Node, Node, float)>();
        var sides = new List<(string Name, float Forward)>[2];
        sides[0] = [];
        sides[1] = [];
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Foot))
        {
            Node hip = Named(rig.Joints[limb.RootJoint].Name);
            Node ankle = Named(rig.Joints[limb.EffectorJoint].Name);
            legs.Add((limb.Name, hip, ankle, (contact[limb.EffectorJoint] - contact[limb.RootJoint]).X));
            Vector3 fromTrunk = hip.WorldMatrix.Translation - trunkRest;
            float side = Vector3.Dot(fromTrunk, left);
            if (MathF.Abs(side) > 1e-3f)
            {
                sides[side > 0f ? 0 : 1].Add((limb.Name, Vector3.Dot(fromTrunk, forward)));
            }
        }

        string[] lefts = [.. sides[0].OrderByDescending(s => s.Forward).Select(s => s.Name)];
        string[] rights = [.. sides[1].OrderByDescending(s => s.Forward).Select(s => s.Name)];
        FootPair[] pairs = [.. Enumerable.Range(0, Math.Min(lefts.Length, rights.Length)).Select(i => new FootPair(
            lefts[i], Named(rig.Joints[model.Limbs.First(l => l.Name == lefts[i]).EffectorJoint].Name),
            rights[i], Named(rig.Joints[model.Limbs.First(l => l.Name == rights[i]).EffectorJoint].Name)))];
        (string, Node, float)[] effectors = [.. model.Limbs.Select(l => (l.Name, Named(rig.Joints[l.EffectorJoint].Name), l.EffectorOffset.Length()))];
        // Arms (hand limbs), each with the leg on its side whose hip is nearest its shoulder (-1: none).
        var arms = new List<(string, Node, Node, int)>();
        foreach (RigLimb limb in model.Limbs.Where(l => l.Kind == LimbKind.Hand))
        {
            Node shoulder = Named(rig.Joints[limb.RootJoint].Name);
            float side = Vector3.Dot(shoulder.WorldMatrix.Translation - trunkRest, left);
            int partner = -1;
            float nearest = float.PositiveInfinity;
            for (int k = 0; k < legs.Count; k++)
            {
                Vector3 hip = legs[k].Item2.WorldMatrix.Translation;
                float d = Vector3.Distance(hip, shoulder.WorldMatrix.Translation);
                if (MathF.Abs(side) > 1e-3f && Vector3.Dot(hip - trunkRest, left) * side > 0f && d < nearest)
                {
                    (nearest, partner) = (d, k);
                }
            }

            arms.Add((limb.Name, shoulder, Named(rig.Joints[limb.EffectorJoint].Name), partner));
        }

        return new AnimatorEye(clip, trunk, forward, leg > 0f ? leg : 0.5f, [.. vertices], [.. bindings], [.. owner.Select(n => n.Name ?? "?")], feet, limbJoints, left, pairs, [.. legs], effectors, [.. arms], legOf);
    }

    /// <summary>
    /// Arms at rest: at the clip's first and last instants, while the body stands before its first move and after its
    /// last, each arm holding no contact hangs within <see cref="MostRestingArm"/> of the trunk's down (shoulder to
    /// wrist; the trunk stands tilted with the ground on a slope, and the arms with it), as the importer poses the GLB;
    /// an arm with no room to hang (the level within its length and a hand's breadth straight below its shoulder: a
    /// ledge, a dune's flank) is not measured.
    /// </summary>
    private void MeasureArmsAtRest(JumpAnimation animation, TriangleBvh level, Look look)
    {
        foreach (float time in new[] { 0f, animation.Duration })
        {
            foreach ((string name, Node shoulder, Node wrist, _) in _arms)
            {
                bool held = animation.ContactPhases.Any(p => animation.Model.Limbs[p.Limb].Name == name && time >= p.From - 1e-4f && time <= p.To + 1e-4f);
                Vector3 top = WorldAt(shoulder, time).Translation;
                Vector3 arm = WorldAt(wrist, time).Translation - top;
                if (held || arm.LengthSquared() < 1e-8f || level.Raycast(top, new Vector3(0f, -(arm.Length() + 0.1f), 0f), 1f, out _))
                {
                    continue;
                }

                float off = Degrees(Vector3.Normalize(arm), -UpAt(time));
                look.ArmsAtRest.Add(off / MostRestingArm, $"{name} hangs {off:0}° off the trunk's down standing at {time:0.00} s");
            }
        }
    }

    /// <summary>A left foot and its right partner (their effector bones).</summary>
    private sealed record FootPair(string Left, Node LeftAnkle, string Right, Node RightAnkle);

    /// <summary>A vertex of a skinned mesh: its bind position, up to four (joint, inverse bind matrix, weight), and each one's index in the eye's list of (joint, inverse bind) pairs.</summary>
    private sealed record SkinnedVertex(Vector3 Bind, (Node Joint, Matrix4x4 InverseBind, float Weight)[] Influences, int[] Bindings);

    private static bool Below(Node node, Node ancestor)
    {
        for (Node? n = node; n is not null; n = n.VisualParent)
        {
            if (n == ancestor)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>A skinned vertex's world position at clip time <paramref name="time"/>, metres.</summary>
    private Vector3 VertexAt(SkinnedVertex vertex, float time, Dictionary<Node, Matrix4x4> worlds)
    {
        Vector3 sum = Vector3.Zero;
        foreach ((Node joint, Matrix4x4 inverse, float weight) in vertex.Influences)
        {
            if (weight <= 0f)
            {
                continue;
            }

            if (!worlds.TryGetValue(joint, out Matrix4x4 world))
            {
                world = WorldAt(joint, time);
                worlds[joint] = world;
            }

            sum += weight * Vector3.Transform(vertex.Bind, inverse * world);
        }

        return sum;
    }

    /// <summary>
    /// <paramref name="node"/>'s world matrix at clip time <paramref name="time"/>: its local transform from the clip's
    /// channels (their keys read by SharpGLTF once per node, sampled as glTF's LINEAR and STEP modes say: lerp, slerp
    /// for rotations) or its rest transform where a channel is missing, times its parent's world matrix, as
    /// <c>Node.GetWorldMatrix(animation, time)</c> composes it (whose samplers search the keys from the first each
    /// call: 12 s for the rooftops clip's vertices, against well under one this way).
    /// </summary>
    private Matrix4x4 WorldAt(Node node, float time)
    {
        Matrix4x4 local = TrackOf(node).LocalAt(time);
        return node.VisualParent is Node parent ? local * WorldAt(parent, time) : local;
    }

    /// <summary><paramref name="node"/>'s channels as keys, read from the clip once.</summary>
    private Track TrackOf(Node node)
    {
        if (!_tracks.TryGetValue(node, out Track? track))
        {
            track = new Track(node, _clip);
            _tracks[node] = track;
        }

        return track;
    }

    /// <summary>
    /// The largest difference (any matrix entry) between the eye's world matrices and SharpGLTF's own
    /// <c>Node.GetWorldMatrix(animation, time)</c>, over the trunk and every limb joint at <paramref name="times"/>.
    /// </summary>
    public float LargestDifferenceFromSharpGltf(IEnumerable<float> times)
    {
        float largest = 0f;
        foreach (float time in times)
        {
            foreach (Node node in _limbJoints.SelectMany(j => j).Append(_trunk))
            {
                Matrix4x4 d = WorldAt(node, time) - node.GetWorldMatrix(_clip, time);
                largest = MathF.Max(largest, new[] { d.M11, d.M12, d.M13, d.M21, d.M22, d.M23, d.M31, d.M32, d.M33, d.M41, d.M42, d.M43 }.Max(MathF.Abs));
            }
        }

        return largest;
    }

    /// <summary>A node's animation channels as key arrays, sampled by binary search.</summary>
    private sealed class Track
    {
        private readonly Matrix4x4? _rest;
        private readonly Vector3 _scale;
        private readonly Quaternion _rotation;
        private readonly Vector3 _translation;
        private readonly (float[] Times, Vector3[] Values, bool Step)? _s;
        private readonly (float[] Times, Quaternion[] Values, bool Step)? _r;
        private readonly (float[] Times, Vector3[] Values, bool Step)? _t;

        public Track(Node node, GltfAnimation clip)
        {
            _s = Keys(clip.FindScaleChannel(node)?.GetScaleSampler());
            _r = Keys(clip.FindRotationChannel(node)?.GetRotationSampler());
            _t = Keys(clip.FindTranslationChannel(node)?.GetTranslationSampler());
            _rest = _s is null && _r is null && _t is null ? node.LocalMatrix : null;
            if (_rest is null)
            {
                // An animated node has its rest transform as scale, rotation and translation (glTF: never a matrix).
                var rest = node.LocalTransform.GetDecomposed();
                (_scale, _rotation, _translation) = (rest.Scale, rest.Rotation, rest.Translation);
            }
        }

        /// <summary>Whether the node has a rotation channel.</summary>
        public bool Rotates => _r is not null;

        /// <summary>The local rotation at clip time <paramref name="time"/>, as <see cref="LocalAt"/> samples it.</summary>
        public Quaternion RotationAt(float time) => _r is { } rk ? Quaternion.Normalize(Sample(rk, time, Quaternion.Slerp)) : _rotation;

        public Matrix4x4 LocalAt(float time)
        {
            if (_rest is Matrix4x4 rest)
            {
                return rest;
            }

            Vector3 s = _s is { } sk ? Sample(sk, time, Vector3.Lerp) : _scale;
            Quaternion r = _r is { } rk ? Sample(rk, time, Quaternion.Slerp) : _rotation;
            Vector3 t = _t is { } tk ? Sample(tk, time, Vector3.Lerp) : _translation;
            return Matrix4x4.CreateScale(s) * Matrix4x4.CreateFromQuaternion(Quaternion.Normalize(r)) * Matrix4x4.CreateTranslation(t);
        }

        private static (float[], T[], bool)? Keys<T>(IAnimationSampler<T>? sampler)
        {
            if (sampler is null)
            {
                return null;
            }

            if (sampler.InterpolationMode == AnimationInterpolationMode.CUBICSPLINE)
            {
                throw new NotSupportedException("The eye reads LINEAR and STEP channels; this clip has a CUBICSPLINE one.");
            }

            (float Key, T Value)[] keys = [.. sampler.GetLinearKeys()];
            return ([.. keys.Select(k => k.Key)], [.. keys.Select(k => k.Value)], sampler.InterpolationMode == AnimationInterpolationMode.STEP);
        }

        private static T Sample<T>((float[] Times, T[] Values, bool Step) keys, float time, Func<T, T, float, T> mix)
        {
            (float[] times, T[] values, bool step) = keys;
            int i = Array.BinarySearch(times, time);
            if (i >= 0)
            {
                return values[i];
            }

            i = ~i; // the first key after the time
            if (i == 0)
            {
                return values[0];
            }

            if (i >= times.Length)
            {
                return values[^1];
            }

            return step ? values[i - 1] : mix(values[i - 1], values[i], (time - times[i - 1]) / (times[i] - times[i - 1]));
        }
    }

    /// <summary>
    /// True when the ground under the trunk at clip time <paramref name="time"/> is level at the scale of a step: the
    /// surface straight below is under <see cref="FlatGround"/>°, and so is the grade between the ground
    /// <see cref="GradeSpan"/> m ahead of the trunk and as far behind (a staircase's treads are flat, the staircase is not).
    /// </summary>
    private bool LevelGroundAt(TriangleBvh level, float time) => LevelGround(level, time) is not null;

    /// <summary>The height (metres) of the ground straight below the trunk at clip time <paramref name="time"/> where it is level (<see cref="LevelGroundAt"/>), or <c>null</c>.</summary>
    private float? LevelGround(TriangleBvh level, float time)
    {
        Vector3 trunk = TrunkAt(time);
        Vector3 heading = HeadingAt(time);
        float flat = MathF.Cos(FlatGround * MathF.PI / 180f);
        if (!level.Raycast(trunk, -Vector3.UnitY, 4f * Leg, out RayHit ground) || MathF.Abs(ground.Normal.Y) < flat)
        {
            return null;
        }

        if (!level.Raycast(trunk + (heading * GradeSpan), -Vector3.UnitY, 4f * Leg, out RayHit ahead)
            || !level.Raycast(trunk - (heading * GradeSpan), -Vector3.UnitY, 4f * Leg, out RayHit behind))
        {
            return null;
        }

        return MathF.Abs(ahead.Point.Y - behind.Point.Y) <= 2f * GradeSpan * MathF.Tan(FlatGround * MathF.PI / 180f) ? ground.Point.Y : null;
    }

    /// <summary>
    /// True when the contacts held at one instant are level with each other: between every two of them the rise is
    /// under <see cref="FlatGround"/>° over their distance on the ground plane (with a centimetre for the soles).
    /// </summary>
    private static bool LevelFooting(IEnumerable<Vector3> contacts)
    {
        Vector3[] held = [.. contacts];
        float grade = MathF.Tan(FlatGround * MathF.PI / 180f);
        for (int i = 0; i < held.Length; i++)
        {
            for (int j = i + 1; j < held.Length; j++)
            {
                Vector3 d = held[j] - held[i];
                if (MathF.Abs(d.Y) > (grade * MathF.Sqrt((d.X * d.X) + (d.Z * d.Z))) + 0.01f)
                {
                    return false;
                }
            }
        }

        return true;
    }

    /// <summary>The trunk bone's world position at clip time <paramref name="time"/>, metres.</summary>
    public Vector3 TrunkAt(float time) => WorldAt(_trunk, time).Translation;

    /// <summary>The trunk's forward on the ground plane at <paramref name="time"/> (unit; zero when it points straight up or down).</summary>
    public Vector3 HeadingAt(float time)
    {
        Quaternion now = Rotation(WorldAt(_trunk, time));
        Vector3 f = Vector3.Transform(_restForward, now * Quaternion.Conjugate(_restTrunk));
        f.Y = 0f;
        return f.LengthSquared() > 1e-8f ? Vector3.Normalize(f) : Vector3.Zero;
    }

    /// <summary>The trunk's own up at <paramref name="time"/> (unit, world), tilting with it.</summary>
    public Vector3 UpAt(float time)
    {
        Quaternion now = Rotation(WorldAt(_trunk, time));
        return Vector3.Normalize(Vector3.Transform(Vector3.Cross(_restForward, _restLeft), now * Quaternion.Conjugate(_restTrunk)));
    }

    /// <summary>
    /// The trunk's own left at <paramref name="time"/> (unit, world), rolling with it: sideways in the trunk's frame,
    /// so that an insect standing across a slope with its body parallel to the ground is measured the way it stands,
    /// not with its legs' downward reach counted as sideways.
    /// </summary>
    public Vector3 LeftAt(float time)
    {
        Quaternion now = Rotation(WorldAt(_trunk, time));
        return Vector3.Normalize(Vector3.Transform(_restLeft, now * Quaternion.Conjugate(_restTrunk)));
    }

    /// <summary>
    /// Measures every jump of <paramref name="animation"/> (whose GLB this is) against the criteria, the feet's
    /// skinned soles in every contact phase against the surface under each held point, and the whole body's vertices
    /// against <paramref name="scene"/>'s level.
    /// </summary>
    public Look Measure(JumpAnimation animation, PlanningScene scene)
    {
        var look = new Look();
        TriangleBvh level = scene.Bvh;
        MeasureSoles(animation, level, look);
        MeasureInside(animation, scene.Level.Triangles, level, look);
        MeasureLegs(animation, level, look);
        MeasureFootholds(animation, look);
        MeasureWalks(animation, scene.Level.Triangles, level, look);
        MeasureSnaps(animation, look);
        MeasureArmsAtRest(animation, level, look);
        for (int j = 0; j < animation.Arcs.Count; j++)
        {
            var arc = animation.Arcs[j];
            int move = animation.MoveOfJump(j);
            float takeoff = animation.JumpStart(j);
            float landing = takeoff + arc.FlightTime;
            string jump = $"jump {j + 1} (move {move})";

            // Facing: the heading at takeoff and landing against the direction across.
            Vector3 across = arc.End - arc.Start;
            across.Y = 0f;
            if (across.Length() >= FacingDistance)
            {
                across = Vector3.Normalize(across);
                float off = Degrees(HeadingAt(takeoff), across);
                float on = Degrees(HeadingAt(landing), across);
                look.Facing.Add(MathF.Max(off / TakeoffFacing, on / LandingFacing), $"{jump} takes off {off:0}° and lands {on:0}° off its direction");
            }

            // Flight pose: at the flight's key pose (its apex, kept within the middle of the flight as the animator
            // keys it) the limbs' joints away from their rest rotations, and turned since takeoff.
            if (arc.FlightTime >= FlightPoseTime)
            {
                float apex = takeoff + JumpAnimator.ApexKeyTime(arc);
                float fromRest = 0f;
                float fromTakeoff = 0f;
                int count = 0;
                foreach (Node joint in _limbJoints.SelectMany(j => j))
                {
                    Quaternion now = joint.GetLocalTransform(_clip, apex).Rotation;
                    fromRest += Between(now, joint.LocalTransform.Rotation);
                    fromTakeoff += Between(now, joint.GetLocalTransform(_clip, takeoff).Rotation);
                    count++;
                }

                fromRest /= Math.Max(count, 1);
                fromTakeoff /= Math.Max(count, 1);
                look.FlightPose.Add(MathF.Min(fromRest / ApexFromRest, fromTakeoff / ApexFromTakeoff), $"{jump}'s limbs at its apex are {fromRest:0.0}° from rest and {fromTakeoff:0.0}° from takeoff on average");
            }

            // Crouch: the trunk's lowest point in the window before takeoff, below its height at takeoff; rising into it.
            float before = MathF.Max(0f, takeoff - DipWindow);
            if (move > 0)
            {
                before = MathF.Max(before, animation.MoveEnd(move - 1));
            }

            float top = TrunkAt(takeoff).Y;
            float crouch = (top - Lowest(before, takeoff)) / Leg;
            bool rising = TrunkAt(takeoff).Y > TrunkAt(MathF.Max(before, takeoff - 0.05f)).Y + 1e-4f;
            look.Crouch.Add(rising ? crouch / LeastDip : 0f, $"{jump} dips {crouch:0.000} L before takeoff{(rising ? "" : " and does not rise into it")}");

            // Absorb: the lowest point in the window after landing (before the next move), below the landing height.
            float after = MathF.Min(animation.Duration, landing + DipWindow);
            if (move + 1 < animation.Moves.Count)
            {
                after = MathF.Min(after, animation.MoveStart(move + 1));
            }

            float absorb = (TrunkAt(landing).Y - Lowest(landing, after)) / Leg;
            look.Absorb.Add(absorb / LeastDip, $"{jump} absorbs {absorb:0.000} L after landing");

            // Ground time before the next jump.
            if (move + 1 < animation.Moves.Count && animation.Moves[move + 1] is Jump)
            {
                float ground = animation.MoveStart(move + 1) - landing;
                look.GroundTime.Add(ground / LeastGroundTime, $"{jump} lands {ground:0.000} s before the next takeoff");
            }
        }

        return look;
    }

    /// <summary>
    /// Feet on the ground, not in it: in each contact phase of a foot (sampled at its start, middle and end), the foot's
    /// vertices against the plane of the surface under the held point (found by a ray of our own): the lowest within
    /// <see cref="SoleTolerance"/> of it, above or below.
    /// </summary>
    private void MeasureSoles(JumpAnimation animation, TriangleBvh level, Look look)
    {
        var worlds = new Dictionary<Node, Matrix4x4>();
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            string limb = animation.Model.Limbs[phase.Limb].Name;
            if (!_feet.TryGetValue(limb, out int[]? foot) || foot.Length == 0 || phase.To - phase.From < 1e-3f)
            {
                continue;
            }

            if (!level.Raycast(phase.Position + new Vector3(0f, 0.05f, 0f), -Vector3.UnitY, 0.1f, out RayHit hit))
            {
                continue;
            }

            Vector3 n = hit.Normal.Y < 0f ? -hit.Normal : hit.Normal;
            float worst = 0f;
            float worstTime = phase.From;
            foreach (float time in (float[])[phase.From, 0.5f * (phase.From + phase.To), phase.To])
            {
                worlds.Clear();
                float lowest = float.PositiveInfinity;
                foreach (int v in foot)
                {
                    lowest = MathF.Min(lowest, Vector3.Dot(VertexAt(_vertices[v], time, worlds) - hit.Point, n));
                }

                if (MathF.Abs(lowest) > MathF.Abs(worst))
                {
                    (worst, worstTime) = (lowest, time);
                }
            }

            look.Soles.Add(SoleTolerance / MathF.Max(MathF.Abs(worst), 1e-6f), $"{limb}'s sole {(worst < 0f ? "sinks" : "floats")} {MathF.Abs(worst) * 100f:0.0} cm {(worst < 0f ? "into" : "above")} the ground at {worstTime:0.000} s (held {phase.From:0.000}–{phase.To:0.000} s)");
        }
    }

    /// <summary>
    /// No part of the body in the level: every <see cref="InsideStep"/> seconds, each skinned vertex against the level
    /// triangles within <see cref="InsideProbe"/> of it: on the back side of the nearest (at an edge shared by several,
    /// the one it is most in front of), it is inside by its distance, which must not exceed <see cref="InsideTolerance"/>.
    /// </summary>
    private void MeasureInside(JumpAnimation animation, IReadOnlyList<Triangle> triangles, TriangleBvh level, Look look)
    {
        if (_vertices.Length == 0)
        {
            return;
        }

        var worlds = new Dictionary<Node, Matrix4x4>();
        var near = new List<int>();
        var points = new Vector3[_vertices.Length];
        var skinning = new Matrix4x4[_bindings.Length];
        float worst = 0f;
        string seen = "";
        for (float t = 0f; t <= animation.Duration + 1e-6f; t += InsideStep)
        {
            float time = MathF.Min(t, animation.Duration);
            worlds.Clear();
            for (int b = 0; b < skinning.Length; b++)
            {
                (Node joint, Matrix4x4 inverse) = _bindings[b];
                if (!worlds.TryGetValue(joint, out Matrix4x4 world))
                {
                    world = WorldAt(joint, time);
                    worlds[joint] = world;
                }

                skinning[b] = inverse * world;
            }

            for (int v = 0; v < points.Length; v++)
            {
                SkinnedVertex vertex = _vertices[v];
                Vector3 sum = Vector3.Zero;
                for (int k = 0; k < vertex.Bindings.Length; k++)
                {
                    float weight = vertex.Influences[k].Weight;
                    sum += weight > 0f ? weight * Vector3.Transform(vertex.Bind, skinning[vertex.Bindings[k]]) : Vector3.Zero;
                }

                points[v] = sum;
            }

            near.Clear();
            level.TrianglesNear(Aabb.FromPoints(points).Inflate(InsideProbe), near);
            if (near.Count == 0)
            {
                continue; // in the air, clear of everything
            }

            // Bone by bone: the triangles near the bone's vertices, then each vertex against them.
            foreach (int[] group in _groups)
            {
                near.Clear();
                Aabb box = Aabb.Empty;
                foreach (int v in group)
                {
                    box = Aabb.Union(box, new Aabb(points[v], points[v]));
                }

                level.TrianglesNear(box.Inflate(InsideProbe), near);
                foreach (int v in near.Count == 0 ? [] : group)
                {
                    float depth = DepthInside(points[v], triangles, near);
                    if (depth > worst)
                    {
                        worst = depth;
                        seen = $"a vertex of '{_owners[v]}' is {depth * 100f:0.0} cm inside the level at {time:0.00} s{During(animation, time)}";
                    }
                }
            }
        }

        look.Inside.Add(InsideTolerance / MathF.Max(worst, 1e-6f), seen.Length > 0 ? seen : "no vertex inside the level");
    }

    /// <summary>
    /// How far (metres) <paramref name="p"/> lies inside the level, judged on the triangles <paramref name="near"/> (indices
    /// into <paramref name="triangles"/>) within <see cref="InsideProbe"/>: behind the nearest, 0 in front of it or with
    /// none that near. Where several are nearest within <see cref="EdgeTie"/> (an edge or corner they share), the one
    /// the point is most in front of decides (a point beside a crate, below its top's plane, is nearest the top's edge
    /// and in front of the side).
    /// </summary>
    internal static float DepthInside(Vector3 p, IReadOnlyList<Triangle> triangles, List<int> near)
    {
        List<(float Distance, float Front)> ties = s_ties ??= [];
        ties.Clear();
        float nearest = InsideProbe;
        foreach (int i in near)
        {
            Triangle triangle = triangles[i];
            Vector3 closest = triangle.ClosestPoint(p);
            float d = Vector3.Distance(closest, p);
            if (d <= nearest + EdgeTie)
            {
                ties.Add((d, Vector3.Dot(p - closest, triangle.Normal)));
                nearest = MathF.Min(nearest, d);
            }
        }

        (bool any, float side) = (false, 0f);
        foreach ((float distance, float front) in ties)
        {
            if (distance <= nearest + EdgeTie)
            {
                (any, side) = (true, any ? MathF.Max(side, front) : front);
            }
        }

        return any && side < 0f ? nearest : 0f;
    }

    /// <summary>
    /// Legs under the body, on the ground (every 1/30 s outside flights): in the trunk's frame (along its own left,
    /// rolling with it) no left foot more than <see cref="CrossTolerance"/> right of its right partner, and each foot
    /// within <see cref="SidewaysShare"/> L sideways of its own hip, counted from where the spec's contact pose holds it,
    /// or, where the ground the foot stands on ends short of that place (<see cref="GroundEnds"/>: a perch narrower than
    /// the rig's stance, a wall beside it), within as much of where it ends: a spider on a crate smaller than its legs'
    /// span gathers its feet on the top, as far out as the top goes.
    /// </summary>
    private void MeasureLegs(JumpAnimation animation, TriangleBvh level, Look look)
    {
        if (_legs.Length == 0)
        {
            return;
        }

        float crossWorst = float.PositiveInfinity;
        string crossSeen = "";
        float sideWorst = 0f;
        string sideSeen = "";
        for (float t = 0f; t <= animation.Duration + 1e-6f; t += 1f / 30f)
        {
            bool flying = false;
            for (int j = 0; j < animation.Arcs.Count && !flying; j++)
            {
                float start = animation.JumpStart(j);
                flying = t > start && t < start + animation.Arcs[j].FlightTime;
            }

            Vector3 left = LeftAt(t);
            if (flying)
            {
                continue;
            }

            foreach (FootPair pair in _pairs)
            {
                float gap = Vector3.Dot(WorldAt(pair.LeftAnkle, t).Translation - WorldAt(pair.RightAnkle, t).Translation, left);
                if (gap < crossWorst)
                {
                    crossWorst = gap;
                    crossSeen = $"{pair.Left} is {-gap * 100f:0.0} cm right of {pair.Right} at {t:0.00} s";
                }
            }

            foreach ((string name, Node hip, Node ankle, float rest) in _legs)
            {
                Vector3 foot = WorldAt(ankle, t).Translation;
                float signed = Vector3.Dot(foot - WorldAt(hip, t).Translation, left) - rest;
                float off = MathF.Abs(signed) / Leg;
                string seen = $"{name} is {off:0.00} L sideways of where its contact pose holds it at {t:0.00} s{During(animation, t)}";
                if (off > SidewaysShare && GroundEnds(level, foot, foot - (left * signed)) is { } brink)
                {
                    off = brink / Leg;
                    seen = $"{name} is {off:0.00} L sideways of where the ground toward its place ends at {t:0.00} s{During(animation, t)}";
                }

                if (off > sideWorst)
                {
                    sideWorst = off;
                    sideSeen = seen;
                }
            }
        }

        if (_pairs.Length > 0 && float.IsFinite(crossWorst))
        {
            look.Crossing.Add(1f + ((crossWorst + CrossTolerance) / CrossTolerance), crossWorst >= 0f ? $"the feet never cross (closest {crossWorst * 100f:0.0} cm apart, {crossSeen.Split(" at ")[^1]})" : crossSeen);
        }

        look.UnderHips.Add(SidewaysShare / MathF.Max(sideWorst, 1e-6f), sideSeen.Length > 0 ? sideSeen : "the feet stay under the hips");
    }

    /// <summary>
    /// How far (metres, on the ground plane) from <paramref name="foot"/> toward <paramref name="place"/> the ground the
    /// foot stands on ends, or <c>null</c> when it goes on to the place: read every <see cref="BrinkStep"/> m, it ends
    /// where a wall rises in the way (a ray at a tenth of a leg above the ground hits the level) or where the ground
    /// below drops or rises by more than a tenth of a leg from the last sample (an edge, a gap). A foot over no ground
    /// (swinging across a gap) whose place is over no ground either: 0 (its place is nowhere to stand).
    /// </summary>
    private float? GroundEnds(TriangleBvh level, Vector3 foot, Vector3 place)
    {
        Vector3 across = place - foot;
        across.Y = 0f;
        float distance = across.Length();
        float lift = 0.1f * Leg;
        if (distance < 1e-4f)
        {
            return null;
        }

        if (!level.Raycast(foot + new Vector3(0f, lift, 0f), -Vector3.UnitY, 2f * Leg, out RayHit under))
        {
            // A foot swinging over a gap: where its place is over the gap too (no ground within two legs below it
            // either), there is no ground there for it to stand on, and the foot may be anywhere short of it.
            return level.Raycast(new Vector3(place.X, foot.Y + lift, place.Z), -Vector3.UnitY, 2f * Leg, out _) ? null : 0f;
        }

        across /= distance;
        float ground = under.Point.Y;
        float reach = distance;
        if (level.Raycast(new Vector3(foot.X, ground + lift, foot.Z), across, distance, out RayHit wall))
        {
            reach = wall.Distance;
        }

        for (float s = BrinkStep; s < reach; s += BrinkStep)
        {
            Vector3 at = foot + (across * s);
            if (!level.Raycast(new Vector3(at.X, ground + lift, at.Z), -Vector3.UnitY, 2f * lift, out RayHit hit) || MathF.Abs(hit.Point.Y - ground) > lift)
            {
                return s - BrinkStep;
            }

            ground = hit.Point.Y;
        }

        return reach < distance ? reach : null;
    }

    /// <summary>
    /// The time (seconds) from one placement of leg <paramref name="leg"/>'s foot to its next during move
    /// <paramref name="move"/>, the median over the walk (a foot rolling onto its ball is not placed anew);
    /// infinity when the foot is placed fewer than twice or <paramref name="leg"/> is no leg.
    /// </summary>
    private float Stride(JumpAnimation animation, int move, int leg)
    {
        if (leg < 0)
        {
            return float.PositiveInfinity;
        }

        float start = animation.MoveStart(move);
        float end = animation.MoveEnd(move);
        string name = _legs[leg].Name;
        float[] placed = [.. animation.ContactPhases
            .Where(p => !p.OnBall && p.From > start && p.From < end && animation.Model.Limbs[p.Limb].Name == name)
            .Select(p => p.From)
            .Order()];
        if (placed.Length < 2)
        {
            return float.PositiveInfinity;
        }

        float[] gaps = [.. Enumerable.Range(1, placed.Length - 1).Select(k => placed[k] - placed[k - 1]).Where(g => g > 1e-4f).Order()];
        return gaps.Length == 0 ? float.PositiveInfinity : gaps[gaps.Length / 2];
    }

    /// <summary>Where <paramref name="time"/> falls among the animation's moves, for a message: " (move 2, a jump, 0.31 s into it)".</summary>
    private static string During(JumpAnimation animation, float time)
    {
        for (int m = animation.Moves.Count - 1; m >= 0; m--)
        {
            if (time >= animation.MoveStart(m) - 1e-4f)
            {
                string kind = animation.Moves[m] is Jump ? "a jump" : "a walk";
                return time <= animation.MoveEnd(m) + 1e-4f
                    ? $" (move {m}, {kind}, {time - animation.MoveStart(m):0.00} s into it)"
                    : $" ({time - animation.MoveEnd(m):0.00} s after move {m}, {kind})";
            }
        }

        return " (before the first move)";
    }

    /// <summary>
    /// Footholds where the plan says: at the start and end of every move, each limb the plan's stance puts on a contact
    /// has its effector bone within <see cref="FootholdTolerance"/> of that contact (beyond the contact point's own
    /// offset from the bone).
    /// </summary>
    private void MeasureFootholds(JumpAnimation animation, Look look)
    {
        float worst = 0f;
        string seen = "";
        for (int m = 0; m < animation.Moves.Count; m++)
        {
            foreach ((float time, RoadmapNode stance) in new[] { (animation.MoveStart(m), animation.Moves[m].From), (animation.MoveEnd(m), animation.Moves[m].To) })
            {
                foreach (Contact c in stance.Contacts)
                {
                    (string name, Node effector, float offset) = _effectors[c.Limb];
                    float off = MathF.Max(0f, Vector3.Distance(WorldAt(effector, time).Translation, c.Position) - offset);
                    if (off > worst)
                    {
                        worst = off;
                        seen = $"{name} is {off:0.00} m from the contact the plan reports at {time:0.00} s (move {m})";
                    }
                }
            }
        }

        look.Footholds.Add(FootholdTolerance / MathF.Max(worst, 1e-6f), seen.Length > 0 ? seen : "every foothold on its reported contact");
    }

    /// <summary>
    /// No snaps, as a player shows the clip at <see cref="DisplayRate"/> frames a second: no limb joint (its local
    /// rotation, sampled as glTF interpolates it) turns more than <see cref="SnapFloor"/>° from one displayed frame to
    /// the next and more than <see cref="SnapRatio"/> times as far as in the frame before and in the frame after (a
    /// step), nor more than <see cref="SnapFloor"/>° out and as far back in the next frame, ending less than a
    /// <see cref="SnapRatio"/>th of that from where it was (a flick). A joint moving fast but smoothly (a push-off) is no
    /// snap; one that jumps between two slow frames, or out and back, is. One measurement per snapping frame of a joint
    /// (score above 1), or, where none snaps, one for the frame nearest to snapping.
    /// </summary>
    private void MeasureSnaps(JumpAnimation animation, Look look)
    {
        (float Score, string Seen) nearest = (0f, "no joint turns");
        float floor = SnapFloor;
        int frames = (int)MathF.Floor(animation.Duration * DisplayRate);
        var shown = new Quaternion[Math.Max(frames, 0) + 1];
        var turns = new float[Math.Max(frames, 0)];
        for (int l = 0; l < _limbJoints.Length; l++)
        {
            foreach (Node joint in _limbJoints[l])
            {
                Track track = TrackOf(joint);
                if (!track.Rotates)
                {
                    continue;
                }

                for (int f = 0; f <= frames; f++)
                {
                    shown[f] = track.RotationAt(f / DisplayRate);
                }

                for (int f = 0; f < frames; f++)
                {
                    turns[f] = Between(shown[f + 1], shown[f]);
                }

                for (int f = 0; f < frames; f++)
                {
                    // A step: one frame turning far more than either beside it. A flick: two frames turning out and back.
                    float around = MathF.Max(f > 0 ? turns[f - 1] : 0f, f + 1 < frames ? turns[f + 1] : 0f);
                    float step = MathF.Min(turns[f] / floor, turns[f] / MathF.Max(SnapRatio * around, 1e-6f));
                    float flick = f + 1 < frames
                        ? MathF.Min(MathF.Min(turns[f], turns[f + 1]) / floor, MathF.Min(turns[f], turns[f + 1]) / MathF.Max(SnapRatio * Between(shown[f + 2], shown[f]), 1e-6f))
                        : 0f;
                    float score = MathF.Max(step, flick);
                    if (score > 1f || score > nearest.Score)
                    {
                        float time = (f + 1) / DisplayRate;
                        string how = step >= flick
                            ? string.Create(CultureInfo.InvariantCulture, $"turns {turns[f]:0.0}° in the frame to {time:0.000} s, at most {around:0.0}° in the frames either side")
                            : string.Create(CultureInfo.InvariantCulture, $"turns {turns[f]:0.0}° out in the frame to {time:0.000} s and {turns[f + 1]:0.0}° back in the next, ending {Between(shown[f + 2], shown[f]):0.0}° from where it was");
                        string seen = $"{joint.Name} {how} ({Where(animation, l, time - (1f / DisplayRate), time)})";
                        if (score > 1f)
                        {
                            look.Snaps.Add(score, seen);
                        }
                        else
                        {
                            nearest = (score, seen);
                        }
                    }
                }
            }
        }

        if (look.Snaps.Seen.Count == 0)
        {
            look.Snaps.Add(nearest.Score, "no snap; nearest: " + nearest.Seen);
        }
    }

    /// <summary>
    /// Where in <paramref name="animation"/> the frame from <paramref name="from"/> to <paramref name="to"/> (clip
    /// seconds) lies, for limb <paramref name="limb"/>: in a flight (after its takeoff, before its landing), a walk, or
    /// on the ground (near a takeoff or landing); and the limb holding a contact, on its ball or free, or letting go or
    /// taking hold in that frame.
    /// </summary>
    private static string Where(JumpAnimation animation, int limb, float from, float to)
    {
        string what = "standing";
        float nearest = float.PositiveInfinity;
        for (int j = 0; j < animation.Arcs.Count; j++)
        {
            float takeoff = animation.JumpStart(j);
            float landing = takeoff + animation.Arcs[j].FlightTime;
            if (to > takeoff && from < landing)
            {
                nearest = 0f;
                what = string.Create(CultureInfo.InvariantCulture, $"jump {j + 1}'s flight, {Math.Max(from - takeoff, 0f):0.00} s after takeoff, {Math.Max(landing - to, 0f):0.00} s before landing");
            }
            else if (takeoff - to < nearest && to <= takeoff)
            {
                nearest = takeoff - to;
                what = string.Create(CultureInfo.InvariantCulture, $"{nearest:0.00} s before jump {j + 1}'s takeoff");
            }
            else if (from - landing < nearest && from >= landing)
            {
                nearest = from - landing;
                what = string.Create(CultureInfo.InvariantCulture, $"{nearest:0.00} s after jump {j + 1}'s landing");
            }
        }

        int move = animation.MoveIndex(to);
        if (nearest > 0f && move < animation.Moves.Count && animation.Moves[move] is Walk && animation.MoveStart(move) <= from && to <= animation.MoveEnd(move))
        {
            what = $"walk (move {move + 1})";
        }

        string state = "free";
        foreach (ContactPhase phase in animation.ContactPhases)
        {
            if (phase.Limb != limb || phase.To < from - 1e-3f || phase.From > to + 1e-3f)
            {
                continue;
            }

            state = phase.From > from + 1e-3f ? "taking hold" : phase.To < to - 1e-3f ? "letting go" : phase.OnBall ? "on its ball" : "held";
            if (state is "taking hold" or "letting go")
            {
                break;
            }
        }

        return $"{what}; its limb {state}";
    }

    /// <summary>
    /// An upright walk at a natural cadence, judged while each walk cruises (after it turns and speeds up, before it
    /// slows down; every 1/60 s): on level ground (<see cref="LevelGroundAt"/>: not on stairs or slopes; <see cref="LevelFooting"/>: the feet then held level with each other), the median
    /// height of the hips above the contacts of the feet then held at least <see cref="UprightHips"/> L; the hips
    /// (their height above the ground straight below the trunk) rising and falling at least <see cref="LeastBob"/> L and at most <see cref="MostBob"/> L about the
    /// line fitted through the second around (5th to 95th percentile: the steps' bob, not the ground's grade or bend; read where the level ground spans at least a stride); a biped (two feet) at most <see cref="MostCadence"/> foot placements
    /// per second on level ground (the mean time between successive placements there), each step at least <see cref="LeastStep"/> L; each arm swinging at least
    /// <see cref="LeastArmSwing"/>° fore and aft about its shoulder (the range of the shoulder-to-wrist direction's angle
    /// above or below the trunk's side plane), against the leg on its side (forward as it goes back), read where the
    /// level ground spans at least a stride of that leg (<see cref="Stride"/>) with room for the arm to swing
    /// (<see cref="ArmHasRoom"/>: not past a door's jamb or beside a wall, where it is rightly held in).
    /// </summary>
    private void MeasureWalks(JumpAnimation animation, IReadOnlyList<Triangle> triangles, TriangleBvh level, Look look)
    {
        int feet = _legs.Length;
        for (int m = 0; m < animation.Moves.Count; m++)
        {
            if (animation.Moves[m] is not Walk walk)
            {
                continue;
            }

            float from = animation.MoveStart(m) + walk.StartTurn + Walk.RampTime;
            float to = animation.MoveStart(m) + walk.StartTurn + walk.WalkTime - Walk.RampTime;
            if (to - from < 0.5f)
            {
                continue;
            }

            string name = $"walk {m}";
            var hips = new List<float>();
            var heights = new List<float>();
            var times = new List<float>();
            var arms = _arms.Select(_ => new List<(float Arm, float Leg)>()).ToArray();
            var armTimes = _arms.Select(_ => new List<float>()).ToArray();
            for (float t = from; t <= to + 1e-6f; t += 1f / 60f)
            {
                if (LevelGround(level, t) is not float groundY)
                {
                    continue;
                }

                // The step's footing must be level too (the feet held now and where each foot in the air lands next):
                // a foot put up on a rock or down a step 25 cm from the other is not a walk on level ground, whatever
                // lies under the trunk, and the hips rightly rise or sink for it.
                var footing = new List<Vector3>();
                float ownShare = 0f;
                var landing = new List<Vector3>();
                foreach ((string legName, Node hip, _, _) in _legs)
                {
                    ContactPhase? now = null;
                    ContactPhase? next = null;
                    foreach (ContactPhase phase in animation.ContactPhases)
                    {
                        if (animation.Model.Limbs[phase.Limb].Name != legName)
                        {
                            continue;
                        }

                        if (t >= phase.From && t <= phase.To)
                        {
                            now = phase;
                        }
                        else if (phase.From > t && (next is null || phase.From < next.Value.From))
                        {
                            next = phase;
                        }
                    }

                    if (now is { } holding)
                    {
                        // In the leg's own lengths: a shorter hind leg's hip stands as high over its foot as it reaches.
                        footing.Add(holding.Position);
                        ownShare += (WorldAt(hip, t).Translation.Y - holding.Position.Y) / (_legOf.TryGetValue(legName, out float own) && own > 0f ? own : Leg);
                    }
                    else if (next is { } lands)
                    {
                        landing.Add(lands.Position);
                    }
                }

                if (!LevelFooting(footing.Concat(landing)))
                {
                    continue;
                }

                int held = footing.Count;
                if (held > 0)
                {
                    hips.Add(ownShare / held);
                    heights.Add((_legs.Average(l => WorldAt(l.Hip, t).Translation.Y) - groundY) / Leg);
                    times.Add(t);
                }

                Vector3 heading = HeadingAt(t);
                for (int a = 0; a < _arms.Length; a++)
                {
                    (_, Node shoulder, Node wrist, int partner) = _arms[a];
                    Vector3 arm = WorldAt(wrist, t).Translation - WorldAt(shoulder, t).Translation;
                    if (!ArmHasRoom(triangles, level, a, t, heading, arm.Length()))
                    {
                        continue; // held in by a jamb or a wall beside it: not a free swing
                    }

                    armTimes[a].Add(t);
                    float angle = MathF.Asin(Math.Clamp(Vector3.Dot(Vector3.Normalize(arm), heading), -1f, 1f)) * 180f / MathF.PI;
                    float legAhead = partner < 0 ? 0f : Vector3.Dot(WorldAt(_legs[partner].Ankle, t).Translation - WorldAt(_legs[partner].Hip, t).Translation, heading);
                    arms[a].Add((angle, legAhead));
                }
            }

            if (hips.Count >= 10)
            {
                float[] sorted = [.. hips.Order()];
                float median = sorted[sorted.Length / 2];
                look.Upright.Add(median / UprightHips, $"{name}'s hips cruise {median:0.000} L above its held feet (each hip in its own leg's length)");
                // The bob: the hips' height above the ground straight below the trunk (as the eye sees the trunk rise
                // and fall over the ground it crosses, whichever foot holds it on a gentle slope) about the straight
                // line fitted through the second around each sample (the ground's grade and the slower rise and sink of
                // starting and stopping taken out), 5th to 95th percentile. Above the ground, not in the world: over a
                // dune's crest, grades of ±8° within the second sag 0.05 L below any straight line, and hips that
                // follow the crest at a steady height above it read as that much bob in the world (the desert
                // skeleton's hips, held down on crests to keep that reading under MostBob, stood 0.74 L over the held
                // foot there). Read, like the arms' swing, over a whole stride of the first leg (a step of each foot) of
                // unbroken level ground, each such stretch on its own: level ground that spans less sees only part of
                // the rise and fall (the desert skeleton's first walk read 0.010 L over 0.32 s, less than its 0.46 s
                // step), and two short stretches a second apart read 0.006 L where the hips rose 0.06 m over each
                // foot between them. Nor is level ground within a step (half a stride) of a step in the ground under
                // the trunk (a crate's edge, a stair): the hips rightly rise or sink with the ground there (stepping onto
                // a 10 cm crate on the holes-debris floor read as 0.086 L of bob).
                float stride = Stride(animation, m, 0);
                float[] steps = GroundSteps(level, from, to);
                int[] kept = [.. Enumerable.Range(0, times.Count).Where(k => !steps.Any(s => MathF.Abs(times[k] - s) <= 0.5f * stride))];
                List<float> bobTimes = [.. kept.Select(k => times[k])];
                List<float> bobHeights = [.. kept.Select(k => heights[k])];
                (float Bob, float Score, float From, float To)? worstBob = null;
                foreach ((int first, int last) in Stretches(bobTimes))
                {
                    if (!(bobTimes[last] - bobTimes[first] >= stride))
                    {
                        continue;
                    }

                    float bob = Bob(bobTimes, bobHeights, first, last);
                    float score = MathF.Min(bob / LeastBob, MostBob / MathF.Max(bob, 1e-6f));
                    if (worstBob is not { } seen || score < seen.Score)
                    {
                        worstBob = (bob, score, bobTimes[first], bobTimes[last]);
                    }
                }

                if (worstBob is { } b)
                {
                    look.Bob.Add(b.Score, $"{name}'s hips rise and fall {b.Bob:0.000} L ({b.To - b.From:0.00} s of level ground from {b.From:0.00} s)");
                }

                for (int a = 0; a < _arms.Length; a++)
                {
                    // An arm's swing is read over a whole stride of its leg (from one placement of the foot to its
                    // next) of unbroken level ground, each such stretch on its own: level ground that spans less sees
                    // only part of the swing (a third of a stride on the curved terrain read 7°; the same arms swing
                    // 30–39° on the plan's other walks), and so do two short stretches a second apart.
                    float armStride = Stride(animation, m, _arms[a].Leg);
                    (float Score, string Seen)? worstSwing = null;
                    foreach ((int first, int last) in Stretches(armTimes[a]))
                    {
                        if (!(armTimes[a][last] - armTimes[a][first] >= armStride))
                        {
                            continue;
                        }

                        List<(float Arm, float Leg)> samples = arms[a].GetRange(first, last - first + 1);
                        float swing = samples.Max(s => s.Arm) - samples.Min(s => s.Arm);
                        float against = _arms[a].Leg < 0 ? -1f : Correlation(samples);
                        float score = against < 0f ? swing / LeastArmSwing : 0f;
                        if (worstSwing is not { } seen || score < seen.Score)
                        {
                            worstSwing = (score, $"{name}'s {_arms[a].Name} swings {swing:0}° {(against < 0f ? "against" : "with")} its leg");
                        }
                    }

                    if (worstSwing is { } w)
                    {
                        look.ArmSwing.Add(w.Score, w.Seen);
                    }
                }
            }

            // The cadence: one over the mean time between successive foot placements on level ground (placements
            // counted in a window miss or gain one at its ends, up to 0.4 per second over the shortest walks; a foot
            // rolling onto its ball is not placed anew).
            float[] placed = [.. animation.ContactPhases
                .Where(p => !p.OnBall && p.From >= from && p.From <= to && _legs.Any(l => l.Name == animation.Model.Limbs[p.Limb].Name))
                .Select(p => p.From).Order()];
            float spanned = 0f;
            int intervals = 0;
            for (int k = 1; k < placed.Length; k++)
            {
                if (placed[k] - placed[k - 1] > 1e-4f && LevelGroundAt(level, placed[k - 1]) && LevelGroundAt(level, placed[k]))
                {
                    spanned += placed[k] - placed[k - 1];
                    intervals++;
                }
            }

            if (feet == 2 && intervals >= 2 && spanned >= 0.5f)
            {
                float cadence = intervals / spanned;
                float step = walk.Speed / MathF.Max(cadence, 1e-3f) / Leg;
                look.Cadence.Add(MathF.Min(MostCadence / MathF.Max(cadence, 1e-3f), step / LeastStep), $"{name} takes {cadence:0.00} steps per second at {walk.Speed:0.00} m/s, {step:0.00} L each");
            }
        }
    }

    /// <summary>
    /// The times (seconds, from <paramref name="from"/> to <paramref name="to"/>, every 1/60 s) at which the ground under
    /// the trunk steps up or down by more than <see cref="GroundStep"/> from one sample to the next: a crate's edge, a
    /// stair, not a slope (10° rises 0.4 cm between samples at a walk).
    /// </summary>
    private float[] GroundSteps(TriangleBvh level, float from, float to)
    {
        var steps = new List<float>();
        float? last = null;
        for (float t = from; t <= to + 1e-6f; t += 1f / 60f)
        {
            float? ground = level.Raycast(TrunkAt(t), -Vector3.UnitY, 4f * Leg, out RayHit hit) ? hit.Point.Y : null;
            if (ground is float g && last is float l && MathF.Abs(g - l) > GroundStep)
            {
                steps.Add(t);
            }

            last = ground;
        }

        return [.. steps];
    }

    /// <summary>The unbroken stretches (first and last index) of sample times <paramref name="times"/> taken every 1/60 s: a gap of more than two samples ends a stretch.</summary>
    private static IEnumerable<(int First, int Last)> Stretches(List<float> times)
    {
        int first = 0;
        for (int k = 1; k <= times.Count; k++)
        {
            if (k == times.Count || times[k] - times[k - 1] > 2.5f / 60f)
            {
                yield return (first, k - 1);
                first = k;
            }
        }
    }

    /// <summary>
    /// True when arm <paramref name="a"/> has room to swing at <paramref name="time"/>: no wall (a surface facing
    /// sideways, not a floor or a ceiling) within <see cref="ArmClearance"/> of the arm as it would hang, a little out
    /// from the shoulder, swung <see cref="ArmRoomSwing"/>° forward or back along <paramref name="heading"/>. An arm
    /// passing a door's jamb or walking beside a wall is rightly held in, not swung (issue 24).
    /// </summary>
    private bool ArmHasRoom(IReadOnlyList<Triangle> triangles, TriangleBvh level, int a, float time, Vector3 heading, float length)
    {
        Vector3 shoulder = WorldAt(_arms[a].Shoulder, time).Translation;
        Vector3 left = LeftAt(time);
        Vector3 centre = _arms.Length > 1 ? _arms.Where((_, i) => i != a).Select(o => WorldAt(o.Shoulder, time).Translation).Aggregate(Vector3.Zero, (x, y) => x + y) / (_arms.Length - 1) : TrunkAt(time);
        Vector3 outward = Vector3.Dot(shoulder - centre, left) >= 0f ? left : -left;
        Vector3 down = -UpAt(time);
        float reach = length + ArmClearance;
        List<int> near = s_near ??= [];
        near.Clear();
        level.TrianglesNearBox(new OrientedBox(shoulder, new Vector3(reach + 0.1f), Quaternion.Identity), near);
        foreach (float degrees in (float[])[-ArmRoomSwing, 0f, ArmRoomSwing])
        {
            float angle = degrees * MathF.PI / 180f;
            Vector3 hand = shoulder + (((MathF.Cos(angle) * down) + (MathF.Sin(angle) * heading)) * length) + (outward * ArmOutward);
            for (int k = 1; k <= 4; k++)
            {
                Vector3 p = Vector3.Lerp(shoulder, hand, k / 4f);
                foreach (int i in near)
                {
                    Triangle triangle = triangles[i];
                    if (MathF.Abs(triangle.Normal.Y) < 0.7f && Vector3.Distance(triangle.ClosestPoint(p), p) < ArmClearance)
                    {
                        return false;
                    }
                }
            }
        }

        return true;
    }

    /// <summary>How far (metres) a wall must stay from a freely swinging arm (<see cref="ArmHasRoom"/>): the forearm's and hand's half thickness and a little air.</summary>
    private const float ArmClearance = 0.1f;

    /// <summary>How far (metres) outward of its shoulder a freely swinging hand hangs (<see cref="ArmHasRoom"/>).</summary>
    private const float ArmOutward = 0.05f;

    /// <summary>The swing (degrees either way of hanging) an arm needs room for (<see cref="ArmHasRoom"/>): a little more than <see cref="LeastArmSwing"/>.</summary>
    private const float ArmRoomSwing = 30f;

    [ThreadStatic]
    private static List<int>? s_near;

    /// <summary>
    /// The rise and fall (leg lengths, 5th to 95th percentile) of <paramref name="heights"/> from sample
    /// <paramref name="first"/> to <paramref name="last"/> about the straight line fitted through the samples of that
    /// stretch within half a second of each.
    /// </summary>
    private static float Bob(List<float> times, List<float> heights, int first, int last)
    {
        float[] residual = new float[last - first + 1];
        for (int k = first; k <= last; k++)
        {
            (float n, float st, float sy, float stt, float sty) = (0f, 0f, 0f, 0f, 0f);
            for (int j = first; j <= last; j++)
            {
                float dt = times[j] - times[k];
                if (MathF.Abs(dt) <= 0.5f)
                {
                    (n, st, sy, stt, sty) = (n + 1f, st + dt, sy + heights[j], stt + (dt * dt), sty + (dt * heights[j]));
                }
            }

            float spread = (n * stt) - (st * st);
            float slope = spread > 1e-9f ? ((n * sty) - (st * sy)) / spread : 0f;
            residual[k - first] = heights[k] - ((sy - (slope * st)) / n);
        }

        Array.Sort(residual);
        return residual[(int)(0.95f * (residual.Length - 1))] - residual[(int)(0.05f * (residual.Length - 1))];
    }

    /// <summary>Pearson correlation of the pairs' two values (0 when either does not vary).</summary>
    private static float Correlation(List<(float A, float B)> pairs)
    {
        float ma = pairs.Average(p => p.A);
        float mb = pairs.Average(p => p.B);
        float ab = pairs.Sum(p => (p.A - ma) * (p.B - mb));
        float aa = pairs.Sum(p => (p.A - ma) * (p.A - ma));
        float bb = pairs.Sum(p => (p.B - mb) * (p.B - mb));
        return aa > 1e-9f && bb > 1e-9f ? ab / MathF.Sqrt(aa * bb) : 0f;
    }

    private static float Between(Quaternion a, Quaternion b) =>
        2f * MathF.Acos(Math.Clamp(MathF.Abs(Quaternion.Dot(Quaternion.Normalize(a), Quaternion.Normalize(b))), 0f, 1f)) * 180f / MathF.PI;

    private float Lowest(float from, float to)
    {
        float lowest = float.PositiveInfinity;
        for (float t = from; t <= to + 1e-6f; t += Step)
        {
            lowest = MathF.Min(lowest, TrunkAt(MathF.Min(t, to)).Y);
        }

        return MathF.Min(lowest, TrunkAt(to).Y);
    }

    private static float Degrees(Vector3 a, Vector3 b) =>
        a == Vector3.Zero ? 180f : MathF.Acos(Math.Clamp(Vector3.Dot(a, b), -1f, 1f)) * 180f / MathF.PI;

    private static Quaternion Rotation(Matrix4x4 m) => Matrix4x4.Decompose(m, out _, out Quaternion r, out _) ? Quaternion.Normalize(r) : Quaternion.Identity;

    private static Vector3 Axis(string name)
    {
        float sign = name[0] == '-' ? -1f : 1f;
        return char.ToUpperInvariant(name[^1]) switch
        {
            'X' => new Vector3(sign, 0f, 0f),
            'Y' => new Vector3(0f, sign, 0f),
            _ => new Vector3(0f, 0f, sign),
        };
    }

    /// <summary>
    /// One criterion over a plan: each measurement as a score (1 = exactly at the threshold, higher passes; for
    /// facing, lower passes) with what was seen.
    /// </summary>
    public sealed class Criterion(bool higherPasses)
    {
        public List<(float Score, string Seen)> Seen { get; } = [];

        public void Add(float score, string seen) => Seen.Add((score, seen));

        /// <summary>The worst measurement, or null when there was none.</summary>
        public (float Score, string Seen)? Worst => Seen.Count == 0 ? null : higherPasses ? Seen.MinBy(s => s.Score) : Seen.MaxBy(s => s.Score);

        public bool Passes => Seen.All(s => higherPasses ? s.Score >= 1f - 1e-4f : s.Score <= 1f + 1e-4f);

        public override string ToString() => Worst is { } w ? w.Seen : "nothing to measure";
    }

    /// <summary>What the eye saw of one plan, per criterion.</summary>
    public sealed class Look
    {
        public Criterion Facing { get; } = new(higherPasses: false);

        public Criterion Crouch { get; } = new(higherPasses: true);

        public Criterion Absorb { get; } = new(higherPasses: true);

        public Criterion GroundTime { get; } = new(higherPasses: true);

        public Criterion Soles { get; } = new(higherPasses: true);

        public Criterion FlightPose { get; } = new(higherPasses: true);

        public Criterion Crossing { get; } = new(higherPasses: true);

        public Criterion UnderHips { get; } = new(higherPasses: true);

        public Criterion Footholds { get; } = new(higherPasses: true);

        public Criterion Inside { get; } = new(higherPasses: true);

        public Criterion Upright { get; } = new(higherPasses: true);

        public Criterion Bob { get; } = new(higherPasses: true);

        public Criterion Cadence { get; } = new(higherPasses: true);

        public Criterion ArmSwing { get; } = new(higherPasses: true);

        public Criterion ArmsAtRest { get; } = new(higherPasses: false);

        public Criterion Snaps { get; } = new(higherPasses: false);

        /// <summary>The snapping frames seen in walks while the snapping limb is <paramref name="doing"/> ("free", "held", "letting go", …), one line each.</summary>
        public string[] WalkSnaps(string doing) =>
            [.. Snaps.Seen.Where(s => s.Score > 1f && s.Seen.Contains("(walk", StringComparison.Ordinal) && s.Seen.EndsWith($"its limb {doing})", StringComparison.Ordinal)).Select(s => s.Seen)];

        public IEnumerable<(string Name, Criterion Criterion)> All =>
            [("facing", Facing), ("crouch", Crouch), ("absorb", Absorb), ("ground time", GroundTime), ("soles", Soles), ("flight pose", FlightPose), ("crossing", Crossing), ("under hips", UnderHips), ("footholds", Footholds), ("inside", Inside), ("upright", Upright), ("bob", Bob), ("cadence", Cadence), ("arm swing", ArmSwing), ("arms at rest", ArmsAtRest)];

        public override string ToString() => string.Join("; ", All.Where(c => !c.Criterion.Passes).Select(c => string.Create(CultureInfo.InvariantCulture, $"{c.Name}: {c.Criterion}")));
    }
}
