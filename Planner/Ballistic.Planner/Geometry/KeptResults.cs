namespace Ballistic.Planner.Geometry;

/// <summary>
/// Whether the current thread keeps what it remembers for good: inside a <see cref="Keep"/> scope, every
/// <see cref="RememberedResults{TKey, TValue}"/> keeps the results this thread makes or recalls outside its bounded
/// generations, so that they are never forgotten (a query prepared ahead of time, <see cref="Query.PathQuery.Prepare"/>).
/// Other threads remember as before. What is kept changes no result, only how soon it comes.
/// </summary>
internal static class KeptResults
{
    [ThreadStatic]
    private static int t_depth;

    /// <summary>True inside a <see cref="Keep"/> scope on this thread.</summary>
    public static bool Keeping => t_depth > 0;

    /// <summary>Starts a keeping scope on this thread, ended by disposing the result (scopes nest).</summary>
    public static Scope Keep()
    {
        t_depth++;
        return new Scope();
    }

    /// <summary>A keeping scope on the thread that started it; disposing it ends it there.</summary>
    public readonly struct Scope : IDisposable
    {
        /// <summary>Ends the scope.</summary>
        public void Dispose() => t_depth--;
    }
}
