using Godot;
using PlannerAabb = Ballistic.Planner.Geometry.Aabb;
using SystemVector3 = System.Numerics.Vector3;

namespace Ballistic.Addon;

/// <summary>
/// The level region a jump roadmap covers, in the manner of <c>NavigationRegion3D</c>: the visual meshes below
/// this node's parent are the level the roadmap is baked on. Later versions bake and hold the roadmap itself;
/// this one gathers the level's world bounds when it enters the tree.
/// </summary>
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpRoadmap3D.svg")]
public partial class JumpRoadmap3D : Node3D
{
    /// <summary>World-space bounds (metres, Y up) of every <see cref="MeshInstance3D"/> in the level, found in <see cref="_Ready"/>.</summary>
    public PlannerAabb LevelBounds { get; private set; } = PlannerAabb.Empty;

    /// <summary>How many mesh instances <see cref="_Ready"/> found in the level.</summary>
    public int LevelMeshCount { get; private set; }

    /// <summary>True once <see cref="_Ready"/> has run.</summary>
    public bool IsLevelScanned { get; private set; }

    /// <summary>Collects the level's mesh instances and their world bounds.</summary>
    public override void _Ready()
    {
        Node level = GetParent() ?? this;
        PlannerAabb bounds = PlannerAabb.Empty;
        int count = 0;
        foreach (Node node in level.FindChildren("*", nameof(MeshInstance3D), recursive: true, owned: false))
        {
            if (node is not MeshInstance3D mesh || mesh.Mesh is null)
            {
                continue;
            }

            Aabb world = mesh.GlobalTransform * mesh.GetAabb();
            bounds = PlannerAabb.Union(bounds, new PlannerAabb(ToPlanner(world.Position), ToPlanner(world.End)));
            count++;
        }

        LevelBounds = bounds;
        LevelMeshCount = count;
        IsLevelScanned = true;
        UpdateConfigurationWarnings();
    }

    /// <summary>Warns in the scene tree when there is no level geometry to bake on.</summary>
    public override string[] _GetConfigurationWarnings() =>
        IsLevelScanned && LevelMeshCount == 0
            ? ["No MeshInstance3D below this node's parent: there is no level to plan jumps on."]
            : [];

    private static SystemVector3 ToPlanner(Vector3 v) => new((float)v.X, (float)v.Y, (float)v.Z);
}
