using System.Numerics;

namespace Ballistic.Planner.Animation;

/// <summary>A contact the whole-body pose really makes: a limb's contact point held on a surface.</summary>
/// <param name="Limb">Index of the limb in the character's limb list.</param>
/// <param name="Position">Contact point on the surface, world metres.</param>
/// <param name="Normal">Unit surface normal at the contact, world.</param>
/// <param name="Mu">Friction coefficient of the surface.</param>
internal readonly record struct LimbContact(int Limb, Vector3 Position, Vector3 Normal, float Mu);
