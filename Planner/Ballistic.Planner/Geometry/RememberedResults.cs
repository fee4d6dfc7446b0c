using System.Diagnostics.CodeAnalysis;

namespace Ballistic.Planner.Geometry;

/// <summary>
/// Results of a pure function remembered across calls and threads, bounded: two generations of at most
/// <c>capacity</c> each, the newer becoming the older when full and the older forgotten, a result found in the older
/// kept in the newer. For work that queries repeat (placing the same stances, steering the same pairs): since a result
/// depends on its key alone, what is remembered never changes one, only how soon it comes, whatever the order or
/// the threads that asked.
/// <para>
/// A thread inside a <see cref="KeptResults.Keep"/> scope (a query being prepared ahead of time) keeps what it makes
/// or recalls for good, outside the two generations: results that every later query over the roadmap would otherwise
/// make again once the generations forgot them.
/// </para>
/// </summary>
internal sealed class RememberedResults<TKey, TValue>(int capacity)
    where TKey : notnull
{
    private readonly object _lock = new();
    private readonly Dictionary<TKey, TValue> _kept = [];
    private Dictionary<TKey, TValue> _newer = [];
    private Dictionary<TKey, TValue> _older = [];

    /// <summary>How many results are kept for good (made or recalled inside a <see cref="KeptResults.Keep"/> scope).</summary>
    public int KeptCount
    {
        get
        {
            lock (_lock)
            {
                return _kept.Count;
            }
        }
    }

    /// <summary>Gives back the kept results' spare room (their table grew by doubling while a preparation kept them).</summary>
    public void TrimKept()
    {
        lock (_lock)
        {
            _kept.TrimExcess();
        }
    }

    /// <summary>The result for <paramref name="key"/>: remembered, or made by <paramref name="make"/> (outside the lock) and remembered.</summary>
    public TValue GetOrAdd<TState>(TKey key, TState state, Func<TKey, TState, TValue> make)
    {
        lock (_lock)
        {
            if (Recall(key, out TValue? known))
            {
                return known;
            }
        }

        TValue made = make(key, state);
        lock (_lock)
        {
            Remember(key, made);
        }

        return made;
    }

    /// <summary>
    /// The value for <paramref name="key"/>: remembered, or made by <paramref name="make"/> under the lock and
    /// remembered (<paramref name="added"/>). For a cheap maker only, such as a <see cref="Lazy{T}"/> the callers then
    /// solve: a second caller asking while the first solves finds the same one and waits for it, instead of solving it
    /// again.
    /// </summary>
    public TValue GetOrAddLocked<TState>(TKey key, TState state, Func<TKey, TState, TValue> make, out bool added)
    {
        lock (_lock)
        {
            if (Recall(key, out TValue? known))
            {
                added = false;
                return known;
            }

            TValue made = make(key, state);
            Remember(key, made);
            added = true;
            return made;
        }
    }

    /// <summary>Forgets <paramref name="key"/> while it is still remembered as <paramref name="value"/> (a solve that failed), so the next call makes it again.</summary>
    public void Forget(TKey key, TValue value)
    {
        lock (_lock)
        {
            foreach (Dictionary<TKey, TValue> generation in (Dictionary<TKey, TValue>[])[_kept, _newer, _older])
            {
                if (generation.TryGetValue(key, out TValue? known) && EqualityComparer<TValue>.Default.Equals(known, value))
                {
                    generation.Remove(key);
                }
            }
        }
    }

    /// <summary>True when <paramref name="key"/> is remembered (made, or being made: a <see cref="Lazy{T}"/> added under the lock and not yet solved).</summary>
    public bool Contains(TKey key)
    {
        lock (_lock)
        {
            return _kept.ContainsKey(key) || _newer.ContainsKey(key) || _older.ContainsKey(key);
        }
    }

    /// <summary>
    /// The value remembered for <paramref name="key"/>: kept for good, or found in a generation and kept in the newer
    /// (for good instead, inside a <see cref="KeptResults.Keep"/> scope on this thread); under the lock.
    /// </summary>
    private bool Recall(TKey key, [MaybeNullWhen(false)] out TValue value)
    {
        if (_kept.TryGetValue(key, out value))
        {
            return true;
        }

        if (_newer.TryGetValue(key, out value))
        {
            if (KeptResults.Keeping)
            {
                _newer.Remove(key);
                _older.Remove(key);
                _kept[key] = value;
            }

            return true;
        }

        if (_older.TryGetValue(key, out value))
        {
            if (KeptResults.Keeping)
            {
                _older.Remove(key);
                _kept[key] = value;
            }
            else
            {
                _newer[key] = value;
            }

            return true;
        }

        return false;
    }

    /// <summary>
    /// Keeps <paramref name="value"/> for good inside a <see cref="KeptResults.Keep"/> scope on this thread, else in the
    /// newer generation, which becomes the older when full; under the lock.
    /// </summary>
    private void Remember(TKey key, TValue value)
    {
        if (KeptResults.Keeping)
        {
            _kept[key] = value;
            return;
        }

        if (_newer.Count >= capacity)
        {
            (_older, _newer) = (_newer, []);
        }

        _newer[key] = value;
    }
}
