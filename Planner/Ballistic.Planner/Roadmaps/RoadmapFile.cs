using System.Buffers.Binary;
using System.Numerics;
using System.Security.Cryptography;
using System.Text;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.IO;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// The binary roadmap format: magic <c>BLSTRMAP</c>, a version, the level and character fingerprints, the seed,
/// the nodes, the jump edges and (version 2) the walk edges (little-endian IEEE floats), and a SHA-256 of everything
/// before it. A roadmap without walks is written as version 1, byte for byte as before walking existed. Writing the same roadmap
/// always gives the same bytes. Saving goes through a temporary file, so a failed save leaves the old file intact.
/// Reading trusts nothing the checksum cannot vouch for: every value is checked (finite, in range, unit where it
/// should be) and, for the character and level it is loaded for, every jump is re-checked against its ends, the
/// speed limits and gravity.
/// </summary>
public static class RoadmapFile
{
    /// <summary>The newest format version this code writes and reads (version 2 adds walks; version 1 is still read, and written for a roadmap without walks).</summary>
    public const ushort Version = 2;

    private static readonly byte[] Magic = "BLSTRMAP"u8.ToArray();
    private const int HashSize = 32;

    /// <summary>The roadmap as bytes.</summary>
    public static byte[] ToBytes(Roadmap roadmap)
    {
        ArgumentNullException.ThrowIfNull(roadmap);
        using var stream = new MemoryStream();
        using (var w = new BinaryWriter(stream, Encoding.UTF8, leaveOpen: true))
        {
            w.Write(Magic);
            w.Write(roadmap.Walks.Count > 0 ? Version : (ushort)1);
            w.Write(Convert.FromHexString(roadmap.LevelFingerprint));
            w.Write(Convert.FromHexString(roadmap.CharacterFingerprint));
            w.Write(roadmap.CharacterName);
            w.Write(roadmap.Seed);
            w.Write(roadmap.Nodes.Count);
            foreach (RoadmapNode node in roadmap.Nodes)
            {
                Write(w, node.Pose.Position);
                Write(w, node.Pose.Rotation);
                Write(w, node.Cone.Axis);
                w.Write(node.Cone.Mu);
                w.Write(node.Contacts.Count);
                foreach (Contact c in node.Contacts)
                {
                    w.Write(c.Limb);
                    Write(w, c.Position);
                    Write(w, c.Normal);
                    w.Write(c.Mu);
                    w.Write(c.Surface);
                }
            }

            w.Write(roadmap.Edges.Count);
            foreach (RoadmapEdge edge in roadmap.Edges)
            {
                w.Write(edge.From);
                w.Write(edge.To);
                Write(w, edge.Arc.TakeoffVelocity);
                w.Write(edge.Arc.FlightTime);
                w.Write(edge.Arc.Gravity);
            }

            if (roadmap.Walks.Count > 0)
            {
                w.Write(roadmap.Walks.Count);
                foreach (RoadmapWalk walk in roadmap.Walks)
                {
                    w.Write(walk.From);
                    w.Write(walk.To);
                    w.Write(walk.Length);
                    w.Write(walk.Duration);
                }
            }
        }

        byte[] hash = SHA256.HashData(stream.GetBuffer().AsSpan(0, (int)stream.Length));
        stream.Write(hash);
        return stream.ToArray();
    }

    /// <summary>Saves the roadmap to <paramref name="path"/> through a temporary file in the same folder.</summary>
    public static void Save(Roadmap roadmap, string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        OutputFile.Write(path, ToBytes(roadmap));
    }

    /// <summary>The largest roadmap file read, bytes (2 GiB).</summary>
    public const long MaxFileBytes = int.MaxValue;

