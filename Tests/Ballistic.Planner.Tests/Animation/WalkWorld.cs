using System.Collections.Concurrent;
using System.Numerics;
using Ballistic.Authoring.Characters;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Contacts;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Sampling;
using Ballistic.Planner.Steering;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// A character on a level for walking tests: stances placed where the whole body can stand, straight walks between
/// them on a ground path sampled by rays, and jumps found by the steering method; walks are built by hand, not planned.
/// </summary>
internal sealed record WalkWorld(PlanningScene Scene, CharacterModel Model, JumpAnimator Animator)
{
    /// <summary>Ground path points are at most this far apart, metres.</summary>
    public const float PathSpacing = 0.2f;

    /// <summary>Foreign characters (<see cref="ForeignCharacters"/>) loaded once each, from files written to a folder removed after.</summary>
    private static readonly ConcurrentDictionary<string, Lazy<(CharacterModel Model, ReducedCharacter Reduced)>> Foreign = new(StringComparer.Ordinal);

    /// <summary>
    /// The character on the level: a bundled one ("skeleton" biped, "ant" hexapod, …) or a foreign rig loaded through
    /// its limbs-only spec ("dog", "human", "human-zup", "tailed", "spider").
    /// </summary>
    public static WalkWorld Create(Level level, string character)
    {
        (CharacterModel model, ReducedCharacter reduced) = character is "dog" or "human" or "human-zup" or "tailed" or "spider"
            ? Foreign.GetOrAdd(character, name => new Lazy<(CharacterModel, ReducedCharacter)>(() => LoadForeign(name))).Value
            : (CharacterPresets.Model(character), CharacterPresets.Get(character));
        var scene = PlanningScene.Create(level, reduced);
        return new WalkWorld(scene, model, new JumpAnimator(scene, model));
    }

    private static (CharacterModel Model, ReducedCharacter Reduced) LoadForeign(string name)
    {
        // Kept while the tests run: a rig with an external texture (the dog's) reads it again when its animation is exported.
        string folder = Path.Combine(Path.GetTempPath(), $"ballistic-walk-{name}-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        AppDomain.CurrentDomain.ProcessExit += (_, _) =>
        {
            if (Directory.Exists(folder))
            {
                Directory.Delete(folder, recursive: true);
            }
        };
        (string gltf, string spec) = ForeignCharacters.Named(name).Write(folder);
        return CharacterSpecFile.Load(gltf, spec);
    }

    /// <summary>The bundled gap course: four flat platforms along +X with gaps between them.</summary>
    public static Level GapCourse() => SharedLevels.Bundled("gap-course");

    /// <summary>
    /// A straight walk animated by hand across the gap course's first platform (this world's level), from a stance
    /// near (−7.3, 0, 0.5) to one near (−3.8, 0, −0.3), both facing +X.
    /// </summary>
    public JumpAnimation AcrossFirstPlatform()
    {
        RoadmapNode from = Stance(new Vector3(-7.3f, 0f, 0.5f), 0, Vector3.UnitX);
        RoadmapNode to = Stance(new Vector3(-3.8f, 0f, -0.3f), 1, Vector3.UnitX);
        return Animator.Animate([Walk(from, to)]);
    }

    /// <summary>
    /// A stance where the whole body stands, its contacts' centre within 0.3 m of <paramref name="point"/>; turned to
    /// face <paramref name="facing"/> (horizontal, world) when given.
    /// </summary>
    public RoadmapNode Stance(Vector3 point, int id, Vector3? facing = null)
    {
        EndpointPlacement placed = Scene.Sampler.Place(point, new EndpointTolerance(0.3f, 0.25f), Animator.CanStand);
        Assert.That(placed.Placed, Is.True, $"{Model.Name} stands near {point}");
        PoseEvaluation pose = placed.Pose!;
        if (facing is Vector3 f)
        {
            var turned = new RootPose(pose.Pose.Position, Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.Atan2(f.X, f.Z)));
            pose = Scene.Estimator.Evaluate(turned);
            Assert.That(pose.IsValid && Animator.CanStand(pose), Is.True, $"{Model.Name} stands near {point} facing {f}: {pose.Validity}");
        }

        return new RoadmapNode(id, pose.Pose, pose.Cone, pose.Contacts);
    }

    /// <summary>The centre of a stance's contacts.</summary>
    public static Vector3 Centre(RoadmapNode node)
    {
        Vector3 sum = Vector3.Zero;
        foreach (Contact c in node.Contacts)
        {
            sum += c.Position;
        }

        return sum / node.Contacts.Count;
    }

    /// <summary>The highest ground straight below (x, z) under <paramref name="top"/>, or null.</summary>
    public Vector3? Ground(float x, float z, float top)
    {
        float depth = top - Scene.Bvh.Bounds.Min.Y + 1f;
        return Scene.Bvh.Raycast(new Vector3(x, top, z), -Vector3.UnitY, depth, out RayHit hit) ? hit.Point : null;
    }

    /// <summary>A straight walk from one stance to another at the character's walking speed on the ground sampled every <see cref="PathSpacing"/> or less.</summary>
    public Walk Walk(RoadmapNode from, RoadmapNode to) => new(from, to, GroundPath(Centre(from), Centre(to)), Scene.Character.Walking.Speed, turnRate: Scene.Character.Walking.TurnRate);

    /// <summary>Ground points from below <paramref name="a"/> to below <paramref name="b"/>, straight across, at most <see cref="PathSpacing"/> apart.</summary>
    public Vector3[] GroundPath(Vector3 a, Vector3 b)
    {
        float top = MathF.Max(a.Y, b.Y) + 0.5f;
        int count = Math.Max(1, (int)MathF.Ceiling(new Vector2(b.X - a.X, b.Z - a.Z).Length() / PathSpacing));
        var points = new Vector3[count + 1];
        for (int i = 0; i <= count; i++)
        {
            Vector3 p = Vector3.Lerp(a, b, i / (float)count);
            points[i] = Ground(p.X, p.Z, top) ?? throw new AssertionException($"no ground below {p}");
        }

        return points;
    }

    /// <summary>A jump from one stance to another found by the steering method.</summary>
    public Jump Jump(RoadmapNode from, RoadmapNode to)
    {
        SteeringResult steered = Scene.Steering.Steer(from.Pose, from.Cone, to.Pose, to.Cone);
        Assert.That(steered.Succeeded, Is.True, $"{Model.Name} jumps from {from.Pose.Position} to {to.Pose.Position}: {steered.Failure}");
        return new Jump(from, to, steered.Arc);
    }
}
