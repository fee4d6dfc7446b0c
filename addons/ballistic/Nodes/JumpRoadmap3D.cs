#nullable enable
using System;
using System.Collections.Generic;
using System.Threading.Tasks;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Baking;
using Ballistic.Runtime;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Links;
using Godot;

namespace Ballistic.Addon;

/// <summary>
/// A jump roadmap over level geometry, in the manner of <c>NavigationRegion3D</c>: its <see cref="Character"/> can
/// jump between the stances of its baked <see cref="Roadmap"/>. The source geometry is parsed like a
/// <c>NavigationMesh</c>'s (mesh instances, static colliders or both; this node's children or a group); the bake runs on
/// a thread (<see cref="BakeRoadmap"/>, <see cref="BakeFinished"/>); a failed or cancelled bake keeps the previous
/// data. At runtime the node registers its region with the <see cref="JumpNavigationServer"/>, and optionally
/// publishes its jumps as one-way links on the world's navigation map. The node only gathers Godot data and
/// forwards it: <see cref="SourceGeometry"/>, <see cref="BakeJob"/>, <see cref="RoadmapData"/>,
/// <see cref="JumpWorld"/> and <see cref="JumpLinkSet"/> decide.
/// </summary>
[Tool]
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpRoadmap3D.svg")]
public partial class JumpRoadmap3D : Node3D
{
    /// <summary>Which scene nodes give source geometry (the names of <c>NavigationMesh.ParsedGeometryType</c>).</summary>
    public enum ParsedGeometry
    {
        /// <summary>Visual meshes (<see cref="MeshInstance3D"/>).</summary>
        MeshInstances = 0,

        /// <summary>Collision shapes of <see cref="StaticBody3D"/> nodes on <see cref="CollisionMask"/> layers.</summary>
        StaticColliders = 1,

        /// <summary>Both.</summary>
        Both = 2,
    }

    /// <summary>Where source geometry is looked for (the names of <c>NavigationMesh.SourceGeometryMode</c>).</summary>
    public enum SourceGeometry3D
    {
        /// <summary>This node's children, recursively.</summary>
        RootNodeChildren = 0,

        /// <summary>The nodes of <see cref="SourceGroupName"/> and their children.</summary>
        GroupsWithChildren = 1,

        /// <summary>Only the nodes of <see cref="SourceGroupName"/>.</summary>
        GroupsExplicit = 2,
    }

    /// <summary>Node metadata giving a source's Coulomb friction μ (a float); the character's default otherwise.</summary>
    public const string FrictionMeta = "jump_friction";

    /// <summary>
    /// Node metadata giving what a second walked on a source costs path searches, in seconds of plain walking (a
    /// float ≥ 1, like a navigation region's travel cost; 1 otherwise). Costs change routes, not the baked roadmap.
    /// </summary>
    public const string TravelCostMeta = "jump_travel_cost";

    /// <summary>
    /// Node metadata giving the seconds path searches add for stepping or landing onto a source from other surfaces (a
    /// float ≥ 0, like a navigation region's enter cost; 0 otherwise).
    /// </summary>
    public const string EnterCostMeta = "jump_enter_cost";

    private BakeJob? _job;
    private string _lastBakeError = "";
    private string? _staleness;
    private KindHandle _worldKind;
    private Task<(CharacterKind Kind, JumpLinkSet? Links)>? _kindTask;
    private CharacterKind? _kind;
    private readonly List<Rid> _links = [];
    private JumpLinkSet? _linkSet;

    /// <summary>Emitted when a bake ends: succeeded (new data in <see cref="Roadmap"/>), failed or cancelled (<see cref="GetLastBakeError"/>).</summary>
    [Signal]
    public delegate void BakeFinishedEventHandler();

    /// <summary>The character kind the roadmap is for.</summary>
    [Export]
    public JumpCharacter? Character { get; set; }

    /// <summary>The baked roadmap; <c>null</c> before the first bake.</summary>
    [Export]
    public JumpRoadmapData? Roadmap { get; set; }