    /// <summary>
    /// Reads a roadmap file and checks that it was baked for this level and character and that its content is
    /// sound: every value finite, rotations and normals unit, node and limb indices in range, gravity the
    /// character's, every jump under the character's speed limits and landing where its parabola ends, and every
    /// node within reach of the level's bounds, and every stance true of the level: each contact on its surface with that
    /// surface's normal and friction, each stance with the contacts the character needs and the friction cone they give.
    /// </summary>
    /// <param name="path">The file.</param>
    /// <param name="level">The level it will be used on.</param>
    /// <param name="character">The character it will be used for.</param>
    /// <exception cref="RoadmapFileException">Missing, not a regular file, truncated, corrupt, unsound, unknown version, or baked for something else.</exception>
    public static Roadmap Load(string path, Levels.Level level, ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        return Read(path, level.Fingerprint, character, level);
    }

    /// <summary>
    /// Reads a roadmap file and checks that it was baked for the level of this fingerprint and for this character,
    /// and that its content is sound (see <see cref="Load(string, Levels.Level, ReducedCharacter)"/>, which also checks
    /// the nodes against the level's bounds).
    /// </summary>
    /// <param name="path">The file.</param>
    /// <param name="levelFingerprint">Fingerprint of the level it will be used on.</param>
    /// <param name="character">The character it will be used for.</param>
    /// <exception cref="RoadmapFileException">Missing, not a regular file, truncated, corrupt, unsound, unknown version, or baked for something else.</exception>
    public static Roadmap Load(string path, string levelFingerprint, ReducedCharacter character) => Read(path, levelFingerprint, character, null);

