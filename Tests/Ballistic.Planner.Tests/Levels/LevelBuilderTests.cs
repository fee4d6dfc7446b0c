using System.Numerics;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;

namespace Ballistic.Planner.Tests.Levels;

public sealed class LevelBuilderTests
{
    private static readonly LevelMaterial Stone = new("stone", null);

    [Test]
    public void TransformsMeshesIntoWorldSpace()
    {
        Level level = RaisedFloor();
        Assert.Multiple(() =>
        {
            Assert.That(level.Triangles, Has.Count.EqualTo(2));
            Assert.That(level.Bounds.Min.Y, Is.EqualTo(2f));
            Assert.That(Vector3.Distance(level.Triangles[0].Normal, Vector3.UnitY), Is.LessThan(1e-6f));
        });
    }

    /// <summary>
    /// The level's public raycast (what the Godot roadmap node's IntersectLevel uses): a segment down onto a raised
    /// floor hits it where it crosses, with the floor's normal; one ending above it, or passing beside it, misses.
    /// </summary>
    [Test]
    public void ASegmentMeetsTheLevelWhereItCrossesIt()
    {
        Level level = RaisedFloor();
        var from = new Vector3(0.25f, 5f, 0.75f);
        bool met = level.Raycast(from, new Vector3(0f, -5f, 0f), 1f, out RayHit hit);
        Assert.Multiple(() =>
        {
            Assert.That(met, Is.True);
            Assert.That(Vector3.Distance(hit.Point, new Vector3(0.25f, 2f, 0.75f)), Is.LessThan(1e-5f));
            Assert.That(hit.Distance, Is.EqualTo(0.6f).Within(1e-5f), "3 m down a 5 m segment");
            Assert.That(Vector3.Distance(hit.Normal, Vector3.UnitY), Is.LessThan(1e-6f));
            Assert.That(level.Raycast(from, new Vector3(0f, -2.9f, 0f), 1f, out _), Is.False, "the segment ends 0.1 m above the floor");
            Assert.That(level.Raycast(new Vector3(1.5f, 5f, 0.5f), new Vector3(0f, -5f, 0f), 1f, out _), Is.False, "beside the floor");
        });
    }

    /// <summary>A 1 × 1 m floor mesh, built at the origin and moved 2 m up by its transform.</summary>
    private static Level RaisedFloor()
    {
        Vector3[] quad = [new(0f, 0f, 0f), new(1f, 0f, 0f), new(1f, 0f, 1f), new(0f, 0f, 1f)];
        return new LevelBuilder("test")
            .AddMesh("floor", quad, [0, 2, 1, 0, 3, 2], Matrix4x4.CreateTranslation(0f, 2f, 0f), Stone)
            .Build();
    }

    [Test]
    public void NonFiniteVertexIsAnErrorNamingTheMesh()
    {
        Vector3[] bad = [Vector3.Zero, new(float.NaN, 0f, 0f), Vector3.UnitZ];
        Assert.That(() => new LevelBuilder("dunes.glb").AddMesh("Dune_04", bad, [0, 1, 2], Matrix4x4.Identity, Stone),
            Throws.TypeOf<LevelException>().With.Message.Contains("Dune_04").And.Message.Contains("dunes.glb").And.Message.Contains("vertex 1"));
    }

    [Test]
    public void DegenerateTrianglesAreDroppedAndCounted()
    {
        Vector3[] points = [Vector3.Zero, Vector3.UnitX, Vector3.UnitZ, new(2f, 0f, 0f)];
        Level level = new LevelBuilder("test")
            .AddMesh("m", points, [0, 2, 1, 0, 1, 3, 1, 1, 2], Matrix4x4.Identity, Stone)
            .Build();
        Assert.Multiple(() =>
        {
            Assert.That(level.Triangles, Has.Count.EqualTo(1));
            Assert.That(level.DroppedDegenerateTriangles, Is.EqualTo(2));
        });
    }

    [Test]
    public void EmptyLevelIsAnError()
    {
        Assert.Multiple(() =>
        {
            Assert.That(() => new LevelBuilder("nothing.glb").Build(), Throws.TypeOf<LevelException>().With.Message.Contains("empty"));
            Assert.That(() => new LevelBuilder("flat.glb").AddTriangle(new Triangle(Vector3.Zero, Vector3.UnitX, 2f * Vector3.UnitX), Stone).Build(),
                Throws.TypeOf<LevelException>().With.Message.Contains("zero area"));
        });
    }

    [Test]
    public void IndexOutOfRangeIsAnError()
    {
        Assert.That(() => new LevelBuilder("x").AddMesh("m", [Vector3.Zero, Vector3.UnitX, Vector3.UnitZ], [0, 1, 7], Matrix4x4.Identity, Stone),
            Throws.TypeOf<LevelException>().With.Message.Contains("out of range"));
    }

    [Test]
    public void FrictionOverridesAndFingerprint()
    {
        var tri = new Triangle(Vector3.Zero, Vector3.UnitZ, Vector3.UnitX);
        Level plain = new LevelBuilder("a").AddTriangle(tri, Stone).Build();
        Level icy = new LevelBuilder("b").AddTriangle(tri, new LevelMaterial("ice", 0.05f)).Build();
        Level same = new LevelBuilder("c").AddTriangle(tri, new LevelMaterial("other name", null)).Build();
        Assert.Multiple(() =>
        {
            Assert.That(plain.FrictionOf(0, 0.5f), Is.EqualTo(0.5f));
            Assert.That(icy.FrictionOf(0, 0.5f), Is.EqualTo(0.05f));
            Assert.That(plain.Fingerprint, Is.Not.EqualTo(icy.Fingerprint));
            Assert.That(plain.Fingerprint, Is.EqualTo(same.Fingerprint));
            Assert.That(plain.Fingerprint, Has.Length.EqualTo(64));
        });
    }
}
