#nullable enable
using System.Reflection;
using Ballistic.Planner.Levels;

namespace Ballistic.Addon;

/// <summary>Facts about the planner library the addon runs on, shown in the editor and checked by tests.</summary>
public static class BallisticAddonInfo
{
    /// <summary>The informational version of the loaded <c>Ballistic.Planner</c> assembly.</summary>
    public static string PlannerVersion =>
        typeof(Level).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion
        ?? typeof(Level).Assembly.GetName().Version?.ToString()
        ?? "unknown";
}
