using System.Buffers.Binary;
using System.Numerics;
using System.Security.Cryptography;
using System.Text;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.IO;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Roadmaps;

/// <summary>
/// The binary roadmap format: magic <c>BLSTRMAP</c>, a version, the level and character fingerprints, the seed,
/// the nodes and edges (little-endian IEEE floats), and a SHA-256 of everything before it. Writing the same roadmap
/// always gives the same bytes. Saving goes through a temporary file, so a failed save leaves the old file intact.
/// </summary>
public static class RoadmapFile
{
    /// <summary>The format version this code writes and reads.</summary>
    public const ushort Version = 1;

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
            w.Write(Version);
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

    /// <summary>Reads a roadmap file and checks that it was baked for this level and character.</summary>
    /// <param name="path">The file.</param>
    /// <param name="levelFingerprint">Fingerprint of the level it will be used on.</param>
    /// <param name="character">The character it will be used for.</param>
    /// <exception cref="RoadmapFileException">Missing, truncated, corrupt, unknown version, or baked for something else.</exception>
    public static Roadmap Load(string path, string levelFingerprint, ReducedCharacter character)
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(character);
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new RoadmapFileException($"Roadmap file {path} cannot be read: {e.Message}", e);
        }

        Roadmap roadmap = FromBytes(bytes, path);
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

        return roadmap;
    }

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
        if (version != Version)
        {
            throw new RoadmapFileException($"Roadmap file {name} has format version {version}; this version of Ballistic reads version {Version}.");
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
        catch (Exception e) when (e is EndOfStreamException or ArgumentException or IOException)
        {
            throw new RoadmapFileException($"Roadmap file {name} is corrupt ({e.Message}).", e);
        }
    }

    private static Roadmap Parse(byte[] payload, string name)
    {
        using var r = new BinaryReader(new MemoryStream(payload), Encoding.UTF8);
        r.ReadBytes(Magic.Length);
        r.ReadUInt16();
        string level = Convert.ToHexStringLower(r.ReadBytes(32));
        string character = Convert.ToHexStringLower(r.ReadBytes(32));
        string characterName = r.ReadString();
        int seed = r.ReadInt32();
        var roadmap = new Roadmap(level, character, characterName, seed);
        int nodeCount = Count(r, payload.Length, name, "nodes");
        for (int i = 0; i < nodeCount; i++)
        {
            Vector3 position = ReadVector3(r);
            Quaternion rotation = ReadQuaternion(r);
            Vector3 axis = ReadVector3(r);
            float mu = r.ReadSingle();
            int contactCount = Count(r, payload.Length, name, "contacts");
            var contacts = new Contact[contactCount];
            for (int k = 0; k < contactCount; k++)
            {
                contacts[k] = new Contact(r.ReadInt32(), ReadVector3(r), ReadVector3(r), r.ReadSingle(), r.ReadInt32());
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

            RoadmapNode a = roadmap.Nodes[from];
            RoadmapNode b = roadmap.Nodes[to];
            roadmap.AddEdge(new RoadmapEdge(from, to, new BallisticArc(a.Pose, b.Pose, velocity, flightTime, gravity)));
        }

        if (r.BaseStream.Position != payload.Length)
        {
            throw new RoadmapFileException($"Roadmap file {name} is corrupt ({payload.Length - r.BaseStream.Position} unexpected bytes after the edges).");
        }

        return roadmap;
    }

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
