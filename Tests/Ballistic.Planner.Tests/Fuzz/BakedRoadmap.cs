using System.Buffers.Binary;
using Ballistic.Planner.Characters;

namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>A saved roadmap's bytes with what loading it needs, and its sizes (to find its fields).</summary>
internal sealed record BakedRoadmap(byte[] Bytes, string LevelFingerprint, ReducedCharacter Character, int Contacts, int Edges)
{
    private const int HashSize = 32;

    /// <summary>Where each field of the file lies: counts, floats and node indices (the roadmap format, version 1, or 2 with walks).</summary>
    public RoadmapFields Fields()
    {
        var fields = new RoadmapFields();
        int at = 8 + 2 + 32 + 32;
        int nameLength = 0;
        int shift = 0;
        byte b;
        do
        {
            b = Bytes[at++];
            nameLength |= (b & 0x7F) << shift;
            shift += 7;
        }
        while ((b & 0x80) != 0);
        fields.NameLength = at - 1;
        at += nameLength + 4; // name, seed
        fields.Counts.Add(at);
        int nodes = BinaryPrimitives.ReadInt32LittleEndian(Bytes.AsSpan(at));
        at += 4;
        for (int n = 0; n < nodes; n++)
        {
            for (int k = 0; k < 11; k++)
            {
                fields.Floats.Add(at + (4 * k)); // position, rotation, cone axis, cone μ
            }

            at += 44;
            fields.Counts.Add(at);
            int contacts = BinaryPrimitives.ReadInt32LittleEndian(Bytes.AsSpan(at));
            at += 4;
            for (int c = 0; c < contacts; c++)
            {
                fields.Indices.Add(at); // limb
                for (int k = 0; k < 7; k++)
                {
                    fields.Floats.Add(at + 4 + (4 * k)); // position, normal, μ
                }

                fields.Indices.Add(at + 32); // surface
                at += 36;
            }
        }

        fields.Counts.Add(at);
        int edges = BinaryPrimitives.ReadInt32LittleEndian(Bytes.AsSpan(at));
        at += 4;
        for (int e = 0; e < edges; e++)
        {
            fields.Indices.Add(at);
            fields.Indices.Add(at + 4);
            for (int k = 0; k < 5; k++)
            {
                fields.Floats.Add(at + 8 + (4 * k)); // velocity, flight time, gravity
            }

            at += 28;
        }

        if (BinaryPrimitives.ReadUInt16LittleEndian(Bytes.AsSpan(8)) >= 2)
        {
            fields.Counts.Add(at);
            int walks = BinaryPrimitives.ReadInt32LittleEndian(Bytes.AsSpan(at));
            at += 4;
            for (int w = 0; w < walks; w++)
            {
                fields.Indices.Add(at);
                fields.Indices.Add(at + 4);
                fields.Floats.Add(at + 8); // length
                fields.Floats.Add(at + 12); // duration
                at += 16;
            }
        }

        fields.PayloadLength = at;
        if (at + HashSize != Bytes.Length)
        {
            throw new InvalidOperationException($"The roadmap layout assumed by the fuzz test is out of date: {at + HashSize} bytes expected, {Bytes.Length} found.");
        }

        return fields;
    }
}
