namespace Ballistic.Runtime;

/// <summary>
/// One of a world's own systems (path requests, locomotion, pose) as an <see cref="IJumpSystem"/> of its list: it
/// runs only when its own world steps it, so that neither another world nor a direct call can advance it out of turn.
/// </summary>
internal sealed class BuiltInSystem(JumpWorld owner, string name, Action<long, double> update) : IJumpSystem
{
    /// <summary>The world whose system it is.</summary>
    public JumpWorld Owner { get; } = owner;

    public void Update(in TickContext tick, JumpWorld world)
    {
        if (ReferenceEquals(world, Owner) && Owner.IsStepping)
        {
            update(tick.Tick, tick.Time);
        }
    }

    public override string ToString() => name;
}