    /// <summary>Which nodes give source geometry.</summary>
    [ExportGroup("Geometry")]
    [Export]
    public ParsedGeometry ParsedGeometryType { get; set; } = ParsedGeometry.MeshInstances;

    /// <summary>Physics layers whose static colliders are parsed (with <see cref="ParsedGeometry.StaticColliders"/> or <see cref="ParsedGeometry.Both"/>).</summary>
    [Export(PropertyHint.Layers3DPhysics)]
    public uint CollisionMask { get; set; } = uint.MaxValue;

    /// <summary>Where source geometry is looked for.</summary>
    [Export]
    public SourceGeometry3D SourceGeometryMode { get; set; } = SourceGeometry3D.RootNodeChildren;

    /// <summary>The group of source nodes for the group modes.</summary>
    [Export]
    public StringName SourceGroupName { get; set; } = "jump_source_geometry";

    /// <summary>The bake's seed: the same seed and geometry give the same roadmap.</summary>
    [ExportGroup("Bake")]
    [Export]
    public int Seed { get; set; } = 1;

    /// <summary>The bake's node budget (stances).</summary>
    [Export(PropertyHint.Range, "8,100000,1,or_greater")]
    public int MaxNodes { get; set; } = 400;

    /// <summary>The bake's time limit, seconds; 0 for none.</summary>
    [Export(PropertyHint.Range, "0,3600,0.1,or_greater,suffix:s")]
    public double TimeLimitSeconds { get; set; }

    /// <summary>At runtime, bake on a thread when no roadmap was baked in the editor (handy for prototypes).</summary>
    [Export]
    public bool BakeOnReadyIfMissing { get; set; } = true;

    /// <summary>
    /// What every jump costs the character's path searches beyond its flight time, in seconds of walking: a path jumps
    /// only where that (and <see cref="JumpHeightEffort"/>) saves more walking, as a navigation region's enter cost.
    /// </summary>
    [ExportGroup("Costs")]
    [Export(PropertyHint.Range, "0,60,0.1,or_greater,suffix:s")]
    public float JumpEffort { get; set; } = QuerySettings.DefaultJumpEffort;

    /// <summary>
    /// What a jump costs on top of <see cref="JumpEffort"/> per metre its takeoff could lift the body (its energy
    /// height, |v|²/2g), in seconds of walking per metre: raise it to make the character walk round walls it could vault.
    /// </summary>
    [Export(PropertyHint.Range, "0,20,0.05,or_greater,suffix:s/m")]
    public float JumpHeightEffort { get; set; } = QuerySettings.DefaultJumpHeightEffort;

    /// <summary>Publish the roadmap's jumps as one-way links on the world's navigation map at runtime.</summary>
    [ExportGroup("Navigation Links")]
    [Export]
    public bool PublishNavigationLinks { get; set; }

    /// <summary>The navigation layers of the published links.</summary>
    [Export(PropertyHint.Layers3DNavigation)]
    public uint NavigationLayers { get; set; } = 1;

    /// <summary>The walking speed (m/s) the links' travel cost is measured against: a jump costs its flight time at this speed.</summary>
    [Export(PropertyHint.Range, "0.1,20,0.1,or_greater,suffix:m/s")]
    public float LinkReferenceSpeed { get; set; } = 3f;

    /// <summary>Jumps shorter than this (horizontal metres between takeoff and landing) are left to the navmesh.</summary>
    [Export(PropertyHint.Range, "0,10,0.05,or_greater,suffix:m")]
    public float LinkMinDistance { get; set; } = 1f;

    /// <summary>At most this many links are published.</summary>
    [Export(PropertyHint.Range, "1,100000,1,or_greater")]
    public int MaxLinks { get; set; } = 2000;

    /// <summary>The roadmap loaded for this level and character at runtime (or after a bake); <c>null</c> before.</summary>
    public Roadmap? LoadedRoadmap { get; private set; }

