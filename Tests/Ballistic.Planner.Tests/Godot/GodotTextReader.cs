using System.Globalization;
using System.Text;

namespace Ballistic.Planner.Tests.Godot;

/// <summary>
/// Reads the syntax shared by Godot's text scenes, text resources and ConfigFiles (the engine's <c>VariantParser</c>):
/// <c>[tag attr=value …]</c> headers, <c>key = value</c> lines whose values may span lines, <c>;</c> comments. Every
/// problem is a <see cref="GodotFormatException"/> naming the file and line.
/// </summary>
internal sealed class GodotTextReader
{
    private readonly string _text;
    private readonly string _file;
    private int _pos;
    private int _line = 1;

    private GodotTextReader(string text, string file)
    {
        _text = text;
        _file = file;
    }

    /// <summary>The sections of <paramref name="text"/>, in order.</summary>
    public static List<GodotSection> ReadSections(string text, string file) => new GodotTextReader(text, file).ReadAll();

    /// <summary>One value written alone, e.g. <c>Vector3(1, 2, 3)</c>; nothing but whitespace may follow it.</summary>
    public static GodotValue ReadValue(string text, string file)
    {
        var reader = new GodotTextReader(text, file);
        GodotValue value = reader.ParseValue(allowIdentifier: false);
        reader.SkipSpaceAndComments(acrossLines: true);
        if (!reader.AtEnd)
        {
            throw reader.Error($"unexpected '{reader.Peek()}' after the value");
        }

        return value;
    }

    private bool AtEnd => _pos >= _text.Length;

    private List<GodotSection> ReadAll()
    {
        var sections = new List<GodotSection>();
        string? tag = null;
        int headerLine = 1;
        List<KeyValuePair<string, GodotValue>> attributes = [];
        List<GodotProperty> properties = [];

        void Flush()
        {
            if (tag is not null || properties.Count > 0)
            {
                sections.Add(new GodotSection(tag ?? "", headerLine, attributes, properties));
            }
        }

        while (true)
        {
            SkipSpaceAndComments(acrossLines: true);
            if (AtEnd)
            {
                break;
            }

            if (Peek() == '[')
            {
                Flush();
                headerLine = _line;
                (tag, attributes) = ParseHeader();
                properties = [];
            }
            else
            {
                properties.Add(ParseAssignment());
            }
        }

        Flush();
        return sections;
    }

    private (string Tag, List<KeyValuePair<string, GodotValue>> Attributes) ParseHeader()
    {
        int line = _line;
        _pos++;
        SkipSpaceAndComments(acrossLines: false);
        int start = _pos;
        while (!AtEnd && !char.IsWhiteSpace(Peek()) && Peek() != ']')
        {
            _pos++;
        }

        string tag = _text[start.._pos];
        if (tag.Length == 0)
        {
            throw Error("empty section header '[]'");
        }

        var attributes = new List<KeyValuePair<string, GodotValue>>();
        while (true)
        {
            SkipSpaceAndComments(acrossLines: true);
            if (AtEnd)
            {
                throw Error($"section header [{tag} … is not closed with ']'", line);
            }

            if (Peek() == ']')
            {
                _pos++;
                break;
            }

            start = _pos;
            while (!AtEnd && IsIdentifierChar(Peek()))
            {
                _pos++;
            }

            string name = _text[start.._pos];
            if (name.Length == 0)
            {
                throw Error($"expected an attribute name or ']' in [{tag} …], found '{Peek()}'");
            }

            SkipSpaceAndComments(acrossLines: false);
            if (AtEnd || Peek() != '=')
            {
                throw Error($"expected '=' after attribute '{name}' in [{tag} …]");
            }

            _pos++;
            SkipSpaceAndComments(acrossLines: false);
            GodotValue value = ParseValue(allowIdentifier: false);
            if (attributes.Any(a => a.Key == name))
            {
                throw Error($"attribute '{name}' is given twice in [{tag} …]");
            }

            attributes.Add(new KeyValuePair<string, GodotValue>(name, value));
        }

        ExpectEndOfLine($"[{tag} …]");
        return (tag, attributes);
    }

