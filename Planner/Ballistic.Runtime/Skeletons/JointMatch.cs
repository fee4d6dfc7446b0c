namespace Ballistic.Runtime.Skeletons;

/// <summary>How a runtime joint found its bone in a target skeleton (tried in this order).</summary>
public enum JointMatch
{
    /// <summary>No bone: the joint is not driven (its children still get their world rotations).</summary>
    None,

    /// <summary>Named by the binding options' rename map.</summary>
    Renamed,

    /// <summary>A bone with exactly the joint's name.</summary>
    Exact,

    /// <summary>A bone with the name Godot's importer gives the joint's name (':' and '/' replaced by '_', see <see cref="GodotBoneNames.Sanitize"/>).</summary>
    Sanitized,

    /// <summary>The only bone whose name equals the joint's ignoring case and separators (see <see cref="GodotBoneNames.LooseKey"/>).</summary>
    Loose,
}
