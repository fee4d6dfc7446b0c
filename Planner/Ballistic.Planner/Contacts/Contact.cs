using System.Numerics;

namespace Ballistic.Planner.Contacts;

/// <summary>An estimated contact of one limb with the level.</summary>
/// <param name="Limb">Index of the limb in the character's limb list.</param>
/// <param name="Position">Contact point: the centre of the limb workspace's intersection with the surface, world metres.</param>
/// <param name="Normal">Unit surface normal at the contact, world space, pointing out of the surface.</param>
/// <param name="Mu">Coulomb friction coefficient of the surface.</param>
/// <param name="Surface">Id of the contact surface touched.</param>
public readonly record struct Contact(int Limb, Vector3 Position, Vector3 Normal, float Mu, int Surface)
{
    /// <summary>The mean of <paramref name="contacts"/>' positions, world metres; <paramref name="none"/> when there are none (a stance's and a sampled pose's contact centre).</summary>
    internal static Vector3 Centre(IReadOnlyList<Contact> contacts, Vector3 none)
    {
        Vector3 sum = Vector3.Zero;
        for (int i = 0; i < contacts.Count; i++)
        {
            sum += contacts[i].Position;
        }

        return contacts.Count > 0 ? sum / contacts.Count : none;
    }

    /// <summary>
    /// The centroidal cone of <paramref name="contacts"/>: the normalised sum of their normals as axis, the least
    /// friction as μ; <c>null</c> when the normals cancel out (|Σ nᵢ| under <see cref="ContactEstimator.ForceClosureThreshold"/>).
    /// </summary>
    internal static FrictionCone? ConeOf(IReadOnlyList<Contact> contacts)
    {
        Vector3 sum = Vector3.Zero;
        float mu = float.PositiveInfinity;
        for (int i = 0; i < contacts.Count; i++)
        {
            sum += contacts[i].Normal;
            mu = MathF.Min(mu, contacts[i].Mu);
        }

        return sum.Length() < ContactEstimator.ForceClosureThreshold ? null : new FrictionCone(sum, mu);
    }
}