    /// <summary>The published links, by index (the node's agents look up the link they reached).</summary>
    public JumpLinkSet? NavigationLinks => _linkSet;

    /// <summary>Parses the level in the editor (to warn about a stale roadmap) or registers the region at runtime.</summary>
    public override void _Ready()
    {
        AddToGroup(GroupName);
        if (Engine.IsEditorHint())
        {
            RefreshStaleness();
            return;
        }

        JumpNavigationServer.Get(this).Track(this);
        if (Roadmap is { RoadmapBytes.Length: > 0 })
        {
            StartLoadingRuntimeKind();
        }
        else if (BakeOnReadyIfMissing)
        {
            BakeRoadmap(onThread: true);
        }
        else
        {
            GD.PushWarning($"{GetPath()}: no roadmap is baked; select the node and press Bake Jump Roadmap.");
        }
    }

    /// <summary>The group every roadmap node joins, so that agents can find one.</summary>
    public const string GroupName = "jump_roadmaps";

    /// <summary>Frees the region, the links and any bake.</summary>
    public override void _ExitTree()
    {
        _job?.Dispose();
        _job = null;
        UnpublishLinks();
        if (JumpNavigationServer.Singleton is { } server)
        {
            server.Untrack(this);
            if (_worldKind.Assigned)
            {
                server.World.RemoveKind(_worldKind);
            }
        }

        _worldKind = default;
    }

    /// <summary>Finishes a threaded bake or a runtime load when it is done.</summary>
    public override void _Process(double delta)
    {
        if (_job is { IsBaking: false, Outcome: { } outcome })
        {
            _job.Dispose();
            _job = null;
            FinishBake(outcome);
        }

        if (_kindTask is { IsCompleted: true } task)
        {
            _kindTask = null;
            if (task.IsCompletedSuccessfully)
            {
                AttachKind(task.Result.Kind, task.Result.Links);
            }
            else
            {
                GD.PushError($"{GetPath()}: the roadmap cannot be used: {task.Exception?.GetBaseException().Message}");
            }
        }
    }

    /// <summary>
    /// Bakes the roadmap from the current source geometry and character. With <paramref name="onThread"/> the bake runs
    /// on a background thread (poll <see cref="IsBaking"/>, wait for <see cref="BakeFinished"/>); otherwise it blocks.
    /// A bake that cannot start (no character, no geometry, a bad rig) ends at once with the reason in
    /// <see cref="GetLastBakeError"/> and <see cref="BakeFinished"/>; the previous data is kept whenever a bake fails.
    /// </summary>
    public void BakeRoadmap(bool onThread = true)
    {
        if (_job is not null)
        {
            GD.PushWarning($"{Name}: a bake is already running.");
            return;
        }

        Level level;
        ReducedCharacter reduced;
        BakeSettings settings;
        try
        {
            settings = BakeJob.Settings(Seed, MaxNodes, TimeLimitSeconds);
            (_, reduced) = LoadCharacter();
            level = ParseSourceGeometry().Build();
        }
        catch (Exception e) when (e is Planner.IO.BallisticInputException or ArgumentException or InvalidOperationException)
        {
            FailBake(e.Message);
            return;
        }

        _lastBakeError = "";
        if (onThread)
        {
            _job = BakeJob.Start(level, reduced, settings);
        }
        else
        {
            FinishBake(BakeJob.Run(level, reduced, settings));
        }
    }

    /// <summary>True while a threaded bake runs.</summary>
    public bool IsBaking() => _job is { IsBaking: true };

    /// <summary>Cancels a running bake; it ends cancelled and the previous data stays.</summary>
    public void CancelBake() => _job?.Cancel();

    /// <summary>The running bake's progress, 0 to 1.</summary>
    public double GetBakeProgress() => _job?.Progress.Fraction ?? 0.0;

    /// <summary>The running bake's progress in words ("214 / 400 stances, 1,930 jumps, 3.1 s").</summary>
    public string GetBakeStatusText() => _job?.Progress.Text ?? "";

