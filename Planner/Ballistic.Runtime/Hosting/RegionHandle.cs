namespace Ballistic.Runtime.Hosting;

/// <summary>
/// Names one region of a <see cref="JumpNavigationHost"/> (one <c>JumpRoadmap3D</c> node), like a navigation region's
/// RID. Valid from <see cref="JumpNavigationHost.CreateRegion"/> until <see cref="JumpNavigationHost.FreeRegion"/>;
/// a freed region's handle stays invalid even when its slot is reused. The default handle names no region.
/// </summary>
/// <param name="Index">Slot of the region in the host.</param>
/// <param name="Generation">How many regions used the slot before, plus one; zero for the default handle.</param>
public readonly record struct RegionHandle(int Index, int Generation)
{
    /// <summary>True for a handle that was ever returned by <see cref="JumpNavigationHost.CreateRegion"/> (not necessarily still valid).</summary>
    public bool IsAssigned => Generation > 0;

    /// <inheritdoc />
    public override string ToString() => IsAssigned ? $"region {Index}#{Generation}" : "no region";
}
