using System.Numerics;

namespace Ballistic.Planner.Levels;

/// <summary>A mesh to write into a level file: world-space positions, triangle indices and a material.</summary>
/// <param name="Name">Mesh and node name.</param>
/// <param name="Positions">Vertex positions, world metres.</param>
/// <param name="Indices">Three indices per triangle, counter-clockwise seen from the front.</param>
/// <param name="Material">Material (its friction, when set, is written to the glTF material's extras).</param>
/// <param name="Color">Base colour (linear RGBA) for viewers.</param>
public sealed record LevelMesh(string Name, Vector3[] Positions, int[] Indices, LevelMaterial Material, Vector4 Color);