    /// <summary>Why the last bake failed or was cancelled; empty after a success.</summary>
    public string GetLastBakeError() => _lastBakeError;

    /// <summary>The kind of this roadmap in the server's world (created on first use, without a roadmap, so agents readied first can name it).</summary>
    public KindHandle GetWorldKind()
    {
        if (!_worldKind.Assigned && !Engine.IsEditorHint())
        {
            _worldKind = JumpNavigationServer.Get(this).World.CreateKind(IsInsideTree() ? GetPath().ToString() : Name.ToString());
        }

        return _worldKind;
    }

    /// <summary>Warns when there is no character, nothing is baked, or the level or character changed since the bake.</summary>
    public override string[] _GetConfigurationWarnings()
    {
        var warnings = new List<string>();
        if (Character is null)
        {
            warnings.Add("No Character: assign a JumpCharacter (e.g. res://Scenes/characters/skeleton.tres).");
        }

        if (Roadmap is null || Roadmap.RoadmapBytes.Length == 0)
        {
            warnings.Add("No roadmap is baked: select this node and press Bake Jump Roadmap in the 3D toolbar.");
        }
        else if (_staleness is not null)
        {
            warnings.Add($"The baked roadmap is out of date: {_staleness}. Bake it again.");
        }

        if (_lastBakeError.Length > 0)
        {
            warnings.Add($"The last bake failed: {_lastBakeError}");
        }

        return [.. warnings];
    }

    /// <summary>The level as the planner sees it: every source node's triangles in world space.</summary>
    /// <exception cref="Planner.Levels.LevelException">A source is malformed, or there is no triangle at all (the message names the node).</exception>
    public SourceGeometry ParseSourceGeometry()
    {
        var geometry = new SourceGeometry(IsInsideTree() ? GetPath().ToString() : Name.ToString());
        var seen = new HashSet<ulong>();
        foreach (Node root in SourceRoots())
        {
            bool children = SourceGeometryMode != SourceGeometry3D.GroupsExplicit;
            AddSource(geometry, root, seen);
            if (children)
            {
                foreach (Node node in root.FindChildren("*", "", recursive: true, owned: false))
                {
                    AddSource(geometry, node, seen);
                }
            }
        }

        return geometry;
    }

    /// <summary>Draws the roadmap in the editor (called by the gizmo plugin).</summary>
    internal (Runtime.DebugDraw.DebugLineRange Nodes, Runtime.DebugDraw.DebugLineRange Jumps) AddGizmoLines(Runtime.DebugDraw.DebugLines lines, Runtime.DebugDraw.DebugDrawSettings settings)
    {
        Roadmap? roadmap = LoadedRoadmap;
        if (roadmap is null && Roadmap is { RoadmapBytes.Length: > 0 } data && Character is not null)
        {
            try
            {
                roadmap = RoadmapFile.FromBytes(data.RoadmapBytes, data.ResourcePath);
                LoadedRoadmap = roadmap;
            }
            catch (Planner.IO.BallisticInputException e)
            {
                GD.PushWarning($"{Name}: the baked roadmap cannot be read: {e.Message}");
                return default;
            }
        }

        return roadmap is null ? default : (lines.AddRoadmapNodes(roadmap, settings), lines.AddRoadmapJumps(roadmap, settings));
    }

    private IEnumerable<Node> SourceRoots() => SourceGeometryMode == SourceGeometry3D.RootNodeChildren
        ? [this]
        : GetTree().GetNodesInGroup(SourceGroupName);

