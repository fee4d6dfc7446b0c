using System.Numerics;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Surfaces;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Surfaces;

public sealed class SurfaceSetTests
{
    [Test]
    public void ABoxOnAFloorGivesOneSurfacePerFaceAndOneFloor()
    {
        Level level = new LevelBuilder("t")
            .AddFloor(-5f, -5f, 5f, 5f, 0f, n: 6)
            .AddBox(new Vector3(-1f, 0f, -1f), new Vector3(1f, 1f, 1f))
            .Build();
        SurfaceSet set = SurfaceSet.Build(level);
        Assert.Multiple(() =>
        {
            // Floor, box top, four sides, box bottom (it faces down but is a surface all the same): 7 in all.
            Assert.That(set.Surfaces, Has.Count.EqualTo(7));
            ContactSurface floor = set.Surfaces.Single(s => s.Area > 50f);
            Assert.That(floor.Area, Is.EqualTo(100f).Within(1e-3f));
            Assert.That(Vector3.Distance(floor.Normal, Vector3.UnitY), Is.LessThan(1e-5f));
            Assert.That(set.Surfaces.Count(s => MathF.Abs(s.Normal.Y) < 1e-5f), Is.EqualTo(4));
            Assert.That(set.SurfaceOf(0), Is.EqualTo(floor.Id));
        });
    }

    [Test]
    public void DifferentMaterialsAndSharpFoldsSplitSurfaces()
    {
        var ice = new LevelMaterial("ice", 0.05f);
        Level level = new LevelBuilder("t")
            .AddFloor(0f, 0f, 2f, 2f, 0f)
            .AddFloor(2f, 0f, 4f, 2f, 0f, material: ice)
            .Build();
        SurfaceSet set = SurfaceSet.Build(level);
        Assert.That(set.Surfaces, Has.Count.EqualTo(2));
        Assert.That(set.Surfaces.Select(s => level.Materials[s.MaterialIndex].Name), Is.EquivalentTo(new[] { "ground", "ice" }));
    }

    [Test]
    public void TinySurfacesTakeNoContacts()
    {
        Level level = new LevelBuilder("t")
            .AddFloor(0f, 0f, 0.1f, 0.1f, 0f, n: 1)
            .AddFloor(5f, 5f, 7f, 7f, 0f, n: 1)
            .Build();
        SurfaceSet set = SurfaceSet.Build(level, new SurfaceSettings { MinArea = 0.05f });
        Assert.Multiple(() =>
        {
            Assert.That(set.Surfaces, Has.Count.EqualTo(1));
            Assert.That(set.SurfaceOf(0), Is.EqualTo(-1));
            Assert.That(set.SurfaceOf(2), Is.Zero);
        });
    }
}
