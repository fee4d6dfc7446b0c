namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// The Godot 4.7 engine classes our scenes may use as a node <c>type=</c> (or a scripted resource's type), with the
/// properties each adds, so that a scene property can be told apart from a typo. A node type missing here fails the
/// scene tests: add the class, its parent and its properties below (every class up to <c>Object</c> must be listed).
/// </summary>
/// <remarks>
/// <para>
/// Each list was confirmed against the Godot class reference with the search tool: the page named in the comment
/// (docs corpus, <c>docs.godotengine.org/en/{4.7,latest,stable}/classes/class_*.html</c>) and, where the stored page's
/// excerpt stopped before its property table, the reference's source for the same class
/// (<c>godotengine/godot doc/classes/*.xml</c>, or <c>godotengine/godot-docs classes/class_*.rst</c>, a 4.5+ revision
/// unless said otherwise). Properties that Godot stores but the reference does not list (<c>script</c>,
/// <c>metadata/…</c>, <c>_import_path</c>, animation <c>libraries</c>, skeleton <c>bones/…</c>) are marked "storage".
/// </para>
/// <para>
/// Deprecated properties still accepted by the engine are kept (they load), so an older scene does not fail here
/// for a reason Godot would not fail it for.
/// </para>
/// </remarks>
public static class GodotClasses
{
    private static readonly Dictionary<string, GodotClass> Table = Build(
        // Object: no listed properties; `script` and `metadata/*` are storage every object accepts
        // (docs.godotengine.org/en/latest/classes/class_node.html notes `script` belongs to Object).
        new("Object", null, ["script"], ["metadata/"]),

        // RefCounted adds none. Resource: docs.godotengine.org/en/4.3/classes/class_resource.html (Inherits: RefCounted <
        // Object; its table is cut from the excerpt) with the setters set_local_to_scene, set_name, set_path and
        // set_scene_unique_id of godot-rust's generated Resource (docs.rs godot 0.4.1) behind these four properties.
        new("RefCounted", "Object", [], []),
        new("Resource", "RefCounted", ["resource_local_to_scene", "resource_name", "resource_path", "resource_scene_unique_id"], []),

        // Node: godot-docs classes/class_node.rst (4.5+ revision, with accessibility methods); `_import_path` is storage.
        new("Node", "Object", [
            "auto_translate_mode", "editor_description", "multiplayer", "name", "owner", "physics_interpolation_mode",
            "process_mode", "process_physics_priority", "process_priority", "process_thread_group",
            "process_thread_group_order", "process_thread_messages", "scene_file_path", "unique_name_in_owner",
            "_import_path",
        ], []),

        // Node3D: docs.godotengine.org/en/stable/classes/class_node3d.html; members from godotengine/godot doc/classes/Node3D.xml.
        new("Node3D", "Node", [
            "basis", "global_basis", "global_position", "global_rotation", "global_rotation_degrees", "global_transform",
            "position", "quaternion", "rotation", "rotation_degrees", "rotation_edit_mode", "rotation_order", "scale",
            "top_level", "transform", "visibility_parent", "visible",
        ], []),

        // VisualInstance3D: godot-docs classes/class_visualinstance3d.rst.
        new("VisualInstance3D", "Node3D", ["layers", "sorting_offset", "sorting_use_aabb_center"], []),

        // GeometryInstance3D: godot-docs classes/class_geometryinstance3d.rst; `instance_shader_parameters/*` is storage.
        new("GeometryInstance3D", "VisualInstance3D", [
            "cast_shadow", "custom_aabb", "extra_cull_margin", "gi_lightmap_scale", "gi_mode", "ignore_occlusion_culling",
            "lod_bias", "material_overlay", "material_override", "transparency", "visibility_range_begin",
            "visibility_range_begin_margin", "visibility_range_end", "visibility_range_end_margin",
            "visibility_range_fade_mode",
        ], ["instance_shader_parameters/"]),

        // MeshInstance3D: docs.godotengine.org/en/stable/classes/class_meshinstance3d.html (mesh, skeleton, skin);
        // `surface_material_override/N` and `blend_shapes/NAME` are storage.
        new("MeshInstance3D", "GeometryInstance3D", ["mesh", "skeleton", "skin"], ["surface_material_override/", "blend_shapes/"]),

        // Label3D: godotengine/godot doc/classes/Label3D.xml (has texture_smooth_pixel_filter, a 4.6+ member).
        new("Label3D", "GeometryInstance3D", [
            "alpha_antialiasing_edge", "alpha_antialiasing_mode", "alpha_cut", "alpha_hash_scale", "alpha_scissor_threshold",
            "autowrap_mode", "billboard", "double_sided", "fixed_size", "font", "font_size", "horizontal_alignment",
            "justification_flags", "language", "line_spacing", "modulate", "no_depth_test", "offset", "outline_modulate",
            "outline_render_priority", "outline_size", "pixel_size", "render_priority", "shaded",
            "structured_text_bidi_override", "structured_text_bidi_override_options", "text", "text_direction",
            "texture_filter", "texture_smooth_pixel_filter", "uppercase", "vertical_alignment", "width",
        ], []),

        // Camera3D: godotengine/godot doc/classes/Camera3D.xml (with compositor, 4.3+).
        new("Camera3D", "Node3D", [
            "attributes", "compositor", "cull_mask", "current", "doppler_tracking", "environment", "far", "fov",
            "frustum_offset", "h_offset", "keep_aspect", "near", "projection", "size", "v_offset",
        ], []),

        // Light3D: godotengine/godot doc/classes/Light3D.xml (with shadow_caster_mask, 4.4+).
        new("Light3D", "VisualInstance3D", [
            "distance_fade_begin", "distance_fade_enabled", "distance_fade_length", "distance_fade_shadow", "editor_only",
            "light_angular_distance", "light_bake_mode", "light_color", "light_cull_mask", "light_energy",
            "light_indirect_energy", "light_intensity_lumens", "light_intensity_lux", "light_negative", "light_projector",
            "light_size", "light_specular", "light_temperature", "light_volumetric_fog_energy", "shadow_bias", "shadow_blur",
            "shadow_caster_mask", "shadow_enabled", "shadow_normal_bias", "shadow_opacity", "shadow_reverse_cull_face",
            "shadow_transmittance_bias",
        ], []),

        // DirectionalLight3D: godotengine/godot doc/classes/DirectionalLight3D.xml.
        new("DirectionalLight3D", "Light3D", [
            "directional_shadow_blend_splits", "directional_shadow_fade_start", "directional_shadow_max_distance",
            "directional_shadow_mode", "directional_shadow_pancake_size", "directional_shadow_split_1",
            "directional_shadow_split_2", "directional_shadow_split_3", "sky_mode",
        ], []),

        // OmniLight3D: godotengine/godot doc/classes/OmniLight3D.xml.
        new("OmniLight3D", "Light3D", ["omni_attenuation", "omni_range", "omni_shadow_mode"], []),

        // WorldEnvironment: docs.godotengine.org/en/4.7/classes/class_worldenvironment.html (whole page in the excerpt).
        new("WorldEnvironment", "Node", ["camera_attributes", "compositor", "environment"], []),

        // CollisionObject3D: godotengine/godot doc/classes/CollisionObject3D.xml.
        new("CollisionObject3D", "Node3D", [
            "collision_layer", "collision_mask", "collision_priority", "disable_mode", "input_capture_on_drag",
            "input_ray_pickable",
        ], []),

        // PhysicsBody3D: godotengine/godot doc/classes/PhysicsBody3D.xml.
        new("PhysicsBody3D", "CollisionObject3D", [
            "axis_lock_angular_x", "axis_lock_angular_y", "axis_lock_angular_z", "axis_lock_linear_x", "axis_lock_linear_y",
            "axis_lock_linear_z",
        ], []),

        // StaticBody3D: docs.godotengine.org/en/latest/classes/class_staticbody3d.html.
        new("StaticBody3D", "PhysicsBody3D", ["constant_angular_velocity", "constant_linear_velocity", "physics_material_override"], []),

        // CharacterBody3D: godotengine/godot doc/classes/CharacterBody3D.xml (move_and_slide(delta) revision).
        new("CharacterBody3D", "PhysicsBody3D", [
            "floor_block_on_wall", "floor_constant_speed", "floor_max_angle", "floor_snap_length", "floor_stop_on_slope",
            "max_slides", "motion_mode", "platform_floor_layers", "platform_on_leave", "platform_wall_layers", "safe_margin",
            "slide_on_ceiling", "up_direction", "velocity", "wall_min_slide_angle",
        ], []),

        // CollisionShape3D: docs.godotengine.org/en/latest/classes/class_collisionshape3d.html.
        new("CollisionShape3D", "Node3D", ["debug_color", "debug_fill", "disabled", "shape"], []),

        // Marker3D: docs.godotengine.org/en/stable/classes/class_marker3d.html.
        new("Marker3D", "Node3D", ["gizmo_extents"], []),

        // NavigationRegion3D: docs.godotengine.org/en/latest/classes/class_navigationregion3d.html (page found; its table
        // is cut from the excerpt) and godot-docs classes/class_navigationregion3d.rst (4.1 revision), plus
        // use_edge_connections (4.2+, named on the 4.2+ page's setters).
        new("NavigationRegion3D", "Node3D", [
            "enabled", "enter_cost", "navigation_layers", "navigation_mesh", "travel_cost", "use_edge_connections",
        ], []),

        // NavigationLink3D: godotengine/godot doc/classes/NavigationLink3D.xml.
        new("NavigationLink3D", "Node3D", [
            "bidirectional", "enabled", "end_position", "enter_cost", "navigation_layers", "start_position", "travel_cost",
        ], []),

        // NavigationAgent3D: godotengine/godot doc/classes/NavigationAgent3D.xml (4.7 revision: navigation_layers_cost_map,
        // pathfinding_algorithm, path_search_max_*).
        new("NavigationAgent3D", "Node", [
            "avoidance_enabled", "avoidance_layers", "avoidance_mask", "avoidance_priority", "debug_enabled",
            "debug_path_custom_color", "debug_path_custom_point_size", "debug_use_custom", "height", "keep_y_velocity",
            "max_neighbors", "max_speed", "navigation_layers", "navigation_layers_cost_map", "neighbor_distance",
            "path_desired_distance", "path_height_offset", "path_max_distance", "path_metadata_flags", "path_postprocessing",
            "path_return_max_length", "path_return_max_radius", "path_search_max_distance", "path_search_max_polygons",
            "pathfinding_algorithm", "radius", "simplify_epsilon", "simplify_path", "target_desired_distance",
            "target_position", "time_horizon_agents", "time_horizon_obstacles", "use_3d_avoidance", "velocity",
        ], []),

        // Skeleton3D: godotengine/godot doc/classes/Skeleton3D.xml; `bones/N/{name,parent,rest,enabled,position,rotation,scale}` is storage.
        new("Skeleton3D", "Node3D", ["animate_physical_bones", "modifier_callback_mode_process", "motion_scale", "show_rest_only"], ["bones/"]),

        // AnimationMixer: godotengine/godot doc/classes/AnimationMixer.xml (with root_motion_local, 4.4+); `libraries` is storage.
        new("AnimationMixer", "Node", [
            "active", "audio_max_polyphony", "callback_mode_discrete", "callback_mode_method", "callback_mode_process",
            "deterministic", "reset_on_save", "root_motion_local", "root_motion_track", "root_node", "libraries",
        ], []),

        // AnimationPlayer: docs.godotengine.org/en/stable/classes/class_animationplayer.html (whole table in the excerpt);
        // deprecated method_call_mode, playback_active, playback_process_mode still load (godot-docs
        // classes/class_animationplayer.rst, 4.1 revision); `blend_times` and `next/*` are storage.
        new("AnimationPlayer", "AnimationMixer", [
            "assigned_animation", "autoplay", "current_animation", "current_animation_length", "current_animation_position",
            "movie_quit_on_finish", "playback_auto_capture", "playback_auto_capture_duration",
            "playback_auto_capture_ease_type", "playback_auto_capture_transition_type", "playback_default_blend_time",
            "speed_scale", "method_call_mode", "playback_active", "playback_process_mode", "blend_times",
        ], ["next/"]));

