using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Collision;
using Ballistic.Planner.Geometry;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Roadmaps;
using Ballistic.Planner.Tests.Support;

namespace Ballistic.Planner.Tests.Animation;

/// <summary>
/// The hold refiner solves and checks each frame's holds once: a frame ends one interval and starts the next, and a
/// halved interval's halves share its ends. What it adds is the same to the bit as checking every interval's ends anew.
/// </summary>
public sealed class HoldRefinerTests
{
    /// <summary>
    /// A walk across the gap course's first platform, its frames thinned to every third (so that held feet sag between
    /// them and the refiner adds frames, halving intervals), refined remembering each frame's holds and not: the same
    /// frames, angles and failures, with at most 55 % of the checks (each frame checked once instead of twice, the
    /// halvings' shared ends too).
    /// </summary>
    [Test]
    public void RememberingEachFramesHoldsChangesNoRefinement()
    {
        WalkWorld world = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        JumpAnimation walked = world.AcrossFirstPlatform();
        AnimationFrame[] thinned = [.. walked.Frames.Where((_, i) => i % 3 == 0 || i == walked.Frames.Count - 1)];
        var clip = new JumpAnimation(walked.Model, walked.Moves, walked.Stances, thinned, walked.ContactPhases, [], 0, 0, walked.LeadIn, walked.LeadOut);
        var collision = new BodyCollision(world.Scene.Bvh, world.Model, world.Scene.Level.Triangles);
        var remembering = new HoldRefiner(world.Model, collision);
        var checking = new HoldRefiner(world.Model, collision) { RemembersFrames = false };

        (List<AnimationFrame> frames, List<(int Limb, float Time)> failures) = remembering.Refine(clip);
        (List<AnimationFrame> expected, List<(int Limb, float Time)> expectedFailures) = checking.Refine(clip);

        Assert.Multiple(() =>
        {
            Assert.That(frames.Count, Is.GreaterThan(thinned.Length), "frames added where held feet sag between the thinned ones");
            Assert.That(frames.Select(f => (f.Time, f.Root)), Is.EqualTo(expected.Select(f => (f.Time, f.Root))));
            Assert.That(frames.SelectMany(f => f.Angles), Is.EqualTo(expected.SelectMany(f => f.Angles)));
            Assert.That(failures, Is.EqualTo(expectedFailures));
            Assert.That(remembering.HoldChecks, Is.LessThanOrEqualTo(0.55 * checking.HoldChecks), $"{remembering.HoldChecks} checks remembering, {checking.HoldChecks} not");
        });
    }

    /// <summary>
    /// A held limb's bones checked against the level at an interval's frames only when they are in it at the
    /// midpoint: the same frames, angles and failures as checking them at every frame, with about half the checks, on
    /// thinned clips (one frame in three kept) of the walk across the gap course's first platform and of jumps and
    /// walks over the desert's dunes, where feet sag between frames and some held limbs are in the sand at frames
    /// already; and on the gap course's walk (one frame in twelve) with a 2 cm cube where a held leg's joint passes between two frames, its
    /// bones clear of the cube at both: the refiner adds frames there, whichever way it checks.
    /// </summary>
    [Test]
    public void CheckingTheFramesBonesOnlyWhenTheMidpointIsInTheLevelChangesNoRefinement()
    {
        var clips = new List<(string Name, JumpAnimation Clip, BodyCollision Collision)>();
        WalkWorld gap = WalkWorld.Create(WalkWorld.GapCourse(), "skeleton");
        JumpAnimation walk = Thinned(gap.AcrossFirstPlatform());
        clips.Add(("gap course walk", walk, Collision(gap)));
        WalkWorld desert = WalkWorld.Create(SharedLevels.Bundled("desert"), "skeleton");
        Roadmap roadmap = new RoadmapBaker(desert.Scene).Bake(new BakeSettings { Locomotion = Locomotion.WalkAndJump, Seed = 1, MaxNodes = 200, Threads = 2 }).Roadmap;
        foreach (RoadmapEdge edge in roadmap.Edges.Where((_, i) => i % 97 == 0).Take(12))
        {
            clips.Add(($"desert jump {edge.From} -> {edge.To}", Thinned(desert.Animator.Animate([new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)])), Collision(desert)));
        }

        foreach (RoadmapWalk step in roadmap.Walks.Where((_, i) => i % 53 == 0).Take(6))
        {
            clips.Add(($"desert walk {step.From} -> {step.To}", Thinned(desert.Animator.Animate([desert.Walk(roadmap.Nodes[step.From], roadmap.Nodes[step.To])])), Collision(desert)));
        }

        JumpAnimation sparse = Thinned(gap.AcrossFirstPlatform(), 12);
        (BodyCollision cubed, float between) = CubeBetweenFrames(gap, sparse);
        clips.Add(("gap course walk by a cube", sparse, cubed));

