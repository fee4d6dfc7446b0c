namespace Ballistic.Runtime.Baking;

/// <summary>
/// Which way round the three corners of a triangle run when seen from its front (the side a character can stand
/// on). The planner's <see cref="Ballistic.Planner.Levels.Level"/> uses glTF's convention, counter-clockwise, so that the
/// right-hand rule (b − a) × (c − a) gives the front normal; Godot's front faces are clockwise (what
/// <c>Mesh.GetFaces()</c>, <c>ConcavePolygonShape3D.GetFaces()</c> and
/// <c>NavigationMeshSourceGeometryData3D.AddFaces</c> hold).
/// </summary>
public enum FaceWinding
{
    /// <summary>Clockwise seen from the front: Godot's convention. Each triangle is turned round when added.</summary>
    Clockwise,

    /// <summary>Counter-clockwise seen from the front: glTF's and the planner's convention. Added as given.</summary>
    CounterClockwise,
}