    private static Roadmap Read(string path, string levelFingerprint, ReducedCharacter character, Levels.Level? level)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(levelFingerprint);
        ArgumentNullException.ThrowIfNull(character);
        byte[] bytes = InputFile.Read(path, MaxFileBytes, "RoadmapFile.MaxFileBytes", (phrase, e) => new RoadmapFileException($"Roadmap file {path} {phrase}.", e!));
        return Check(FromBytes(bytes, path), path, levelFingerprint, character, level);
    }

    /// <summary>
    /// Parses roadmap bytes held in memory (e.g. by an engine resource) and checks them exactly as
    /// <see cref="Load(string, Levels.Level, ReducedCharacter)"/> checks a file: baked for this level and character,
    /// every value sound, every node within reach of the level's bounds, every stance true of the level.
    /// </summary>
    /// <param name="bytes">The roadmap's bytes, as <see cref="ToBytes"/> wrote them.</param>
    /// <param name="name">Names the bytes in messages (e.g. the resource's path).</param>
    /// <param name="level">The level it will be used on.</param>
    /// <param name="character">The character it will be used for.</param>
    /// <exception cref="RoadmapFileException">Truncated, corrupt, unsound, unknown version, or baked for something else.</exception>
    public static Roadmap FromBytes(ReadOnlySpan<byte> bytes, string name, Levels.Level level, ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(name);
        ArgumentNullException.ThrowIfNull(level);
        ArgumentNullException.ThrowIfNull(character);
        return Check(FromBytes(bytes, name), name, level.Fingerprint, character, level);
    }

    /// <summary>The checks of a parsed roadmap against the level and character it is loaded for.</summary>
    private static Roadmap Check(Roadmap roadmap, string path, string levelFingerprint, ReducedCharacter character, Levels.Level? level)
    {
        if (!string.Equals(roadmap.LevelFingerprint, levelFingerprint, StringComparison.Ordinal))
        {
            throw new RoadmapFileException($"Roadmap file {path} was baked on another level (level fingerprint {roadmap.LevelFingerprint[..12]}…, this level is {levelFingerprint[..Math.Min(12, levelFingerprint.Length)]}…); bake it again.");
        }

        if (!string.Equals(roadmap.CharacterFingerprint, character.Fingerprint, StringComparison.Ordinal))
        {
            throw new RoadmapFileException(roadmap.CharacterName == character.Name
                ? $"Roadmap file {path} was baked for a different version of the character '{character.Name}'; bake it again."
                : $"Roadmap file {path} was baked for the character '{roadmap.CharacterName}', not '{character.Name}'.");
        }

        if (level is not null)
        {
            Geometry.Aabb box = level.Bounds.Inflate(character.Reach + 1f);
            foreach (RoadmapNode node in roadmap.Nodes)
            {
                if (!box.Contains(node.Pose.Position))
                {
                    throw Invalid(path, $"node {node.Id} stands at ({node.Pose.Position.X:G4}, {node.Pose.Position.Y:G4}, {node.Pose.Position.Z:G4}), outside the level's bounds");
                }
            }
        }

        CheckForCharacter(roadmap, character, path);
        CheckWalks(roadmap, character, path);
        if (level is not null && StanceCheck.FirstLie(roadmap, level, character) is { } lie)
        {
            throw Invalid(path, $"{lie}, not as the bake puts stances on this level (edited by hand?); bake it again");
        }

        return roadmap;
    }

    /// <summary>The checks a roadmap must pass for its character (the checksum only says the bytes are as written).</summary>
    private static void CheckForCharacter(Roadmap roadmap, ReducedCharacter character, string name)
    {
        foreach (RoadmapNode node in roadmap.Nodes)
        {
            foreach (Contact c in node.Contacts)
            {
                if (c.Limb >= character.Limbs.Count)
                {
                    throw Invalid(name, $"node {node.Id} has a contact of limb {c.Limb}, but {character.Name} has {character.Limbs.Count} limbs");
                }
            }
        }

        for (int e = 0; e < roadmap.Edges.Count; e++)
        {
            BallisticArc arc = roadmap.Edges[e].Arc;
            if (MathF.Abs(arc.Gravity - character.Limits.Gravity) > 1e-3f)
            {
                throw Invalid(name, $"jump {e} falls under a gravity of {arc.Gravity:G4} m/s², not {character.Limits.Gravity} m/s²");
            }

            if (arc.TakeoffVelocity.Length() > character.TakeoffSpeedMax * 1.001f || arc.LandingVelocity.Length() > character.LandingSpeedMax * 1.001f)
            {
                throw Invalid(name, $"jump {e} is faster than {character.Name}'s speed limits ({arc.TakeoffVelocity.Length():G4} m/s at takeoff, {arc.LandingVelocity.Length():G4} m/s at landing)");
            }

            float miss = Vector3.Distance(arc.PositionAt(arc.FlightTime), arc.End);
            if (!(miss <= 0.01f))
            {
                throw Invalid(name, $"jump {e} (nodes {roadmap.Edges[e].From} → {roadmap.Edges[e].To}) lands {miss:G4} m from its landing node: its velocity and flight time do not fit its ends");
            }
        }
    }

    /// <summary>The walks' checks for the character: it walks, each walk's time is its length at the character's speed, and no walk is shorter than the ground between its nodes' contacts.</summary>
    private static void CheckWalks(Roadmap roadmap, ReducedCharacter character, string name)
    {
        for (int w = 0; w < roadmap.Walks.Count; w++)
        {
            RoadmapWalk walk = roadmap.Walks[w];
            if (!character.Walking.CanWalk)
            {
                throw Invalid(name, $"it holds walks, but {character.Name} does not walk");
            }

            float expected = walk.Length / character.Walking.Speed;
            if (!(MathF.Abs(walk.Duration - expected) <= 1e-3f * MathF.Max(1f, expected)))
            {
                throw Invalid(name, $"walk {w} (nodes {walk.From} → {walk.To}) takes {walk.Duration:G4} s for {walk.Length:G4} m, not {expected:G4} s at {character.Name}'s walking speed of {character.Walking.Speed:G4} m/s");
            }

            Vector3 a = roadmap.ContactCentres[walk.From];
            Vector3 b = roadmap.ContactCentres[walk.To];
            float across = new Vector2(b.X - a.X, b.Z - a.Z).Length();
            if (walk.Length < across - 0.01f)
            {
                throw Invalid(name, $"walk {w} (nodes {walk.From} → {walk.To}) is {walk.Length:G4} m long, shorter than the {across:G4} m between its nodes' contacts");
            }
        }
    }

    private static RoadmapFileException Invalid(string name, string what) => new($"Roadmap file {name} is invalid: {what}.");

    /// <summary>Parses roadmap bytes.</summary>
    /// <param name="bytes">The file's content.</param>
    /// <param name="name">Name of the file for messages.</param>
    /// <exception cref="RoadmapFileException">Truncated, corrupt or of an unknown version.</exception>
    public static Roadmap FromBytes(ReadOnlySpan<byte> bytes, string name = "(memory)")
    {
        if (bytes.Length < Magic.Length + 2 + HashSize || !bytes[..Magic.Length].SequenceEqual(Magic))
        {
            throw new RoadmapFileException($"Roadmap file {name} is not a Ballistic roadmap (it does not start with BLSTRMAP).");
        }

        ushort version = BinaryPrimitives.ReadUInt16LittleEndian(bytes[Magic.Length..]);
        if (version is not (1 or Version))
        {
            throw new RoadmapFileException($"Roadmap file {name} has format version {version}; this version of Ballistic reads versions 1 to {Version}.");
        }

        ReadOnlySpan<byte> payload = bytes[..^HashSize];
        if (!SHA256.HashData(payload).AsSpan().SequenceEqual(bytes[^HashSize..]))
        {
            throw new RoadmapFileException($"Roadmap file {name} is corrupt or truncated (its checksum does not match).");
        }

        try
        {
            return Parse(payload.ToArray(), name);
        }
        catch (Exception e) when (e is EndOfStreamException or ArgumentException or IOException or FormatException or OverflowException)
        {
            throw new RoadmapFileException($"Roadmap file {name} is corrupt: it ends early or holds a malformed value.", e);
        }
    }

    private static Roadmap Parse(byte[] payload, string name)
    {
        using var r = new BinaryReader(new MemoryStream(payload), Encoding.UTF8);
        r.ReadBytes(Magic.Length);
        ushort version = r.ReadUInt16();
        string level = HexText.Lower(r.ReadBytes(32));
        string character = HexText.Lower(r.ReadBytes(32));
        string characterName = r.ReadString();
        int seed = r.ReadInt32();
        var roadmap = new RoadmapBuilder(level, character, characterName, seed);
        int nodeCount = Count(r, payload.Length, name, "nodes");
        for (int i = 0; i < nodeCount; i++)
        {
            Vector3 position = ReadVector3(r);
            Quaternion rotation = ReadQuaternion(r);
            Vector3 axis = ReadVector3(r);
            float mu = r.ReadSingle();
            if (!Finite(position) || MathF.Abs(position.Length()) > MaxCoordinate)
            {
                throw Invalid(name, $"node {i} has a position that is not finite or lies beyond ±{MaxCoordinate:G3} m");
            }

            if (!Unit(new Vector4(rotation.X, rotation.Y, rotation.Z, rotation.W)))
            {
                throw Invalid(name, $"node {i} has a rotation that is not a unit quaternion");
            }

            if (!Unit(new Vector4(axis, 0f)) || !(mu >= 0f && mu <= MaxFriction))
            {
                throw Invalid(name, $"node {i} has a friction cone whose axis is not a unit vector or whose μ {mu:G4} is outside 0 to {MaxFriction}");
            }

            int contactCount = Count(r, payload.Length, name, "contacts");
            var contacts = new Contact[contactCount];
            for (int k = 0; k < contactCount; k++)
            {
                var contact = new Contact(r.ReadInt32(), ReadVector3(r), ReadVector3(r), r.ReadSingle(), r.ReadInt32());
                if (contact.Limb < 0 || !Finite(contact.Position) || contact.Position.Length() > MaxCoordinate || !Unit(new Vector4(contact.Normal, 0f)) || !(contact.Mu >= 0f && contact.Mu <= MaxFriction) || contact.Surface < -1)
                {
                    throw Invalid(name, $"node {i}, contact {k} has a negative limb, a position or normal that is not finite (or a normal not of unit length), or μ outside 0 to {MaxFriction}");
                }

                contacts[k] = contact;
            }

            roadmap.AddNode(new RoadmapNode(i, new RootPose(position, rotation), new FrictionCone(axis, mu), contacts));
        }

        int edgeCount = Count(r, payload.Length, name, "edges");
        for (int i = 0; i < edgeCount; i++)
        {
            int from = r.ReadInt32();
            int to = r.ReadInt32();
            Vector3 velocity = ReadVector3(r);
            float flightTime = r.ReadSingle();
            float gravity = r.ReadSingle();
            if ((uint)from >= (uint)nodeCount || (uint)to >= (uint)nodeCount)
            {
                throw new RoadmapFileException($"Roadmap file {name} is corrupt (edge {i} joins nodes {from} and {to}, but there are {nodeCount}).");
            }

            if (!Finite(velocity) || !(flightTime > 0f && flightTime <= MaxFlightTime) || !(gravity > 0f && gravity <= 1e3f))
            {
                throw Invalid(name, $"jump {i} has a velocity that is not finite, a flight time of {flightTime:G4} s (not above 0 and at most {MaxFlightTime} s) or a gravity of {gravity:G4} m/s²");
            }

            RoadmapNode a = roadmap.Nodes[from];
            RoadmapNode b = roadmap.Nodes[to];
            roadmap.AddEdge(new RoadmapEdge(from, to, new BallisticArc(a.Pose, b.Pose, velocity, flightTime, gravity)));
        }

        if (version >= 2)
        {
            int walkCount = Count(r, payload.Length, name, "walks");
            for (int i = 0; i < walkCount; i++)
            {
                int from = r.ReadInt32();
                int to = r.ReadInt32();
                float length = r.ReadSingle();
                float duration = r.ReadSingle();
                if ((uint)from >= (uint)nodeCount || (uint)to >= (uint)nodeCount || from == to)
                {
                    throw new RoadmapFileException($"Roadmap file {name} is corrupt (walk {i} joins nodes {from} and {to}, but there are {nodeCount}).");
                }

                if (!(length > 0f && length <= MaxCoordinate) || !(duration > 0f && duration <= MaxCoordinate))
                {
                    throw Invalid(name, $"walk {i} has a length of {length:G4} m or a duration of {duration:G4} s (each must be above 0 and at most {MaxCoordinate:G3})");
                }

                roadmap.AddWalk(new RoadmapWalk(from, to, length, duration));
            }
        }

        if (r.BaseStream.Position != payload.Length)
        {
            throw new RoadmapFileException($"Roadmap file {name} is corrupt ({payload.Length - r.BaseStream.Position} unexpected bytes after the {(version >= 2 ? "walks" : "edges")}).");
        }

        return roadmap.Freeze();
    }

    /// <summary>The farthest a node or contact may lie from the origin, metres.</summary>
    private const float MaxCoordinate = 1e6f;

    /// <summary>The largest friction coefficient read.</summary>
    private const float MaxFriction = 1e3f;

    /// <summary>The longest flight read, seconds.</summary>
    private const float MaxFlightTime = 1e3f;

    private static bool Finite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    private static bool Unit(Vector4 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z) && float.IsFinite(v.W) && MathF.Abs(v.Length() - 1f) <= 1e-3f;

    private static int Count(BinaryReader r, int limit, string name, string what)
    {
        int count = r.ReadInt32();
        return count >= 0 && count <= limit
            ? count
            : throw new RoadmapFileException($"Roadmap file {name} is corrupt (it claims {count} {what}).");
    }

    private static void Write(BinaryWriter w, Vector3 v)
    {
        w.Write(v.X);
        w.Write(v.Y);
        w.Write(v.Z);
    }

    private static void Write(BinaryWriter w, Quaternion q)
    {
        w.Write(q.X);
        w.Write(q.Y);
        w.Write(q.Z);
        w.Write(q.W);
    }

    private static Vector3 ReadVector3(BinaryReader r) => new(r.ReadSingle(), r.ReadSingle(), r.ReadSingle());

    private static Quaternion ReadQuaternion(BinaryReader r) => new(r.ReadSingle(), r.ReadSingle(), r.ReadSingle(), r.ReadSingle());
}
