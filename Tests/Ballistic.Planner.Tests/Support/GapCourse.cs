using System.Numerics;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Tests.Support;

/// <summary>Four platforms along +X with gaps between them, the last one higher, and a thin wall to jump over.</summary>
internal static class GapCourse
{
    public static Level Build() => new LevelBuilder("gap-course")
        .AddBox(new Vector3(-8f, -1f, -2f), new Vector3(-3f, 0f, 2f))
        .AddBox(new Vector3(-1.5f, -1f, -2f), new Vector3(1.5f, 0f, 2f))
        .AddBox(new Vector3(3f, -1f, -2f), new Vector3(8f, 0f, 2f))
        .AddBox(new Vector3(5.4f, 0f, -2f), new Vector3(5.5f, 0.5f, 2f)) // a low wall across the third platform
        .AddBox(new Vector3(9.5f, -1f, -2f), new Vector3(13f, 1f, 2f))
        .Build();

    public static readonly Vector3 From = new(-6f, 0f, 0f);
    public static readonly Vector3 To = new(11.5f, 1f, 0f);
}
