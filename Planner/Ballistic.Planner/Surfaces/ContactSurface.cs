using System.Numerics;

namespace Ballistic.Planner.Surfaces;

/// <summary>
/// A connected patch of level triangles with similar normals and one material: where a limb can make contact.
/// </summary>
/// <param name="Id">Index of the surface in its <see cref="SurfaceSet"/>.</param>
/// <param name="Normal">Area-weighted mean unit normal, world space.</param>
/// <param name="Area">Total area, square metres.</param>
/// <param name="MaterialIndex">Index of the material shared by its triangles, in the level's material list.</param>
/// <param name="TriangleCount">Number of triangles.</param>
internal readonly record struct ContactSurface(int Id, Vector3 Normal, float Area, int MaterialIndex, int TriangleCount);
