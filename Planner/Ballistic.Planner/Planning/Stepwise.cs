namespace Ballistic.Planner.Planning;

/// <summary>
/// Work written in steps (an iterator giving <c>null</c> at each pause point, then its outcome), run whole: the one
/// body behind a call that runs to its end and a job spread over several frames (the planner's plan job).
/// </summary>
internal static class Stepwise
{
    /// <summary>Runs <paramref name="steps"/> to their end: the first outcome they give.</summary>
    /// <exception cref="InvalidOperationException">The steps ended without an outcome.</exception>
    public static T Last<T>(IEnumerable<T?> steps)
        where T : class
    {
        foreach (T? step in steps)
        {
            if (step is not null)
            {
                return step;
            }
        }

        throw new InvalidOperationException("Work in steps ended without an outcome.");
    }

    /// <summary>
    /// <paramref name="steps"/> as pauses inside other work in steps: <c>true</c> at each of their pauses; their outcome
    /// handed to <paramref name="outcome"/> when they give it, then they end.
    /// </summary>
    /// <exception cref="InvalidOperationException">The steps ended without an outcome.</exception>
    public static IEnumerable<bool> Pauses<T>(IEnumerable<T?> steps, Action<T> outcome)
        where T : class
    {
        foreach (T? step in steps)
        {
            if (step is not null)
            {
                outcome(step);
                yield break;
            }

            yield return true;
        }

        throw new InvalidOperationException("Work in steps ended without an outcome.");
    }
}