    private GodotProperty ParseAssignment()
    {
        int line = _line;
        string key;
        if (Peek() == '"')
        {
            key = ParseString();
            SkipSpaceAndComments(acrossLines: false);
            if (AtEnd || Peek() != '=')
            {
                throw Error($"expected '=' after property name \"{key}\"");
            }
        }
        else
        {
            int start = _pos;
            while (!AtEnd && Peek() != '=' && Peek() != '\n')
            {
                _pos++;
            }

            if (AtEnd || Peek() != '=')
            {
                throw Error($"expected 'key = value', found '{Shorten(_text[start.._pos].Trim())}'", line);
            }

            key = _text[start.._pos].Trim();
            if (key.Length == 0)
            {
                throw Error("missing property name before '='");
            }

            if (key.Any(char.IsWhiteSpace))
            {
                throw Error($"property name '{key}' contains whitespace");
            }
        }

        _pos++;
        SkipSpaceAndComments(acrossLines: false);
        if (AtEnd || Peek() is '\n' or '\r')
        {
            throw Error($"missing value after '{key} ='");
        }

        GodotValue value = ParseValue(allowIdentifier: false);
        ExpectEndOfLine($"the value of '{key}'");
        return new GodotProperty(key, value, line);
    }

    private GodotValue ParseValue(bool allowIdentifier)
    {
        SkipSpaceAndComments(acrossLines: true);
        if (AtEnd)
        {
            throw Error("expected a value, found the end of the file");
        }

        int line = _line;
        char c = Peek();
        switch (c)
        {
            case '"':
                return GodotValue.FromText(GodotValueKind.String, ParseString(), line);
            case '&' when PeekAt(1) == '"':
                _pos++;
                return GodotValue.FromText(GodotValueKind.StringName, ParseString(), line);
            case '^' when PeekAt(1) == '"':
                _pos++;
                return GodotValue.FromText(GodotValueKind.NodePath, ParseString(), line);
            case '[':
                _pos++;
                return GodotValue.Array(ParseList(']', "array", allowIdentifier: false), line);
            case '{':
                _pos++;
                return GodotValue.Dictionary(ParseDictionary(), line);
        }

        if (char.IsAsciiDigit(c) || c is '-' or '+' or '.')
        {
            return ParseNumber(line);
        }

        if (IsIdentifierStart(c))
        {
            return ParseWord(line, allowIdentifier);
        }

        throw Error($"unexpected character '{c}' where a value should start");
    }

    private GodotValue ParseWord(int line, bool allowIdentifier)
    {
        int start = _pos;
        while (!AtEnd && IsIdentifierChar(Peek()))
        {
            _pos++;
        }

        string word = _text[start.._pos];
        if (!AtEnd && Peek() == '[')
        {
            // A typed container: Array[int]([1, 2]) or Dictionary[String, int]({...}).
            _pos++;
            List<GodotValue> typeArguments = ParseList(']', $"type arguments of {word}", allowIdentifier: true);
            SkipSpaceAndComments(acrossLines: false);
            if (AtEnd || Peek() != '(')
            {
                throw Error($"expected '(' after {word}[…]");
            }

            _pos++;
            (List<GodotValue> items, List<KeyValuePair<GodotValue, GodotValue>> entries) = ParseArguments(word);
            return GodotValue.Call(word, typeArguments, items, entries, line);
        }

        int afterWord = _pos;
        SkipSpaceAndComments(acrossLines: false);
        if (!AtEnd && Peek() == '(')
        {
            _pos++;
            (List<GodotValue> items, List<KeyValuePair<GodotValue, GodotValue>> entries) = ParseArguments(word);
            if (word is "ExtResource" or "SubResource"
                && (items.Count != 1 || entries.Count != 0 || items[0].Kind is not (GodotValueKind.String or GodotValueKind.Int)))
            {
                throw Error($"{word}(…) takes one id, a string, found {word}({string.Join(", ", items)})", line);
            }

            return GodotValue.Call(word, [], items, entries, line);
        }

        _pos = afterWord;
        switch (word)
        {
            case "true":
                return GodotValue.FromBool(true, line);
            case "false":
                return GodotValue.FromBool(false, line);
            case "null" or "nil":
                return GodotValue.Null(line);
            case "inf":
                return GodotValue.FromFloat(double.PositiveInfinity, line);
            case "inf_neg":
                return GodotValue.FromFloat(double.NegativeInfinity, line);
            case "nan":
                return GodotValue.FromFloat(double.NaN, line);
        }

        if (allowIdentifier)
        {
            return GodotValue.FromText(GodotValueKind.Identifier, word, line);
        }

        throw Error($"unexpected identifier '{word}' (a value is a string, number, true/false/null, [array], {{dictionary}} or Name(…))", line);
    }

