namespace Ballistic.Planner.Tests.Fuzz;

/// <summary>Byte offsets of a roadmap file's fields.</summary>
internal sealed class RoadmapFields
{
    /// <summary>The first byte of the character name's length prefix.</summary>
    public int NameLength { get; set; }

    /// <summary>The node count, each node's contact count, and the edge count.</summary>
    public List<int> Counts { get; } = [];

    /// <summary>Every float: node poses, cones, contacts, and the edges' velocities, flight times and gravity.</summary>
    public List<int> Floats { get; } = [];

    /// <summary>Contacts' limb and surface indices and the edges' node indices.</summary>
    public List<int> Indices { get; } = [];

    /// <summary>Bytes before the SHA-256.</summary>
    public int PayloadLength { get; set; }
}
