using System.Numerics;

namespace Ballistic.Planner.Rigs;

/// <summary>
/// A joint (bone) of a rig: its parent, its rest offset and rotation relative to the parent, and 0 to 3 rotational
/// degrees of freedom applied in order after the rest rotation. A hinge has one axis; a ball joint three.
/// </summary>
/// <param name="Name">Unique joint name (the glTF node name on export).</param>
/// <param name="Parent">Index of the parent joint, or −1 for the rig's root joint.</param>
/// <param name="Offset">Position of the joint in its parent's frame at rest, metres.</param>
/// <param name="RestRotation">Rotation of the joint's frame relative to its parent's at rest.</param>
/// <param name="Axes">The joint's degrees of freedom, applied in order.</param>
internal sealed record Joint(string Name, int Parent, Vector3 Offset, Quaternion RestRotation, IReadOnlyList<JointAxis> Axes);