    private (List<GodotValue> Items, List<KeyValuePair<GodotValue, GodotValue>> Entries) ParseArguments(string callee)
    {
        int line = _line;
        var items = new List<GodotValue>();
        var entries = new List<KeyValuePair<GodotValue, GodotValue>>();
        SkipSpaceAndComments(acrossLines: true);
        if (!AtEnd && Peek() == ')')
        {
            _pos++;
            return (items, entries);
        }

        while (true)
        {
            // Object(ClassName, "property": value, …) names its class with a bare identifier.
            GodotValue value = ParseValue(allowIdentifier: callee == "Object" && items.Count == 0 && entries.Count == 0);
            SkipSpaceAndComments(acrossLines: true);
            if (!AtEnd && Peek() == ':')
            {
                _pos++;
                entries.Add(new KeyValuePair<GodotValue, GodotValue>(value, ParseValue(allowIdentifier: false)));
                SkipSpaceAndComments(acrossLines: true);
            }
            else
            {
                items.Add(value);
            }

            if (AtEnd)
            {
                throw Error($"{callee}( opened on line {line} is not closed with ')'", line);
            }

            char c = Peek();
            _pos++;
            if (c == ')')
            {
                return (items, entries);
            }

            if (c != ',')
            {
                throw Error($"expected ',' or ')' in the arguments of {callee}(…), found '{c}'");
            }
        }
    }

    private List<GodotValue> ParseList(char close, string what, bool allowIdentifier)
    {
        int line = _line;
        var items = new List<GodotValue>();
        SkipSpaceAndComments(acrossLines: true);
        if (!AtEnd && Peek() == close)
        {
            _pos++;
            return items;
        }

        while (true)
        {
            items.Add(ParseValue(allowIdentifier));
            SkipSpaceAndComments(acrossLines: true);
            if (AtEnd)
            {
                throw Error($"{what} opened on line {line} is not closed with '{close}'", line);
            }

            char c = Peek();
            _pos++;
            if (c == close)
            {
                return items;
            }

            if (c != ',')
            {
                throw Error($"expected ',' or '{close}' in {what}, found '{c}'");
            }
        }
    }

    private List<KeyValuePair<GodotValue, GodotValue>> ParseDictionary()
    {
        int line = _line;
        var entries = new List<KeyValuePair<GodotValue, GodotValue>>();
        SkipSpaceAndComments(acrossLines: true);
        if (!AtEnd && Peek() == '}')
        {
            _pos++;
            return entries;
        }

        while (true)
        {
            GodotValue key = ParseValue(allowIdentifier: false);
            SkipSpaceAndComments(acrossLines: true);
            if (AtEnd || Peek() != ':')
            {
                throw Error($"expected ':' after dictionary key {key}");
            }

            _pos++;
            entries.Add(new KeyValuePair<GodotValue, GodotValue>(key, ParseValue(allowIdentifier: false)));
            SkipSpaceAndComments(acrossLines: true);
            if (AtEnd)
            {
                throw Error($"dictionary opened on line {line} is not closed with '}}'", line);
            }

            char c = Peek();
            _pos++;
            if (c == '}')
            {
                return entries;
            }

            if (c != ',')
            {
                throw Error($"expected ',' or '}}' in a dictionary, found '{c}'");
            }
        }
    }

