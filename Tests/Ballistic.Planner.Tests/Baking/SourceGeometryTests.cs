using System.Numerics;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Runtime.Baking;

namespace Ballistic.Planner.Tests.Baking;

public sealed class SourceGeometryTests
{
    /// <summary>
    /// What Godot's <c>PlaneMesh.GetFaces()</c> returns for the default 2 × 2 m plane facing +Y: its
    /// <c>_create_mesh_array</c> puts vertex (−x, 0, −z) for x, z from −1 to 1 and indexes each quad as
    /// (prev i−1, prev i, this i−1), (prev i, this i, this i−1), which is clockwise seen from above.
    /// </summary>
    private static readonly Vector3[] GodotPlaneFaces =
    [
        new(1f, 0f, 1f), new(-1f, 0f, 1f), new(1f, 0f, -1f),
        new(-1f, 0f, 1f), new(-1f, 0f, -1f), new(1f, 0f, -1f),
    ];

    [Test]
    public void AGodotFloorGivenClockwiseFacesUpAndTheWrongWindingIsCaught()
    {
        Level godot = new SourceGeometry("plane").AddFaces("Plane", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise).Build();
        Level wrong = new SourceGeometry("plane").AddFaces("Plane", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.CounterClockwise).Build();
        Assert.Multiple(() =>
        {
            Assert.That(godot.Triangles, Has.Count.EqualTo(2));
            Assert.That(godot.Triangles.Select(t => t.Normal.Y), Is.All.EqualTo(1f).Within(1e-6f), "Godot's clockwise front faces become the planner's up-facing floor");
            Assert.That(wrong.Triangles.Select(t => t.Normal.Y), Is.All.EqualTo(-1f).Within(1e-6f), "taken as counter-clockwise, the same faces point down");
        });
    }

    [Test]
    public void AMirroringTransformKeepsFrontFacesInFront()
    {
        // Mirror in X and stretch: the floor still faces up, and so does a box's top.
        Matrix4x4 mirror = SourceGeometry.FromBasis(new Vector3(-2f, 0f, 0f), Vector3.UnitY, new Vector3(0f, 0f, 3f), new Vector3(1f, 2f, 3f));
        Level level = new SourceGeometry("mirrored")
            .AddFaces("Plane", GodotPlaneFaces, mirror, FaceWinding.Clockwise)
            .AddBox("Box", new Vector3(1f, 1f, 1f), mirror)
            .Build();
        Assert.That(level.Triangles.Take(2).Select(t => t.Normal.Y), Is.All.EqualTo(1f).Within(1e-6f));

        // Every box face points away from the box's centre.
        Vector3 centre = new(1f, 2f, 3f);
        foreach (Triangle t in level.Triangles.Skip(2))
        {
            Assert.That(Vector3.Dot(t.Normal, t.Centroid - centre), Is.GreaterThan(0f), $"box face at {t.Centroid} faces out");
        }
    }

    [Test]
    public void TransformsFollowGodotsBasisColumnsAndOrigin()
    {
        // Godot: transform * p = p.x·X + p.y·Y + p.z·Z + origin.
        Matrix4x4 m = SourceGeometry.FromBasis(new Vector3(0f, 0f, -1f), new Vector3(0f, 2f, 0f), new Vector3(1f, 0f, 0f), new Vector3(5f, 6f, 7f));
        Assert.That(Vector3.Transform(new Vector3(1f, 2f, 3f), m), Is.EqualTo(new Vector3(8f, 10f, 6f)));

        Level level = new SourceGeometry("moved").AddFaces("Tri", [new(0f, 0f, 0f), new(1f, 0f, 0f), new(0f, 0f, 1f)], m, FaceWinding.Clockwise).Build();
        Triangle t = level.Triangles[0];
        Assert.Multiple(() =>
        {
            Assert.That(t.A, Is.EqualTo(new Vector3(5f, 6f, 7f)));
            Assert.That(new[] { t.B, t.C }, Is.EquivalentTo(new[] { new Vector3(5f, 6f, 6f), new Vector3(6f, 6f, 7f) }));
            Assert.That(t.Normal.Y, Is.EqualTo(1f).Within(1e-6f), "clockwise seen from above in the local frame, rotated about Y: still up");
        });
    }

    [Test]
    public void GodotStyleSourcesBuildTheSameLevelAsThePlanner()
    {
        Level sources = BakingLevels.FromSources().Build();
        Level planner = BakingLevels.Planner();
        Assert.Multiple(() =>
        {
            Assert.That(sources.Triangles, Is.EqualTo(planner.Triangles), "same triangles, same corner order");
            Assert.That(sources.Fingerprint, Is.EqualTo(planner.Fingerprint));
            Assert.That(BakingLevels.FromSources().Fingerprint, Is.EqualTo(planner.Fingerprint), "the fingerprint is deterministic");
            Assert.That(sources.Source, Is.EqualTo("Level/JumpRoadmap3D"));
        });
    }

