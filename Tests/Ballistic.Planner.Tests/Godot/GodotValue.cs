using System.Globalization;
using System.Text;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// A value written in Godot's text variant syntax (the right side of <c>key = value</c> and of header attributes), read
/// far enough to get strings, numbers, booleans and <c>ExtResource("id")</c>/<c>SubResource("id")</c> references; any
/// other constructor is kept as a <see cref="GodotValueKind.Call"/> with its arguments.
/// </summary>
public sealed class GodotValue
{
    private static readonly GodotValue[] NoValues = [];
    private static readonly KeyValuePair<GodotValue, GodotValue>[] NoEntries = [];

    private GodotValue(GodotValueKind kind, int line)
    {
        Kind = kind;
        Line = line;
    }

    /// <summary>What the value is.</summary>
    public GodotValueKind Kind { get; }

    /// <summary>The 1-based line the value starts on.</summary>
    public int Line { get; }

    /// <summary>The text of a string, string name or node path; the name of an identifier or call; empty otherwise.</summary>
    public string Text { get; private init; } = "";

    /// <summary>The value of a <see cref="GodotValueKind.Bool"/>.</summary>
    public bool Bool { get; private init; }

    /// <summary>The value of an <see cref="GodotValueKind.Int"/>.</summary>
    public long Int { get; private init; }

    /// <summary>The value of a <see cref="GodotValueKind.Float"/> or <see cref="GodotValueKind.Int"/>.</summary>
    public double Number { get; private init; }

    /// <summary>The items of an array, or the positional arguments of a call.</summary>
    public IReadOnlyList<GodotValue> Items { get; private init; } = NoValues;

    /// <summary>The type arguments of a typed container call, e.g. <c>int</c> in <c>Array[int]([1])</c>.</summary>
    public IReadOnlyList<GodotValue> TypeArguments { get; private init; } = NoValues;

    /// <summary>The entries of a dictionary, or the <c>"key": value</c> arguments of a call such as <c>Object(…)</c>.</summary>
    public IReadOnlyList<KeyValuePair<GodotValue, GodotValue>> Entries { get; private init; } = NoEntries;

    /// <summary>True for a quoted string, string name or node path.</summary>
    public bool IsText => Kind is GodotValueKind.String or GodotValueKind.StringName or GodotValueKind.NodePath;

    /// <summary>The text of a string, string name or node path; null for any other value.</summary>
    public string? AsString() => IsText ? Text : null;

    /// <summary>
    /// True when the value is <c>ExtResource("id")</c> or <c>SubResource("id")</c>; <paramref name="kind"/> is the call's
    /// name and <paramref name="id"/> its argument.
    /// </summary>
    public bool TryGetResourceReference(out string kind, out string id)
    {
        if (Kind == GodotValueKind.Call && Text is "ExtResource" or "SubResource" && Items.Count == 1)
        {
            kind = Text;
            id = Items[0].Kind == GodotValueKind.Int ? Items[0].Int.ToString(CultureInfo.InvariantCulture) : Items[0].Text;
            return true;
        }

        kind = "";
        id = "";
        return false;
    }

    /// <summary>This value and every value nested in it (items, type arguments, entry keys and values), depth first.</summary>
    public IEnumerable<GodotValue> DescendantsAndSelf()
    {
        yield return this;
        foreach (GodotValue child in TypeArguments.Concat(Items).Concat(Entries.SelectMany(e => new[] { e.Key, e.Value })))
        {
            foreach (GodotValue nested in child.DescendantsAndSelf())
            {
                yield return nested;
            }
        }
    }

    /// <summary>Every string value nested in this one (including this one), e.g. the paths of a <c>PackedStringArray</c>.</summary>
    public IEnumerable<string> Strings() => DescendantsAndSelf().Where(v => v.IsText).Select(v => v.Text);

    /// <summary>The value in Godot's syntax, shortened for messages.</summary>
    public override string ToString()
    {
        var text = new StringBuilder();
        Write(text);
        return text.Length <= 80 ? text.ToString() : text.ToString(0, 77) + "...";
    }

    internal static GodotValue Null(int line) => new(GodotValueKind.Null, line);

    internal static GodotValue FromBool(bool value, int line) => new(GodotValueKind.Bool, line) { Bool = value };

    internal static GodotValue FromInt(long value, int line) => new(GodotValueKind.Int, line) { Int = value, Number = value };

    internal static GodotValue FromFloat(double value, int line) => new(GodotValueKind.Float, line) { Number = value };

    internal static GodotValue FromText(GodotValueKind kind, string text, int line) => new(kind, line) { Text = text };

    internal static GodotValue Call(
        string name, IReadOnlyList<GodotValue> typeArguments, IReadOnlyList<GodotValue> items,
        IReadOnlyList<KeyValuePair<GodotValue, GodotValue>> entries, int line) =>
        new(GodotValueKind.Call, line) { Text = name, TypeArguments = typeArguments, Items = items, Entries = entries };

    internal static GodotValue Array(IReadOnlyList<GodotValue> items, int line) => new(GodotValueKind.Array, line) { Items = items };

    internal static GodotValue Dictionary(IReadOnlyList<KeyValuePair<GodotValue, GodotValue>> entries, int line) =>
        new(GodotValueKind.Dictionary, line) { Entries = entries };

    private void Write(StringBuilder text)
    {
        switch (Kind)
        {
            case GodotValueKind.Null:
                text.Append("null");
                break;
            case GodotValueKind.Bool:
                text.Append(Bool ? "true" : "false");
                break;
            case GodotValueKind.Int:
                text.Append(Int.ToString(CultureInfo.InvariantCulture));
                break;
            case GodotValueKind.Float:
                text.Append(Number.ToString("R", CultureInfo.InvariantCulture));
                break;
            case GodotValueKind.String:
                text.Append('"').Append(Text).Append('"');
                break;
            case GodotValueKind.StringName:
                text.Append("&\"").Append(Text).Append('"');
                break;
            case GodotValueKind.NodePath:
                text.Append("^\"").Append(Text).Append('"');
                break;
            case GodotValueKind.Identifier:
                text.Append(Text);
                break;
            case GodotValueKind.Call:
                text.Append(Text);
                if (TypeArguments.Count > 0)
                {
                    text.Append('[');
                    WriteList(text, TypeArguments);
                    text.Append(']');
                }

                text.Append('(');
                WriteList(text, Items);
                WriteEntries(text, Entries, Items.Count > 0);
                text.Append(')');
                break;
            case GodotValueKind.Array:
                text.Append('[');
                WriteList(text, Items);
                text.Append(']');
                break;
            case GodotValueKind.Dictionary:
                text.Append('{');
                WriteEntries(text, Entries, false);
                text.Append('}');
                break;
        }
    }

    private static void WriteList(StringBuilder text, IReadOnlyList<GodotValue> values)
    {
        for (int i = 0; i < values.Count; i++)
        {
            if (i > 0)
            {
                text.Append(", ");
            }

            values[i].Write(text);
        }
    }

    private static void WriteEntries(StringBuilder text, IReadOnlyList<KeyValuePair<GodotValue, GodotValue>> entries, bool comma)
    {
        foreach (KeyValuePair<GodotValue, GodotValue> entry in entries)
        {
            if (comma)
            {
                text.Append(", ");
            }

            entry.Key.Write(text);
            text.Append(": ");
            entry.Value.Write(text);
            comma = true;
        }
    }
}
