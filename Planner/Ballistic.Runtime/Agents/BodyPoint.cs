using System.Numerics;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// An agent's body point this tick (<see cref="JumpWorld.GetBodyPoint"/>): the ground reference of the character, where
/// a game puts the origin of its body node. On a stance, the centre of its contacts; in a jump, a parabola under the
/// world's gravity from the takeoff stance's contact centre to the landing one's; in a walk, the walk's ground path
/// reached at its speed. World frame, metres, Y up.
/// </summary>
/// <param name="Position">The body point, world metres.</param>
/// <param name="Velocity">Its velocity, m/s: zero on a stance; a parabola's in a jump; the walking speed along the ground path in a walk.</param>
/// <param name="Heading">
/// A rotation about +Y turning +Z (the model's front) toward the trunk's forward axis projected on the ground (kept
/// from the tick before while the trunk faces straight up or down).
/// </param>
public readonly record struct BodyPoint(Vector3 Position, Vector3 Velocity, Quaternion Heading);