    [Test]
    public void MovingABoxChangesTheFingerprint()
    {
        string before = BakingLevels.FromSources().Fingerprint;
        string moved = BakingLevels.FromSources(BakingLevels.BlockCentre + new Vector3(0.01f, 0f, 0f)).Fingerprint;
        Assert.That(moved, Is.Not.EqualTo(before));
    }

    [Test]
    public void BuildGivesTheSameLevelUntilASourceIsAdded()
    {
        SourceGeometry geometry = new SourceGeometry("level").AddFaces("Plane", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise);
        Level first = geometry.Build();
        Assert.That(geometry.Build(), Is.SameAs(first));
        geometry.AddBox("Box", Vector3.One, Matrix4x4.CreateTranslation(0f, 3f, 0f));
        Level second = geometry.Build();
        Assert.Multiple(() =>
        {
            Assert.That(second, Is.Not.SameAs(first));
            Assert.That(second.Triangles, Has.Count.EqualTo(14));
            Assert.That(geometry.SourceCount, Is.EqualTo(2));
        });
    }

    [Test]
    public void FrictionIsPerSourceAndSharedByEqualValues()
    {
        Level level = new SourceGeometry("ice")
            .AddFaces("Ice", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise, friction: 0.05f)
            .AddBox("Rock", Vector3.One, Matrix4x4.CreateTranslation(3f, 0.5f, 0f))
            .AddBox("Ice2", Vector3.One, Matrix4x4.CreateTranslation(-3f, 0.5f, 0f), friction: 0.05f)
            .Build();
        Assert.Multiple(() =>
        {
            Assert.That(level.FrictionOf(0, 0.5f), Is.EqualTo(0.05f));
            Assert.That(level.FrictionOf(2, 0.5f), Is.EqualTo(0.5f), "no friction given: the character's default");
            Assert.That(level.FrictionOf(14, 0.5f), Is.EqualTo(0.05f));
            Assert.That(level.Materials, Has.Count.EqualTo(2), "one material per friction value, so surfaces split only where friction does");
        });

        string plain = new SourceGeometry("ice").AddFaces("Ice", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise).Fingerprint;
        string icy = new SourceGeometry("ice").AddFaces("Ice", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise, friction: 0.05f).Fingerprint;
        Assert.That(icy, Is.Not.EqualTo(plain), "friction is part of the level fingerprint");
    }

    /// <summary>
    /// Costs per source, as the Godot node reads them from a node's <c>jump_travel_cost</c> and <c>jump_enter_cost</c>
    /// metadata: each source's faces get a material with those costs; sources with equal costs and friction share one;
    /// costs leave the fingerprint (and so a baked roadmap) as it was; out of range, refused naming the source.
    /// </summary>
    [Test]
    public void SurfaceCostsArePerSourceAndLeaveTheFingerprint()
    {
        Level level = new SourceGeometry("swamp")
            .AddFaces("Mud", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise, travelCost: 4f)
            .AddBox("Rock", Vector3.One, Matrix4x4.CreateTranslation(3f, 0.5f, 0f))
            .AddBox("Pool", Vector3.One, Matrix4x4.CreateTranslation(-3f, 0.5f, 0f), friction: 0.1f, enterCost: 6f)
            .Build();
        LevelMaterial mud = level.Materials[level.MaterialIndices[0]];
        LevelMaterial rock = level.Materials[level.MaterialIndices[2]];
        LevelMaterial pool = level.Materials[level.MaterialIndices[14]];
        Assert.Multiple(() =>
        {
            Assert.That((mud.TravelCost, mud.EnterCost, mud.Friction), Is.EqualTo((4f, 0f, (float?)null)));
            Assert.That((rock.TravelCost, rock.EnterCost), Is.EqualTo((1f, 0f)));
            Assert.That((pool.TravelCost, pool.EnterCost, pool.Friction), Is.EqualTo((1f, 6f, (float?)0.1f)));
            Assert.That(level.Materials, Has.Count.EqualTo(3));
        });

        string plain = new SourceGeometry("swamp").AddFaces("Mud", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise).Fingerprint;
        string costly = new SourceGeometry("swamp").AddFaces("Mud", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise, travelCost: 4f, enterCost: 2f).Fingerprint;
        Assert.That(costly, Is.EqualTo(plain), "costs are not part of the level fingerprint: changing them needs no rebake");

        LevelException refused = Assert.Throws<LevelException>(() => new SourceGeometry("swamp").AddBox("Level/Pool", Vector3.One, Matrix4x4.Identity, enterCost: -3f))!;
        Assert.That(refused.Message, Is.EqualTo("Source 'Level/Pool' in swamp: its enter cost -3 must be a number of seconds from 0 to 10000."));
    }