    private void AddSource(SourceGeometry geometry, Node node, HashSet<ulong> seen)
    {
        if (!seen.Add(node.GetInstanceId()))
        {
            return;
        }

        // The float metadata of a node, or null when it has none.
        static float? Meta(Node source, string key) => source.HasMeta(key) ? source.GetMeta(key).AsSingle() : null;

        float? friction = Meta(node, FrictionMeta);
        float? travelCost = Meta(node, TravelCostMeta);
        float? enterCost = Meta(node, EnterCostMeta);
        if (ParsedGeometryType != ParsedGeometry.StaticColliders && node is MeshInstance3D { Mesh: { } mesh } instance)
        {
            geometry.AddFaces(instance.GetPath().ToString(), mesh.GetFaces().Select(GodotMath.ToNumerics).ToArray(), instance.GlobalTransform.ToNumerics(), FaceWinding.Clockwise, friction, travelCost ?? 1f, enterCost ?? 0f);
        }

        if (ParsedGeometryType != ParsedGeometry.MeshInstances && node is CollisionShape3D { Disabled: false, Shape: { } shape } collision
            && collision.GetParent() is StaticBody3D body && (body.CollisionLayer & CollisionMask) != 0)
        {
            string name = collision.GetPath().ToString();
            float? bodyFriction = friction ?? Meta(body, FrictionMeta);
            float bodyTravel = travelCost ?? Meta(body, TravelCostMeta) ?? 1f;
            float bodyEnter = enterCost ?? Meta(body, EnterCostMeta) ?? 0f;
            switch (shape)
            {
                case BoxShape3D box:
                    geometry.AddBox(name, box.Size.ToNumerics(), collision.GlobalTransform.ToNumerics(), bodyFriction, bodyTravel, bodyEnter);
                    break;
                case ConcavePolygonShape3D concave:
                    geometry.AddFaces(name, concave.GetFaces().Select(GodotMath.ToNumerics).ToArray(), collision.GlobalTransform.ToNumerics(), FaceWinding.Clockwise, bodyFriction, bodyTravel, bodyEnter);
                    break;
                default:
                    GD.PushWarning($"{name}: {shape.GetClass()} is not parsed as jump source geometry (boxes and concave polygons are); give the level a mesh or one of those.");
                    break;
            }
        }
    }

    private (CharacterModel Model, ReducedCharacter Reduced) LoadCharacter() =>
        Character is null
            ? throw new InvalidOperationException($"{Name}: no Character is assigned; set a JumpCharacter (e.g. res://Scenes/characters/skeleton.tres).")
            : Character.Load();

    private void FinishBake(BakeOutcome outcome)
    {
        if (outcome.Succeeded && outcome.Data is { } data)
        {
            Roadmap = JumpRoadmapData.FromData(data);
            LoadedRoadmap = outcome.Roadmap;
            _lastBakeError = "";
            _staleness = null;
            if (!Engine.IsEditorHint())
            {
                StartLoadingRuntimeKind();
            }
        }
        else
        {
            _lastBakeError = outcome.ToString();
            GD.PushWarning($"{Name}: {_lastBakeError}");
        }

        UpdateGizmos();
        UpdateConfigurationWarnings();
        EmitSignal(SignalName.BakeFinished);
    }

    /// <summary>A bake that could not start: the previous data stays.</summary>
    private void FailBake(string reason)
    {
        _lastBakeError = $"bake failed: {reason}";
        GD.PushWarning($"{Name}: {_lastBakeError}");
        UpdateConfigurationWarnings();
        EmitSignal(SignalName.BakeFinished);
    }

    private void RefreshStaleness()
    {
        _staleness = null;
        if (Roadmap is not { RoadmapBytes.Length: > 0 } data || Character is null)
        {
            return;
        }

        try
        {
            (_, ReducedCharacter reduced) = LoadCharacter();
            _staleness = data.ToData().Staleness(ParseSourceGeometry().Fingerprint, reduced);
        }
        catch (Exception e) when (e is Planner.IO.BallisticInputException or ArgumentException or InvalidOperationException)
        {
            _staleness = e.Message;
        }

        UpdateConfigurationWarnings();
    }

