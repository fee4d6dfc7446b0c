using System.Buffers.Binary;
using System.Numerics;
using System.Security.Cryptography;
using System.Text;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.IO;

namespace Ballistic.Planner.Characters;

/// <summary>
/// The reduced character the planner works with (paper §4): the trunk box W0 centred on the root, one workspace
/// box Wk per limb, how many limbs must touch for a pose to be valid, the jump speed limits and the default friction.
/// Trunk frame: +Y up (the back), +Z forward, +X the character's left; metres.
/// </summary>
public sealed class ReducedCharacter
{
    private string? _fingerprint;
    private HeightRange? _stanceLift;
    private WalkingLimits _walking = WalkingLimits.None;

    /// <summary>Creates a character, checking every value.</summary>
    /// <exception cref="CharacterException">A value is out of range, limb names repeat, or more limbs are required than exist.</exception>
    public ReducedCharacter(string name, Vector3 trunkHalfExtents, IReadOnlyList<Limb> limbs, int requiredContacts, float takeoffSpeedMax, float landingSpeedMax, float friction)
    {
        ArgumentNullException.ThrowIfNull(name);
        ArgumentNullException.ThrowIfNull(limbs);
        if (string.IsNullOrWhiteSpace(name))
        {
            throw new CharacterException("A character needs a name.");
        }

        if (!(trunkHalfExtents.X > 0f && trunkHalfExtents.Y > 0f && trunkHalfExtents.Z > 0f) || !float.IsFinite(trunkHalfExtents.Length()))
        {
            throw new CharacterException($"Character '{name}': trunk half extents must be finite and positive, not {trunkHalfExtents}.");
        }

        if (limbs.Count == 0)
        {
            throw new CharacterException($"Character '{name}' has no limbs: it cannot make contact.");
        }

        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (Limb limb in limbs)
        {
            if (string.IsNullOrWhiteSpace(limb.Name) || !seen.Add(limb.Name))
            {
                throw new CharacterException($"Character '{name}': limb names must be unique and non-empty ('{limb.Name}').");
            }

            Vector3 h = limb.WorkspaceHalfExtents;
            if (!(h.X > 0f && h.Y > 0f && h.Z > 0f) || !float.IsFinite(h.Length()) || !float.IsFinite(limb.WorkspaceCenter.Length()))
            {
                throw new CharacterException($"Character '{name}', limb '{limb.Name}': the workspace box must be finite with positive half extents.");
            }
        }

        if (requiredContacts < 1 || requiredContacts > limbs.Count)
        {
            throw new CharacterException($"Character '{name}': {requiredContacts} required contacts, but it has {limbs.Count} limbs (need 1 to {limbs.Count}).");
        }

        if (!(friction >= 0f) || !float.IsFinite(friction))
        {
            throw new CharacterException($"Character '{name}': friction must be finite and not negative, not {friction}.");
        }

        try
        {
            Limits = new SteeringLimits(takeoffSpeedMax, landingSpeedMax);
        }
        catch (ArgumentOutOfRangeException e)
        {
            throw new CharacterException($"Character '{name}': {e.Message}", e);
        }

        Name = name;
        TrunkHalfExtents = trunkHalfExtents;
        Limbs = [.. limbs];
        RequiredContacts = requiredContacts;
        Friction = friction;
    }

    /// <summary>Name of the character, e.g. <c>skeleton</c>.</summary>
    public string Name { get; }

    /// <summary>Half extents of the trunk box W0 in the trunk frame, metres. The root is its centre.</summary>
    public Vector3 TrunkHalfExtents { get; }

    /// <summary>The limbs with their workspaces.</summary>
    public IReadOnlyList<Limb> Limbs { get; }

    /// <summary>How many limbs must touch a surface for a root pose to be valid.</summary>
    public int RequiredContacts { get; }

    /// <summary>Largest takeoff speed, m/s.</summary>
    public float TakeoffSpeedMax => Limits.TakeoffSpeedMax;

    /// <summary>Largest landing speed, m/s.</summary>
    public float LandingSpeedMax => Limits.LandingSpeedMax;

    /// <summary>Default Coulomb friction coefficient of every surface (materials may override it).</summary>
    public float Friction { get; }

    /// <summary>Speed limits and gravity for the steering method.</summary>
    internal SteeringLimits Limits { get; }

    /// <summary>
    /// How far below the root (along the trunk's −Y, metres) the limbs reach: the lowest point of any workspace.
    /// Root poses are sampled up to this height above a surface.
    /// </summary>
    public float Reach
    {
        get
        {
            float reach = TrunkHalfExtents.Y;
            foreach (Limb limb in Limbs)
            {
                var box = limb.WorkspaceAt(new RootPose(Vector3.Zero, Quaternion.Identity));
                reach = MathF.Max(reach, -box.Bounds.Min.Y);
            }

            return reach;
        }
    }