        int ends = 0;
        int lazyChecks = 0;
        int everyChecks = 0;
        Assert.Multiple(() =>
        {
            foreach ((string name, JumpAnimation clip, BodyCollision collision) in clips)
            {
                var lazy = new HoldRefiner(clip.Model, collision);
                var every = new HoldRefiner(clip.Model, collision) { ChecksEndsWhenNeeded = false };
                (List<AnimationFrame> frames, List<(int Limb, float Time)> failures) = lazy.Refine(clip);
                (List<AnimationFrame> expected, List<(int Limb, float Time)> expectedFailures) = every.Refine(clip);
                Assert.That(frames.Select(f => (f.Time, f.Root)), Is.EqualTo(expected.Select(f => (f.Time, f.Root))), name);
                Assert.That(frames.SelectMany(f => f.Angles), Is.EqualTo(expected.SelectMany(f => f.Angles)), name);
                Assert.That(failures, Is.EqualTo(expectedFailures), name);
                if (collision == cubed)
                {
                    (List<AnimationFrame> clear, _) = new HoldRefiner(clip.Model, Collision(gap)).Refine(clip);
                    Assert.That(expected.Count(f => f.Time > between - 0.05f && f.Time < between + 0.05f), Is.GreaterThan(clear.Count(f => f.Time > between - 0.05f && f.Time < between + 0.05f)), "frames added where the leg passes the cube");
                }

                ends += every.EndsInLevel;
                lazyChecks += lazy.BoneChecks;
                everyChecks += every.BoneChecks;
            }

            TestContext.Out.WriteLine($"{clips.Count} clips: {lazyChecks} bone checks checking frames when needed, {everyChecks} at every frame; {ends} frames with a held limb in the level");
            Assert.That(ends, Is.GreaterThan(0), "some held limbs are in the level at frames, so the frames' checks decide something");
            Assert.That(lazyChecks, Is.LessThanOrEqualTo(0.6 * everyChecks));
        });
    }

    private static BodyCollision Collision(WalkWorld world) => new(world.Scene.Bvh, world.Model, world.Scene.Level.Triangles);

    /// <summary>
    /// The gap course with a 2 cm cube where a joint of a held leg is at the midpoint of two of <paramref name="clip"/>'s
    /// frames, as the refiner poses it (the root where the clip has it, the angles half-way), and the bones of that leg
    /// clear of the cube at both frames (checked here); and the midpoint's time.
    /// </summary>
    private static (BodyCollision Collision, float Time) CubeBetweenFrames(WalkWorld world, JumpAnimation clip)
    {
        Rig rig = world.Model.Rig;
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        Vector3 JointAt(RootPose root, float[] angles, int joint)
        {
            rig.Solve(root, angles, positions, rotations);
            return positions[joint];
        }

        for (int k = 1; k < clip.Frames.Count; k++)
        {
            AnimationFrame a = clip.Frames[k - 1];
            AnimationFrame b = clip.Frames[k];
            foreach (ContactPhase phase in clip.ContactPhases.Where(p => p.From <= a.Time && p.To >= b.Time))
            {
                RigLimb limb = world.Model.Limbs[phase.Limb];
                float time = a.Time + (0.5f * (b.Time - a.Time));
                float[] half = [.. a.Angles.Zip(b.Angles, (x, y) => float.Lerp(x, y, 0.5f))];
                foreach (int joint in limb.Chain.Take(limb.Chain.Count - 1))
                {
                    Vector3 middle = JointAt(clip.RootAt(time), half, joint);
                    if (Vector3.Distance(middle, JointAt(a.Root, a.Angles, joint)) < 0.03f || Vector3.Distance(middle, JointAt(b.Root, b.Angles, joint)) < 0.03f)
                    {
                        continue;
                    }

                    var builder = new LevelBuilder("gap-course-cube");
                    foreach (Triangle triangle in world.Scene.Level.Triangles)
                    {
                        builder.AddTriangle(triangle, TestLevels.Ground);
                    }

                    Level level = builder.AddBox(middle - new Vector3(0.01f), middle + new Vector3(0.01f)).Build();
                    var collision = new BodyCollision(new TriangleBvh(level.Triangles), world.Model, level.Triangles);
                    rig.Solve(a.Root, a.Angles, positions, rotations);
                    bool atA = collision.LimbCollides(limb, positions, rotations, phase.Position);
                    rig.Solve(b.Root, b.Angles, positions, rotations);
                    bool atB = collision.LimbCollides(limb, positions, rotations, phase.Position);
                    rig.Solve(clip.RootAt(time), half, positions, rotations);
                    if (!atA && !atB && collision.LimbCollides(limb, positions, rotations, phase.Position))
                    {
                        return (collision, time);
                    }
                }
            }
        }

        Assert.Fail("no held leg's joint moves 3 cm between two frames of the thinned walk, its bones clear of a cube where it is half-way");
        throw new InvalidOperationException();
    }

    /// <summary>The clip with one frame in <paramref name="every"/> kept (and the last), so that held feet sag between them.</summary>
    private static JumpAnimation Thinned(JumpAnimation clip, int every = 3)
    {
        AnimationFrame[] thinned = [.. clip.Frames.Where((_, i) => i % every == 0 || i == clip.Frames.Count - 1)];
        return new JumpAnimation(clip.Model, clip.Moves, clip.Stances, thinned, clip.ContactPhases, [], 0, 0, clip.LeadIn, clip.LeadOut);
    }
}