    /// <summary>Parses the level on the main thread, then builds the planning scene, roadmap and animator on a worker thread.</summary>
    private void StartLoadingRuntimeKind()
    {
        Level level;
        CharacterModel model;
        ReducedCharacter reduced;
        try
        {
            (model, reduced) = LoadCharacter();
            level = ParseSourceGeometry().Build();
        }
        catch (Exception e) when (e is Planner.IO.BallisticInputException or ArgumentException or InvalidOperationException)
        {
            GD.PushError($"{GetPath()}: {e.Message}");
            return;
        }

        RoadmapData data = Roadmap!.ToData();
        string name = string.IsNullOrEmpty(Roadmap.ResourcePath) ? GetPath().ToString() : Roadmap.ResourcePath;
        (float effort, float heightEffort) = (JumpEffort, JumpHeightEffort);
        JumpLinkSettings? links = PublishNavigationLinks
            ? new JumpLinkSettings { ReferenceSpeed = LinkReferenceSpeed, MinHorizontalDistance = LinkMinDistance, MaxLinks = MaxLinks }
            : null;
        _kindTask = Task.Run(() =>
        {
            var scene = PlanningScene.Create(level, reduced);
            Roadmap roadmap = data.Load(level, reduced, name);
            var animator = new JumpAnimator(scene, model);
            JumpLinkSet? set = links is null ? null : JumpLinkSet.Build(roadmap, links, animator, System.Environment.ProcessorCount);
            return (new CharacterKind(scene, roadmap, animator) { JumpEffort = effort, JumpHeightEffort = heightEffort }, set);
        });
    }

    private void AttachKind(CharacterKind kind, JumpLinkSet? links)
    {
        _kind = kind;
        LoadedRoadmap = kind.Roadmap;
        var result = JumpNavigationServer.Get(this).World.ReplaceKind(GetWorldKind(), kind);
        if (!result.Ok)
        {
            GD.PushError($"{GetPath()}: {result.Reason}");
            return;
        }

        if (links is not null)
        {
            PublishLinks(links);
        }
    }

    /// <summary>Creates one one-way navigation server link per jump of <paramref name="links"/>, in their order.</summary>
    private void PublishLinks(JumpLinkSet links)
    {
        UnpublishLinks();
        _linkSet = links;
        Rid map = GetWorld3D().NavigationMap;
        foreach (JumpLink link in _linkSet.Links)
        {
            Rid rid = NavigationServer3D.LinkCreate();
            NavigationServer3D.LinkSetMap(rid, map);
            NavigationServer3D.LinkSetBidirectional(rid, false);
            NavigationServer3D.LinkSetStartPosition(rid, link.Start.ToGodot());
            NavigationServer3D.LinkSetEndPosition(rid, link.End.ToGodot());
            NavigationServer3D.LinkSetTravelCost(rid, link.TravelCost);
            NavigationServer3D.LinkSetEnterCost(rid, link.EnterCost);
            NavigationServer3D.LinkSetNavigationLayers(rid, NavigationLayers);
            NavigationServer3D.LinkSetOwnerId(rid, GetInstanceId());
            NavigationServer3D.LinkSetEnabled(rid, true);
            _links.Add(rid);
        }
    }

    private void UnpublishLinks()
    {
        foreach (Rid rid in _links)
        {
            NavigationServer3D.FreeRid(rid);
        }

        _links.Clear();
        _linkSet = null;
    }

    /// <summary>
    /// Where the segment from <paramref name="from"/> to <paramref name="to"/> (world metres) first meets the level as
    /// the planner sees it (no physics bodies needed); <c>null</c> when it misses or the roadmap is not loaded yet.
    /// </summary>
    public Vector3? IntersectLevel(Vector3 from, Vector3 to) =>
        _kind is not null && _kind.Scene.Level.Raycast(from.ToNumerics(), (to - from).ToNumerics(), 1f, out Planner.Collision.RayHit hit)
            ? hit.Point.ToGodot()
            : null;

    /// <summary>The index of a published link (<see cref="JumpLinkSet.Links"/>) from its navigation server id; -1 when it is not ours.</summary>
    public int FindLink(Rid link) => _links.IndexOf(link);
}
