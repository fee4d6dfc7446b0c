namespace Ballistic.Planner.Geometry;

/// <summary>Solves remembered as <see cref="Lazy{T}"/> values in a <see cref="RememberedResults{TKey, TValue}"/>: each solved once across threads.</summary>
internal static class RememberedSolves
{
    /// <summary>
    /// The value for <paramref name="key"/>: remembered, being solved by another thread (waited for), or solved here
    /// by <paramref name="solve"/> and remembered (<paramref name="solvedHere"/>; <paramref name="solves"/> counted up
    /// first). A solve that throws is forgotten, so that the next call solves it again; the exception reaches every
    /// caller that waited for it.
    /// </summary>
    public static T GetOrSolve<TKey, T, TState>(this RememberedResults<TKey, Lazy<T>> memory, TKey key, TState state, Func<TState, T> solve, ref int solves, out bool solvedHere)
        where TKey : notnull
    {
        Lazy<T> entry = memory.GetOrAddLocked(
            key,
            (State: state, Solve: solve),
            static (_, s) => new Lazy<T>(() => s.Solve(s.State), LazyThreadSafetyMode.ExecutionAndPublication),
            out solvedHere);
        if (solvedHere)
        {
            Interlocked.Increment(ref solves);
        }

        try
        {
            return entry.Value;
        }
        catch (Exception)
        {
            memory.Forget(key, entry);
            throw;
        }
    }
}