    /// <summary>Every class in the table, by name.</summary>
    public static IReadOnlyDictionary<string, GodotClass> All => Table;

    /// <summary>True when <paramref name="name"/> is a class in the table.</summary>
    public static bool IsKnown(string name) => Table.ContainsKey(name);

    /// <summary><paramref name="name"/> and its ancestors up to <c>Object</c>, nearest first; empty when unknown.</summary>
    public static IReadOnlyList<GodotClass> Chain(string name)
    {
        var chain = new List<GodotClass>();
        for (string? current = name; current is not null && Table.TryGetValue(current, out GodotClass? cls); current = cls.Parent)
        {
            chain.Add(cls);
        }

        return chain;
    }

    /// <summary>True when <paramref name="derived"/> is <paramref name="ancestor"/> or inherits from it (both must be known).</summary>
    public static bool Inherits(string derived, string ancestor) => Chain(derived).Any(c => c.Name == ancestor);

    /// <summary>
    /// True when a scene may set <paramref name="key"/> on an object of class <paramref name="className"/>: a property
    /// of the class or an ancestor, or an indexed property under one of their prefixes.
    /// </summary>
    public static bool HasProperty(string className, string key) =>
        Chain(className).Any(c => c.Properties.Contains(key) || c.Prefixes.Any(p => key.StartsWith(p, StringComparison.Ordinal) && key.Length > p.Length));

    private static Dictionary<string, GodotClass> Build(params GodotClass[] classes) =>
        classes.ToDictionary(c => c.Name, StringComparer.Ordinal);
}