    private static readonly Matrix4x4 Flat = Matrix4x4.CreateScale(1f, 0f, 1f);

    private static readonly Matrix4x4 Projective = new(1f, 0f, 0f, 0.5f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f);

    private static IEnumerable<TestCaseData> BadSources()
    {
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddFaces("Level/Odd", GodotPlaneFaces.AsSpan(0, 5), Matrix4x4.Identity, FaceWinding.Clockwise)), "5 vertices is not a whole number of triangles").SetName("VertexCountNotAMultipleOfThree");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddFaces("Level/Odd", [new(0f, 0f, 0f), new(float.NaN, 0f, 0f), new(1f, 0f, 0f)], Matrix4x4.Identity, FaceWinding.Clockwise)), "vertex 1 (triangle 0) is not finite").SetName("NaNVertex");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddFaces("Level/Odd", GodotPlaneFaces, Matrix4x4.CreateTranslation(float.PositiveInfinity, 0f, 0f), FaceWinding.Clockwise)), "NaN or infinite").SetName("InfiniteTransform");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddFaces("Level/Odd", GodotPlaneFaces, Flat, FaceWinding.Clockwise)), "flattens it").SetName("ZeroScaleTransform");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", Vector3.One, Projective)), "not affine").SetName("ProjectiveTransform");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", new Vector3(1f, -1f, 1f), Matrix4x4.Identity)), "box size (1, -1, 1) must be finite and not negative").SetName("NegativeBoxSize");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", new Vector3(1f, float.NaN, 1f), Matrix4x4.Identity)), "must be finite").SetName("NaNBoxSize");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", Vector3.One, Matrix4x4.Identity, friction: -0.5f)), "friction -0.5 must be finite").SetName("NegativeFriction");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", Vector3.One, Matrix4x4.Identity, friction: float.NaN)), "friction NaN must be finite").SetName("NaNFriction");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddBox("Level/Odd", Vector3.One, Matrix4x4.CreateTranslation(2e6f, 0f, 0f))), "beyond the ±1e6 m").SetName("TooFar");
        yield return new TestCaseData((Action<SourceGeometry>)(g => g.AddFaces("Level/Odd", GodotPlaneFaces, Matrix4x4.Identity, (FaceWinding)7)), "unknown face winding 7").SetName("UnknownWinding");
    }

    [TestCaseSource(nameof(BadSources))]
    public void ABadSourceIsAOneLineErrorNamingItAndAddsNothing(Action<SourceGeometry> add, string problem)
    {
        SourceGeometry geometry = new SourceGeometry("Main/JumpRoadmap3D").AddFaces("Level/Good", GodotPlaneFaces, Matrix4x4.Identity, FaceWinding.Clockwise);
        string before = geometry.Fingerprint;
        LevelException error = Assert.Throws<LevelException>(() => add(geometry))!;
        Assert.Multiple(() =>
        {
            Assert.That(error.Message, Does.Contain("'Level/Odd'"));
            Assert.That(error.Message, Does.Contain("Main/JumpRoadmap3D"));
            Assert.That(error.Message, Does.Contain(problem));
            Assert.That(error.Message, Does.Not.Contain('\n'));
            Assert.That(geometry.SourceCount, Is.EqualTo(1));
            Assert.That(geometry.Fingerprint, Is.EqualTo(before), "the failed source added nothing");
        });
    }

    [Test]
    public void NoSourceOrOnlyFlatTrianglesFailClearly()
    {
        LevelException none = Assert.Throws<LevelException>(() => new SourceGeometry("Main/JumpRoadmap3D").Build())!;
        Assert.That(none.Message, Is.EqualTo("The level Main/JumpRoadmap3D has no source geometry: no mesh or collision shape was given to bake on."));

        SourceGeometry flat = new SourceGeometry("Main/JumpRoadmap3D").AddBox("Level/Sheet", Vector3.Zero, Matrix4x4.Identity);
        LevelException empty = Assert.Throws<LevelException>(() => _ = flat.Fingerprint)!;
        Assert.That(empty.Message, Does.Contain("is empty: all 12 of its triangles have zero area"));
    }

    [Test]
    public void ALineBreakInANameStaysOnOneLine()
    {
        LevelException error = Assert.Throws<LevelException>(() =>
            new SourceGeometry("Main\nRoadmap").AddFaces("Bad\nNode", GodotPlaneFaces.AsSpan(0, 4), Matrix4x4.Identity, FaceWinding.Clockwise))!;
        Assert.That(error.Message, Does.Not.Contain('\n'));
        Assert.That(error.Message, Does.Contain("Bad\\u000aNode"));
    }
}
