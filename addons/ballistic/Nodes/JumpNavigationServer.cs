#nullable enable
using System.Collections.Generic;
using Ballistic.Runtime;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.DebugDraw;
using Ballistic.Runtime.Hosting;
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// The Ballistic runtime in the scene tree, registered as the autoload <c>JumpNavigationServer</c> when the plugin is
/// enabled (like Godot's <c>NavigationServer3D</c>, it owns the maps the nodes register with). It owns one
/// <see cref="JumpWorld"/>: <see cref="JumpRoadmap3D"/> nodes add character kinds (with or without a roadmap yet),
/// <see cref="JumpAgent3D"/> nodes add agents (entities), and every physics frame the world's systems step at their
/// fixed tick (the ticks the frame owes, in one <see cref="JumpWorld.Step(int)"/>), before the agent nodes read their
/// entities' components and events. It also draws the debug view (roadmaps, current paths, cones) with an
/// <see cref="ImmediateMesh"/> when the project settings <c>ballistic/debug/draw_roadmaps</c> or
/// <c>ballistic/debug/draw_paths</c> are on. No planning logic here.
/// </summary>
public partial class JumpNavigationServer : Node
{
    /// <summary>Project setting: draw the registered roadmaps at runtime.</summary>
    public const string DrawRoadmapsSetting = "ballistic/debug/draw_roadmaps";

    /// <summary>Project setting: draw each agent's current path and its jumps' cones at runtime.</summary>
    public const string DrawPathsSetting = "ballistic/debug/draw_paths";

    private readonly DebugLines _lines = new(1024);
    private readonly List<JumpRoadmap3D> _roadmaps = [];
    private readonly List<JumpAgent3D> _agents = [];
    private ImmediateMesh? _debugMesh;
    private MeshInstance3D? _debugInstance;
    private StandardMaterial3D? _debugMaterial;
    private FixedTickClock? _clock;
    private DebugPalette _palette = DebugPalette.GodotDefaults;

    /// <summary>The server in the tree; created on first use when the autoload is missing.</summary>
    public static JumpNavigationServer? Singleton { get; private set; }

    /// <summary>The engine-free world: kinds, agents, systems; with a real-time wait for late animations (<see cref="WorldSettings.RealTime"/>), as a game stepping at its physics rate needs.</summary>
    public JumpWorld World { get; } = new(WorldSettings.RealTime);

    /// <summary>Draw the registered roadmaps (stances and jumps); starts from <see cref="DrawRoadmapsSetting"/>.</summary>
    public bool DrawRoadmaps { get; set; }

    /// <summary>Draw the agents' current paths and cones; starts from <see cref="DrawPathsSetting"/>.</summary>
    public bool DrawPaths { get; set; }

    /// <summary>
    /// The server for nodes in <paramref name="from"/>'s tree: the autoload, or one added to the root (deferred, the
    /// tree may be busy) when the plugin's autoload is not registered.
    /// </summary>
    public static JumpNavigationServer Get(Node from)
    {
        if (Singleton is not null && IsInstanceValid(Singleton))
        {
            return Singleton;
        }

        var server = new JumpNavigationServer { Name = nameof(JumpNavigationServer) };
        Singleton = server;
        Window root = from.GetTree().Root;
        Callable.From(() => root.AddChild(server)).CallDeferred();
        return server;
    }

    /// <summary>Becomes the singleton and reads the debug settings.</summary>
    public override void _EnterTree()
    {
        Singleton = this;
        ProcessPhysicsPriority = -100; // step the world before the agent nodes read it
        DrawRoadmaps = ProjectSettings.GetSetting(DrawRoadmapsSetting, false).AsBool();
        DrawPaths = ProjectSettings.GetSetting(DrawPathsSetting, false).AsBool();
        _palette = DebugMeshes.Palette();
    }

    /// <summary>Stops the world's background work.</summary>
    public override void _ExitTree()
    {
        if (Singleton == this)
        {
            Singleton = null;
        }

        World.Dispose();
    }

    /// <summary>Steps the runtime at its fixed tick and redraws the debug view.</summary>
    public override void _PhysicsProcess(double delta)
    {
        // At most four ticks a frame (a long hitch does not freeze the game catching up); a bad delta adds nothing.
        _clock ??= new FixedTickClock(World.Settings.TickSeconds, maxTicksPerFrame: 4);
        World.Step(_clock.Advance(delta));

        DrawDebug();
    }

    /// <summary>Adds a roadmap node to the debug view (called by <see cref="JumpRoadmap3D"/>).</summary>
    internal void Track(JumpRoadmap3D roadmap)
    {
        if (!_roadmaps.Contains(roadmap))
        {
            _roadmaps.Add(roadmap);
        }
    }

    /// <summary>Removes a roadmap node from the debug view.</summary>
    internal void Untrack(JumpRoadmap3D roadmap) => _roadmaps.Remove(roadmap);

    /// <summary>Adds an agent node to the debug view (called by <see cref="JumpAgent3D"/>).</summary>
    internal void Track(JumpAgent3D agent)
    {
        if (!_agents.Contains(agent))
        {
            _agents.Add(agent);
        }
    }

    /// <summary>Removes an agent node from the debug view.</summary>
    internal void Untrack(JumpAgent3D agent) => _agents.Remove(agent);

    private void DrawDebug()
    {
        if (!DrawRoadmaps && !DrawPaths)
        {
            if (_debugInstance is not null)
            {
                _debugInstance.Visible = false;
            }

            return;
        }

        _lines.Clear();
        var settings = new DebugDrawSettings { Colors = _palette };
        if (DrawRoadmaps)
        {
            foreach (JumpRoadmap3D roadmap in _roadmaps)
            {
                if (roadmap.LoadedRoadmap is { } frozen)
                {
                    _lines.AddRoadmapNodes(frozen, settings);
                    _lines.AddRoadmapJumps(frozen, settings);
                }
            }
        }

        if (DrawPaths)
        {
            foreach (JumpAgent3D agent in _agents)
            {
                agent.AddDebugLines(_lines, settings);
            }
        }

        EnsureDebugMesh();
        DebugMeshes.Fill(_debugMesh!, _debugMaterial!, _lines);
        _debugInstance!.Visible = true;
    }

    private void EnsureDebugMesh()
    {
        if (_debugMesh is not null)
        {
            return;
        }

        _debugMesh = new ImmediateMesh();
        _debugMaterial = DebugMeshes.LineMaterial();
        _debugInstance = new MeshInstance3D { Mesh = _debugMesh, CastShadow = GeometryInstance3D.ShadowCastingSetting.Off, Name = "BallisticDebug" };
        AddChild(_debugInstance);
    }
}