    /// <summary>
    /// How high the trunk centre stands above the surface under its supporting contacts, along the trunk's up axis
    /// (metres): root poses are sampled in this range. Derived from the rig, from about 70 % (moderately bent legs)
    /// to 100 % (legs near straight) of its rest-pose height; when not set, from the trunk's half height to
    /// <see cref="Reach"/>.
    /// </summary>
    internal HeightRange StanceLift
    {
        get => _stanceLift ?? new HeightRange(TrunkHalfExtents.Y + 0.02f, MathF.Max(TrunkHalfExtents.Y + 0.02f, Reach));
        init
        {
            if (!value.IsValid || value.Min < TrunkHalfExtents.Y)
            {
                throw new CharacterException($"Character '{Name}': the stance lift must be a finite range above the trunk's half height ({TrunkHalfExtents.Y:0.###} m), not {value.Min:0.###}–{value.Max:0.###} m.");
            }

            _stanceLift = value;
        }
    }

    /// <summary>
    /// The highest step (metres) the character's feet take in their stride: its <see cref="Walking"/> step height, or
    /// for a character that does not walk, <see cref="WalkingLimits.StepShare"/> of its highest stance. Where a
    /// ledge's brink counts as a drop (<see cref="Contacts.ContactEstimator"/>) and how high a foot is lifted off its
    /// tread as it leaves it (<see cref="Animation.JumpAnimator"/>).
    /// </summary>
    internal float StepReach => Walking.StepHeight > 0f ? Walking.StepHeight : WalkingLimits.StepShare * StanceLift.Max;

    /// <summary>
    /// How the character walks (speed, steepest slope, highest step); <see cref="WalkingLimits.None"/> (the default):
    /// it only jumps. Derived from the rig's legs by <see cref="Rigs.ReducedModelBuilder"/>, overridable in the limb spec.
    /// </summary>
    /// <exception cref="CharacterException">A value is out of range.</exception>
    public WalkingLimits Walking
    {
        get => _walking;
        init
        {
            ArgumentNullException.ThrowIfNull(value);
            if (value.Problem() is string problem)
            {
                throw new CharacterException($"Character '{Name}': {problem}.");
            }

            _walking = value;
        }
    }

    /// <summary>This character with other walking limits (everything else the same).</summary>
    /// <exception cref="CharacterException">A value is out of range.</exception>
    public ReducedCharacter WithWalking(WalkingLimits walking) =>
        new(Name, TrunkHalfExtents, Limbs, RequiredContacts, TakeoffSpeedMax, LandingSpeedMax, Friction) { _stanceLift = _stanceLift, Walking = walking };

    /// <summary>A hex SHA-256 of everything that affects planning; roadmap files record it.</summary>
    public string Fingerprint => _fingerprint ??= ComputeFingerprint();

    private string ComputeFingerprint()
    {
        using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        hash.AppendData(Encoding.UTF8.GetBytes(Name));
        Append(hash, TrunkHalfExtents.X, TrunkHalfExtents.Y, TrunkHalfExtents.Z, RequiredContacts, TakeoffSpeedMax, LandingSpeedMax, Friction, Limits.Gravity, StanceLift.Min, StanceLift.Max);
        foreach (Limb limb in Limbs)
        {
            hash.AppendData(Encoding.UTF8.GetBytes(limb.Name));
            Vector3 c = limb.WorkspaceCenter;
            Vector3 h = limb.WorkspaceHalfExtents;
            Quaternion q = limb.WorkspaceRotation;
            Append(hash, (int)limb.Kind, c.X, c.Y, c.Z, h.X, h.Y, h.Z, q.X, q.Y, q.Z, q.W, limb.Filter.Direction.X, limb.Filter.Direction.Y, limb.Filter.Direction.Z, limb.Filter.MinCosine);
            if (limb.Home is { } home)
            {
                Append(hash, home.X, home.Y, home.Z);
            }
        }

        // Walking changes the roadmap (its walks); a character that only jumps keeps the fingerprint it always had.
        if (Walking.CanWalk)
        {
            hash.AppendData("walking"u8);
            Append(hash, Walking.Speed, Walking.MaxSlopeDegrees, Walking.StepHeight);
            if (Walking.MaxSlopeAlongDegrees != Walking.MaxSlopeDegrees)
            {
                // Characters whose limit is the same whichever way the ground falls keep the fingerprint they had.
                Append(hash, Walking.MaxSlopeAlongDegrees);
            }

            if (Walking.RollSpan > 0f)
            {
                // A trunk rolling with the ground checks and times its walks otherwise; others keep their fingerprint.
                hash.AppendData("roll"u8);
                Append(hash, Walking.RollSpan);
            }
        }

        return HexText.Lower(hash.GetHashAndReset());
    }

    /// <inheritdoc />
    public override string ToString() => $"{Name} ({Limbs.Count} limbs, {RequiredContacts} must touch, μ {Friction}, {TakeoffSpeedMax}/{LandingSpeedMax} m/s{(Walking.CanWalk ? $", walks at {Walking.Speed:0.##} m/s" : "")})";

    private static void Append(IncrementalHash hash, params ReadOnlySpan<float> values)
    {
        Span<byte> buffer = stackalloc byte[4];
        foreach (float v in values)
        {
            BinaryPrimitives.WriteSingleLittleEndian(buffer, v);
            hash.AppendData(buffer);
        }
    }
}
