namespace Ballistic.Runtime.Agents;

/// <summary>
/// One array shared by every agent's slice of one pose component (joint angles, joint rotations): slices are rented
/// at their end or, freed, reused by the next slice of the same length (agents of one kind share a length), so agents
/// added and removed allocate nothing once the pool has grown, and the pose system walks one array in slot order.
/// Growing moves the array: a span over it is valid until the next slice is rented.
/// </summary>
internal sealed class SlicePool<T>
{
    private readonly Dictionary<int, Stack<int>> _free = [];
    private int _top;

    /// <summary>Every slice, at its offset.</summary>
    public T[] Items { get; private set; } = new T[64];

    /// <summary>Elements rented or freed for reuse: the part of <see cref="Items"/> in use.</summary>
    public int Top => _top;

    /// <summary>Rents <paramref name="count"/> elements (cleared); returns their offset.</summary>
    public int Rent(int count)
    {
        if (count == 0)
        {
            return 0;
        }

        if (_free.TryGetValue(count, out Stack<int>? reused) && reused.TryPop(out int offset))
        {
            Array.Clear(Items, offset, count);
            return offset;
        }

        if (_top + count > Items.Length)
        {
            T[] grown = new T[Math.Max(Items.Length * 2, _top + count)];
            Array.Copy(Items, grown, _top);
            Items = grown;
        }

        offset = _top;
        _top += count;
        return offset;
    }

    /// <summary>Frees the <paramref name="count"/> elements at <paramref name="offset"/> for the next slice of that length.</summary>
    public void Return(int offset, int count)
    {
        if (count == 0)
        {
            return;
        }

        if (!_free.TryGetValue(count, out Stack<int>? stack))
        {
            _free[count] = stack = new Stack<int>();
        }

        stack.Push(offset);
    }

    /// <summary>The <paramref name="count"/> elements at <paramref name="offset"/>.</summary>
    public Span<T> Slice(int offset, int count) => Items.AsSpan(offset, count);
}
