namespace Ballistic.Runtime;

/// <summary>What the world needs of a game's component column, whatever its value type: presence by slot, and forgetting a removed agent's value.</summary>
internal interface IComponentColumn
{
    /// <summary>The world the column belongs to.</summary>
    JumpWorld World { get; }

    /// <summary>True when the agent in <paramref name="slot"/> has a value in the column.</summary>
    bool HasSlot(int slot);

    /// <summary>Forgets the value of the agent in <paramref name="slot"/> (removed).</summary>
    void Clear(int slot);
}