    private GodotValue ParseNumber(int line)
    {
        int start = _pos;
        if (Peek() is '-' or '+')
        {
            _pos++;
        }

        if (string.CompareOrdinal(_text, _pos, "inf", 0, 3) == 0 && (_pos + 3 >= _text.Length || !IsIdentifierChar(_text[_pos + 3])))
        {
            _pos += 3;
            return GodotValue.FromFloat(_text[start] == '-' ? double.NegativeInfinity : double.PositiveInfinity, line);
        }

        bool isFloat = false;
        int digits = 0;
        while (!AtEnd && char.IsAsciiDigit(Peek()))
        {
            _pos++;
            digits++;
        }

        if (!AtEnd && Peek() == '.')
        {
            isFloat = true;
            _pos++;
            while (!AtEnd && char.IsAsciiDigit(Peek()))
            {
                _pos++;
                digits++;
            }
        }

        if (digits > 0 && !AtEnd && Peek() is 'e' or 'E')
        {
            isFloat = true;
            _pos++;
            if (!AtEnd && Peek() is '-' or '+')
            {
                _pos++;
            }

            int exponentDigits = 0;
            while (!AtEnd && char.IsAsciiDigit(Peek()))
            {
                _pos++;
                exponentDigits++;
            }

            if (exponentDigits == 0)
            {
                throw Error($"malformed number '{_text[start.._pos]}'");
            }
        }

        string number = _text[start.._pos];
        if (digits == 0 || (!AtEnd && IsIdentifierChar(Peek())))
        {
            while (!AtEnd && IsIdentifierChar(Peek()))
            {
                _pos++;
            }

            throw Error($"malformed number '{_text[start.._pos]}'");
        }

        if (!isFloat && long.TryParse(number, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long integer))
        {
            return GodotValue.FromInt(integer, line);
        }

        return GodotValue.FromFloat(double.Parse(number, NumberStyles.Float, CultureInfo.InvariantCulture), line);
    }

    private string ParseString()
    {
        int line = _line;
        _pos++;
        var text = new StringBuilder();
        while (true)
        {
            if (AtEnd)
            {
                throw Error($"string starting on line {line} is not closed with '\"'", line);
            }

            char c = _text[_pos++];
            if (c == '"')
            {
                return text.ToString();
            }

            if (c == '\n')
            {
                _line++;
                text.Append(c);
                continue;
            }

            if (c != '\\')
            {
                text.Append(c);
                continue;
            }

            if (AtEnd)
            {
                throw Error($"string starting on line {line} is not closed with '\"'", line);
            }

            char escape = _text[_pos++];
            switch (escape)
            {
                case 'b': text.Append('\b'); break;
                case 't': text.Append('\t'); break;
                case 'n': text.Append('\n'); break;
                case 'f': text.Append('\f'); break;
                case 'r': text.Append('\r'); break;
                case '"': text.Append('"'); break;
                case '\'': text.Append('\''); break;
                case '\\': text.Append('\\'); break;
                case 'u':
                    text.Append(ParseCodePoint(4));
                    break;
                case 'U':
                    text.Append(ParseCodePoint(6));
                    break;
                default:
                    throw Error($"invalid escape '\\{escape}' in a string");
            }
        }
    }

    private string ParseCodePoint(int digits)
    {
        if (_pos + digits > _text.Length
            || !int.TryParse(_text.AsSpan(_pos, digits), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int code)
            || code > 0x10FFFF)
        {
            throw Error($"invalid unicode escape: expected {digits} hexadecimal digits");
        }

        _pos += digits;
        return code is >= 0xD800 and <= 0xDFFF ? ((char)code).ToString() : char.ConvertFromUtf32(code);
    }

    private void ExpectEndOfLine(string after)
    {
        SkipSpaceAndComments(acrossLines: false);
        if (!AtEnd && Peek() is not ('\n' or '\r'))
        {
            int start = _pos;
            int end = _text.IndexOf('\n', start);
            throw Error($"unexpected '{Shorten(_text[start..(end < 0 ? _text.Length : end)].Trim())}' after {after}");
        }
    }

    private void SkipSpaceAndComments(bool acrossLines)
    {
        while (!AtEnd)
        {
            char c = Peek();
            if (c == '\n')
            {
                if (!acrossLines)
                {
                    return;
                }

                _line++;
                _pos++;
            }
            else if (c is ' ' or '\t' or '\r' or '\uFEFF')
            {
                _pos++;
            }
            else if (c == ';')
            {
                while (!AtEnd && Peek() != '\n')
                {
                    _pos++;
                }
            }
            else
            {
                return;
            }
        }
    }

    private char Peek() => _text[_pos];

    private char PeekAt(int offset) => _pos + offset < _text.Length ? _text[_pos + offset] : '\0';

    private static bool IsIdentifierStart(char c) => char.IsAsciiLetter(c) || c == '_';

    private static bool IsIdentifierChar(char c) => char.IsAsciiLetterOrDigit(c) || c == '_';

    private static string Shorten(string text) => text.Length <= 40 ? text : text[..37] + "...";

    private GodotFormatException Error(string problem, int? line = null) => new(_file, line ?? _line, problem);
}
