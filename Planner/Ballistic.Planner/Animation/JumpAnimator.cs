using System.Numerics;
using Ballistic.Planner.Characters;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Rigs;
using Ballistic.Planner.Steering;

namespace Ballistic.Planner.Animation;

/// <summary>
/// Turns a planned path into a whole-body animation (paper §5): contact poses at takeoff and landing, each limb
/// keeping its contact by IK while the root moves along the arc until the IK fails (takeoff) or from the moment it
/// succeeds (landing), an extended pose at the apex, and per-angle interpolation between these key poses for each
/// limb, re-sampling a limb's apex pose when it would pass through the level. The root stays on the parabola.
/// </summary>
public sealed class JumpAnimator
{
    private const int MaxResamples = 64;

    private readonly ContactGenerator _contacts;
    private readonly LimbIk _holdIk;

    /// <summary>Creates an animator for a character model on a planning scene of its reduced model.</summary>
    public JumpAnimator(PlanningScene scene, CharacterModel model)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(model);
        _contacts = new ContactGenerator(scene, model);
        _holdIk = new LimbIk(model.Rig, new IkSettings { Restarts = 0, MaxIterations = 12 });
        Model = model;
    }

    /// <summary>The character.</summary>
    public CharacterModel Model { get; }

    /// <summary>The contact generator (its databases and collision checks).</summary>
    public ContactGenerator Contacts => _contacts;

    /// <summary>Animates the jumps at <paramref name="frameRate"/> frames per second.</summary>
    /// <exception cref="ArgumentException">No jumps, or a non-positive frame rate.</exception>
    public JumpAnimation Animate(IReadOnlyList<Jump> jumps, float frameRate = 60f)
    {
        ArgumentNullException.ThrowIfNull(jumps);
        if (jumps.Count == 0)
        {
            throw new ArgumentException("There are no jumps to animate.", nameof(jumps));
        }

        if (!(frameRate > 0f))
        {
            throw new ArgumentException("The frame rate must be positive.", nameof(frameRate));
        }

        var frames = new List<AnimationFrame>();
        var phases = new List<ContactPhase>();
        var open = new Dictionary<int, (Vector3 Position, float From)>();
        int failed = 0;
        int colliding = 0;
        float clock = 0f;
        ContactConfiguration? previousLanding = null;
        for (int j = 0; j < jumps.Count; j++)
        {
            Jump jump = jumps[j];
            BallisticArc arc = jump.Arc;
            ContactConfiguration takeoff = previousLanding is { } landed && landed.Valid && landed.Cone.Contains(arc.TakeoffVelocity, 1e-3f)
                ? landed
                : _contacts.Generate(arc.Takeoff, jump.Takeoff.Contacts, arc.TakeoffVelocity);
            ContactConfiguration landing = _contacts.Generate(arc.Landing, jump.Landing.Contacts, -arc.LandingVelocity);
            failed += (takeoff.Valid ? 0 : 1) + (landing.Valid ? 0 : 1);

            (AnimationFrame[] jumpFrames, float[] breaks, float[] makes, int bad) = AnimateJump(arc, takeoff, landing, clock, frameRate);
            colliding += bad;

            // Contact phases: takeoff contacts continue the previous landing's when the same limb holds the same point.
            var holding = new HashSet<int>();
            foreach (LimbContact c in takeoff.Contacts)
            {
                holding.Add(c.Limb);
                if (open.TryGetValue(c.Limb, out (Vector3 Position, float From) o) && Vector3.Distance(o.Position, c.Position) > 1e-4f)
                {
                    phases.Add(new ContactPhase(c.Limb, o.Position, o.From, clock));
                    open.Remove(c.Limb);
                }

                if (!open.ContainsKey(c.Limb))
                {
                    open[c.Limb] = (c.Position, clock);
                }

                phases.Add(new ContactPhase(c.Limb, open[c.Limb].Position, open[c.Limb].From, clock + breaks[c.Limb]));
                open.Remove(c.Limb);
            }

            foreach ((int limb, (Vector3 position, float from)) in open)
            {
                if (!holding.Contains(limb))
                {
                    phases.Add(new ContactPhase(limb, position, from, clock));
                }
            }

            open.Clear();
            foreach (LimbContact c in landing.Contacts)
            {
                open[c.Limb] = (c.Position, clock + makes[c.Limb]);
            }

            frames.AddRange(j == 0 ? jumpFrames : jumpFrames[1..]);
            clock += arc.FlightTime;
            previousLanding = landing;
        }

        foreach ((int limb, (Vector3 position, float from)) in open)
        {
            phases.Add(new ContactPhase(limb, position, from, clock));
        }

        phases.Sort((a, b) => a.From != b.From ? a.From.CompareTo(b.From) : a.Limb.CompareTo(b.Limb));
        return new JumpAnimation(Model, [.. jumps.Select(x => x.Arc)], frames, phases, failed, colliding);
    }

    /// <summary>Contact phases are stepped this many times finer than the frame rate, so that held contacts do not slide between frames.</summary>
    private const int ContactSubsteps = 4;

    private (AnimationFrame[] Frames, float[] Breaks, float[] Makes, int Colliding) AnimateJump(BallisticArc arc, ContactConfiguration takeoff, ContactConfiguration landing, float clock, float frameRate)
    {
        Rig rig = Model.Rig;
        int frames = Math.Max(2, (int)MathF.Ceiling(arc.FlightTime * frameRate));
        int steps = frames * ContactSubsteps;
        float h = arc.FlightTime / steps;
        float Time(int i) => i >= steps ? arc.FlightTime : i * h;
        int limbs = Model.Limbs.Count;
        var held = new Dictionary<int, float[]>[limbs];
        int[] breaks = new int[limbs];
        int[] makes = new int[limbs];

        // Contact phases on the fine grid: hold each contact by IK, forward from takeoff and backward from landing.
        for (int l = 0; l < limbs; l++)
        {
            held[l] = [];
            breaks[l] = Hold(arc, takeoff, l, 0, +1, steps / 2, held[l], h, steps);
            makes[l] = Hold(arc, landing, l, steps, -1, Math.Max(breaks[l] + 1, steps / 2), held[l], h, steps);
        }

        // The times that become frames: every frame, and every fine step while some limb holds a contact.
        var grid = new SortedSet<int>();
        for (int f = 0; f <= frames; f++)
        {
            grid.Add(f * ContactSubsteps);
        }

        for (int i = 0; i <= breaks.Max(); i++)
        {
            grid.Add(i);
        }

        for (int i = makes.Min(); i <= steps; i++)
        {
            grid.Add(i);
        }

        int[] times = [.. grid];
        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];

        // Apex: the extending pose, each limb kept out of the level.
        int apex = Math.Clamp((int)MathF.Round(arc.ApexTime / h), 1, steps - 1);
        RootPose apexRoot = arc.PoseAt(Time(apex));
        float[] apexAngles = (float[])Model.ExtendingPose.Clone();
        for (int l = 0; l < limbs; l++)
        {
            rig.Solve(apexRoot, apexAngles, positions, rotations);
            if (_contacts.Collision.LimbCollides(Model.Limbs[l], positions, rotations, null))
            {
                _contacts.KeepFree(apexRoot, apexAngles, l);
            }
        }

        var angles = new float[times.Length][];
        var limbDof = new bool[rig.DofCount];
        foreach (RigLimb limb in Model.Limbs)
        {
            foreach (int d in limb.ChainDofs)
            {
                limbDof[d] = true;
            }
        }

        // Trunk angles (in no limb): takeoff → apex → landing.
        for (int k = 0; k < times.Length; k++)
        {
            int i = times[k];
            angles[k] = new float[rig.DofCount];
            for (int d = 0; d < rig.DofCount; d++)
            {
                if (!limbDof[d])
                {
                    angles[k][d] = i <= apex
                        ? float.Lerp(takeoff.Angles[d], apexAngles[d], i / (float)apex)
                        : float.Lerp(apexAngles[d], landing.Angles[d], (i - apex) / (float)(steps - apex));
                }
            }
        }

        // Each limb: held angles in its contact phases; in flight, break → apex → make, re-sampling the apex pose
        // while a frame would put a bone through the level.
        int colliding = 0;
        var random = new Random(17);
        for (int l = 0; l < limbs; l++)
        {
            RigLimb limb = Model.Limbs[l];
            float[] from = held[l][breaks[l]];
            float[] to = held[l][makes[l]];
            float[] limbApex = (float[])apexAngles.Clone();
            bool clear = false;
            for (int attempt = 0; attempt <= MaxResamples && !clear; attempt++)
            {
                // Re-sampling: the tucked and contact poses first, then random samples of the limb's database.
                if (attempt is 1 or 2)
                {
                    float[] pose = attempt == 1 ? Model.FlexionPose : Model.ContactPose;
                    foreach (int d in limb.ChainDofs)
                    {
                        limbApex[d] = pose[d];
                    }
                }
                else if (attempt > 2)
                {
                    _contacts.Database(l).Apply(random.Next(_contacts.Database(l).Count), limbApex);
                }

                clear = true;
                for (int k = 0; k < times.Length; k++)
                {
                    int i = times[k];
                    if (held[l].TryGetValue(i, out float[]? holding) && (i <= breaks[l] || i >= makes[l]))
                    {
                        foreach (int d in limb.ChainDofs)
                        {
                            angles[k][d] = holding[d];
                        }

                        continue;
                    }

                    foreach (int d in limb.ChainDofs)
                    {
                        angles[k][d] = apex > breaks[l] && apex < makes[l]
                            ? (i <= apex ? float.Lerp(from[d], limbApex[d], (i - breaks[l]) / (float)(apex - breaks[l])) : float.Lerp(limbApex[d], to[d], (i - apex) / (float)(makes[l] - apex)))
                            : float.Lerp(from[d], to[d], (i - breaks[l]) / (float)(makes[l] - breaks[l]));
                    }

                    rig.Solve(arc.PoseAt(Time(i)), angles[k], positions, rotations);
                    if (_contacts.Collision.LimbCollides(limb, positions, rotations, null))
                    {
                        clear = false;
                    }
                }
            }

            if (!clear)
            {
                colliding++;
            }
        }

        var result = new AnimationFrame[times.Length];
        for (int k = 0; k < times.Length; k++)
        {
            float t = Time(times[k]);
            result[k] = new AnimationFrame(clock + t, arc.PoseAt(t), angles[k]);
        }

        return (result, [.. breaks.Select(b => Time(b))], [.. makes.Select(m => Time(m))], colliding);
    }

    /// <summary>
    /// Records limb <paramref name="l"/>'s angles at fine step <paramref name="start"/> and onward by
    /// <paramref name="direction"/> while it holds its contact in <paramref name="config"/> by IK (with no bone through
    /// the level), up to step <paramref name="limit"/>. Returns the last step where it held (the start for a free limb).
    /// </summary>
    private int Hold(BallisticArc arc, ContactConfiguration config, int l, int start, int direction, int limit, Dictionary<int, float[]> held, float h, int steps)
    {
        Rig rig = Model.Rig;
        RigLimb limb = Model.Limbs[l];
        float[] q = (float[])config.Angles.Clone();
        held[start] = (float[])q.Clone();
        LimbContact? target = null;
        foreach (LimbContact c in config.Contacts)
        {
            if (c.Limb == l)
            {
                target = c;
            }
        }

        if (target is not LimbContact contact)
        {
            return start;
        }

        var positions = new Vector3[rig.Joints.Count];
        var rotations = new Quaternion[rig.Joints.Count];
        int last = start;
        for (int i = start + direction; direction > 0 ? i <= limit : i >= limit; i += direction)
        {
            RootPose root = arc.PoseAt(i >= steps ? arc.FlightTime : i * h);
            IkResult result = _holdIk.Solve(root, q, limb, contact.Position, -contact.Normal);
            if (!result.Success)
            {
                break;
            }

            rig.Solve(root, q, positions, rotations);
            if (_contacts.Collision.LimbCollides(limb, positions, rotations, contact.Position))
            {
                break;
            }

            held[i] = (float[])q.Clone();
            last = i;
        }

        return last;
    }
}
