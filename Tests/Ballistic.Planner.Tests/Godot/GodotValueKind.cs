namespace Ballistic.Planner.Tests.Godot;

/// <summary>What a <see cref="GodotValue"/> parsed from Godot's text variant syntax is.</summary>
public enum GodotValueKind
{
    /// <summary><c>null</c> (also written <c>nil</c>).</summary>
    Null,

    /// <summary><c>true</c> or <c>false</c>.</summary>
    Bool,

    /// <summary>An integer without a fraction or exponent, e.g. <c>-3</c>.</summary>
    Int,

    /// <summary>A number with a fraction or exponent, or <c>inf</c>, <c>-inf</c>, <c>nan</c>.</summary>
    Float,

    /// <summary>A quoted string, <c>"text"</c>.</summary>
    String,

    /// <summary>A string name, <c>&amp;"text"</c>.</summary>
    StringName,

    /// <summary>A node path, <c>^"a/b"</c>.</summary>
    NodePath,

    /// <summary>A bare identifier, only allowed as a type or class argument (e.g. <c>Object(InputEventKey, …)</c>).</summary>
    Identifier,

    /// <summary>A constructor or reference: <c>Vector3(0, 1, 0)</c>, <c>ExtResource("1_x")</c>, <c>Array[int]([1])</c>.</summary>
    Call,

    /// <summary>An untyped array, <c>[a, b]</c>.</summary>
    Array,

    /// <summary>An untyped dictionary, <c>{ "k": v }</c>.</summary>
    Dictionary,
}
