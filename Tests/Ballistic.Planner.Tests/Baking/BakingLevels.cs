using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Tests.Support;
using Ballistic.Runtime.Baking;

namespace Ballistic.Planner.Tests.Baking;

/// <summary>
/// A small level (a 12 × 6 m floor and a 2 × 1 × 2 m block on it) given twice: as a Godot node layer would give it
/// to <see cref="SourceGeometry"/> (the floor as clockwise <c>Mesh.GetFaces()</c> triangles in a rotated, moved local
/// frame; the block as a <c>BoxShape3D</c>), and built directly for the planner, counter-clockwise in world space.
/// </summary>
internal static class BakingLevels
{
    /// <summary>The floor's local-to-world transform: a quarter turn about +Y (local X to world −Z), then a move by (2, 0, 1).</summary>
    public static readonly Matrix4x4 FloorToWorld = SourceGeometry.FromBasis(new Vector3(0f, 0f, -1f), Vector3.UnitY, Vector3.UnitX, new Vector3(2f, 0f, 1f));

    /// <summary>The block's size and centre (world), metres.</summary>
    public static readonly Vector3 BlockSize = new(2f, 1f, 2f);

    /// <summary>Where the block's centre stands.</summary>
    public static readonly Vector3 BlockCentre = new(3f, 0.5f, 0f);

    /// <summary>Settings of the shared bake: small and quick.</summary>
    public static readonly BakeSettings Settings = new() { Seed = 3, MaxNodes = 40, Threads = 2 };

    private static readonly Lazy<BakeOutcome> SharedBake = new(() =>
    {
        using BakeJob job = BakeJob.Start(FromSources().Build(), CharacterPresets.Skeleton(), Settings);
        return job.Wait();
    });

    /// <summary>The planner's level: floor and block, counter-clockwise, world space.</summary>
    public static Level Planner() =>
        new LevelBuilder("planner").AddFloor(-6f, -3f, 6f, 3f, 0f).AddBox(BlockCentre - (BlockSize / 2f), BlockCentre + (BlockSize / 2f)).Build();

    /// <summary>The same level as a node layer gives it: Godot-style clockwise floor faces in the floor's frame, and a box shape.</summary>
    public static SourceGeometry FromSources(Vector3? blockCentre = null) =>
        new SourceGeometry("Level/JumpRoadmap3D")
            .AddFaces("Level/Floor/MeshInstance3D", GodotFloorFaces(), FloorToWorld, FaceWinding.Clockwise)
            .AddBox("Level/Block/CollisionShape3D", BlockSize, Matrix4x4.CreateTranslation(blockCentre ?? BlockCentre));

    /// <summary>
    /// The floor's faces as Godot's <c>Mesh.GetFaces()</c> would give them: three vertices per triangle, clockwise
    /// seen from above, in the floor's local frame.
    /// </summary>
    public static Vector3[] GodotFloorFaces()
    {
        Level world = new LevelBuilder("floor").AddFloor(-6f, -3f, 6f, 3f, 0f).Build();
        var faces = new List<Vector3>();
        foreach (Planner.Geometry.Triangle t in world.Triangles)
        {
            // Clockwise: the planner's (a, b, c) becomes (a, c, b).
            faces.AddRange([ToFloorFrame(t.A), ToFloorFrame(t.C), ToFloorFrame(t.B)]);
        }

        return [.. faces];
    }

    /// <summary>The inverse of <see cref="FloorToWorld"/>, exact for these small whole and half numbers.</summary>
    private static Vector3 ToFloorFrame(Vector3 world) => new(1f - world.Z, world.Y, world.X - 2f);

    /// <summary>A bake of <see cref="FromSources"/> for the skeleton through a <see cref="BakeJob"/>, shared by the tests.</summary>
    public static BakeOutcome Baked => SharedBake.Value;
}
