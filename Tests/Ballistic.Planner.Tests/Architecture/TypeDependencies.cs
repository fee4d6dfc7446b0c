using System.Reflection;
using System.Reflection.Emit;

namespace Ballistic.Planner.Tests.Architecture;

/// <summary>
/// The types a compiled type depends on, found by reflection: its base type and interfaces, fields, properties,
/// events, method and constructor signatures, generic arguments and constraints, and the locals and the types,
/// fields and methods named by the IL of its method bodies (so a call hidden inside a body counts too).
/// </summary>
internal static class TypeDependencies
{
    private const BindingFlags Declared = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;

    private static readonly Dictionary<short, OpCode> OpCodesByValue = typeof(OpCodes)
        .GetFields(BindingFlags.Public | BindingFlags.Static)
        .Select(f => (OpCode)f.GetValue(null)!)
        .ToDictionary(o => o.Value);

    /// <summary>Every type of <paramref name="assembly"/>, nested and compiler-generated ones included.</summary>
    public static IReadOnlyList<Type> AllTypes(Assembly assembly) => assembly.GetTypes();

    /// <summary>The named types <paramref name="type"/> depends on (array, by-ref and generic types unwrapped).</summary>
    public static IReadOnlySet<Type> Of(Type type)
    {
        var found = new HashSet<Type>();
        void Add(Type? t) => Unwrap(t, found);

        Add(type.BaseType);
        Add(type.DeclaringType);
        foreach (Type i in type.GetInterfaces())
        {
            Add(i);
        }

        foreach (Type g in type.IsGenericTypeDefinition ? type.GetGenericArguments() : [])
        {
            foreach (Type c in g.GetGenericParameterConstraints())
            {
                Add(c);
            }
        }

        foreach (FieldInfo f in type.GetFields(Declared))
        {
            Add(f.FieldType);
        }

        foreach (PropertyInfo p in type.GetProperties(Declared))
        {
            Add(p.PropertyType);
            foreach (ParameterInfo i in p.GetIndexParameters())
            {
                Add(i.ParameterType);
            }
        }

        foreach (EventInfo e in type.GetEvents(Declared))
        {
            Add(e.EventHandlerType);
        }

        foreach (MethodBase m in type.GetMethods(Declared).Cast<MethodBase>().Concat(type.GetConstructors(Declared)))
        {
            if (m is MethodInfo mi)
            {
                Add(mi.ReturnType);
                if (mi.IsGenericMethodDefinition)
                {
                    foreach (Type c in mi.GetGenericArguments().SelectMany(g => g.GetGenericParameterConstraints()))
                    {
                        Add(c);
                    }
                }
            }

            foreach (ParameterInfo p in m.GetParameters())
            {
                Add(p.ParameterType);
            }

            AddBody(m, found);
        }

        found.Remove(type);
        return found;
    }

    private static void AddBody(MethodBase method, HashSet<Type> found)
    {
        MethodBody? body = method.GetMethodBody();
        if (body is null)
        {
            return;
        }

        foreach (LocalVariableInfo local in body.LocalVariables)
        {
            Unwrap(local.LocalType, found);
        }

        byte[] il = body.GetILAsByteArray() ?? [];
        Type[] typeArgs = method.DeclaringType is { IsGenericType: true } d ? d.GetGenericArguments() : [];
        Type[] methodArgs = method is MethodInfo { IsGenericMethod: true } gm ? gm.GetGenericArguments() : [];
        int pos = 0;
        while (pos < il.Length)
        {
            short value = il[pos++];
            if (value == 0xFE)
            {
                value = (short)(0xFE00 | il[pos++]);
            }

            OpCode op = OpCodesByValue[value];
            switch (op.OperandType)
            {
                case OperandType.InlineField:
                case OperandType.InlineMethod:
                case OperandType.InlineTok:
                case OperandType.InlineType:
                    AddMember(method.Module.ResolveMember(BitConverter.ToInt32(il, pos), typeArgs, methodArgs), found);
                    pos += 4;
                    break;
                case OperandType.InlineSwitch:
                    pos += 4 + (4 * BitConverter.ToInt32(il, pos));
                    break;
                case OperandType.InlineI8:
                case OperandType.InlineR:
                    pos += 8;
                    break;
                case OperandType.InlineNone:
                    break;
                case OperandType.ShortInlineBrTarget:
                case OperandType.ShortInlineI:
                case OperandType.ShortInlineVar:
                    pos += 1;
                    break;
                case OperandType.InlineVar:
                    pos += 2;
                    break;
                default:
                    pos += 4;
                    break;
            }
        }
    }

    private static void AddMember(MemberInfo? member, HashSet<Type> found)
    {
        switch (member)
        {
            case Type t:
                Unwrap(t, found);
                break;
            case FieldInfo f:
                Unwrap(f.DeclaringType, found);
                Unwrap(f.FieldType, found);
                break;
            case MethodBase m:
                Unwrap(m.DeclaringType, found);
                if (m is MethodInfo mi)
                {
                    Unwrap(mi.ReturnType, found);
                    foreach (Type g in mi.IsGenericMethod ? mi.GetGenericArguments() : [])
                    {
                        Unwrap(g, found);
                    }
                }

                foreach (ParameterInfo p in m.GetParameters())
                {
                    Unwrap(p.ParameterType, found);
                }

                break;
            default:
                break;
        }
    }

    private static void Unwrap(Type? type, HashSet<Type> found)
    {
        if (type is null || type.IsGenericParameter)
        {
            return;
        }

        if (type.HasElementType)
        {
            Unwrap(type.GetElementType(), found);
            return;
        }

        if (type.IsGenericType && !type.IsGenericTypeDefinition)
        {
            Unwrap(type.GetGenericTypeDefinition(), found);
            foreach (Type a in type.GetGenericArguments())
            {
                Unwrap(a, found);
            }

            return;
        }

        found.Add(type);
    }
}
