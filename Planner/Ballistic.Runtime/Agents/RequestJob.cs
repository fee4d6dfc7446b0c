using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Planning;
using Ballistic.Planner.Query;
using Ballistic.Planner.Roadmaps;
using Ballistic.Runtime.Kinds;
using Ballistic.Runtime.Paths;

namespace Ballistic.Runtime.Agents;

/// <summary>
/// One started path request as a job for any thread: the planner's plan-and-repair loop (<see cref="PlanJob"/>, the
/// one <see cref="AnimatedPlanner"/> runs) on the kind's roadmap, from the request's stance to its target, starting
/// with its given moves if any: search, animate, set aside what the body cannot perform and search again, up to
/// <c>rounds</c> searches. Its inputs are read from the request when it starts, on the tick (<see cref="Begin"/>); the
/// request does not change until its outcome is delivered, so the job gives the same outcome on whichever thread and
/// at whatever time it runs, whole (<see cref="TryRun"/>, <see cref="Run"/>) or in slices on the tick
/// (<see cref="Advance"/>). Everything the job makes (its repair record, taught the kind's lessons; its searches; the
/// path its agent follows) is made on the thread that runs it. Reused with its <see cref="PathRequest"/>: between two
/// uses it is claimed, so that a thread holding it from an earlier use leaves it alone.
/// </summary>
internal sealed class RequestJob : IDisposable
{
    private CharacterKind? _kind;
    private RoadmapSearch? _search;
    private RoadmapNode? _start;
    private Vector3 _target;
    private int _forcedEdge;
    private IReadOnlyList<Move>? _forcedMoves;
    private TaughtStances _lessons = TaughtStances.None;
    private int _rounds;
    private float _frameRate;
    private JumpRepair? _repair;
    private PlanJob? _job;
    private RequestOutcome? _outcome;
    private int _claimed = 1;
    private volatile bool _ended;

    /// <summary>
    /// Readies the job for <paramref name="request"/> as it starts (its stance, target and given moves read now),
    /// on <paramref name="kind"/>'s roadmap through <paramref name="search"/>, taught <paramref name="lessons"/>; after
    /// this call (and not before) any thread may claim it.
    /// </summary>
    public void Begin(CharacterKind kind, RoadmapSearch search, PathRequest request, TaughtStances lessons, int rounds, float frameRate)
    {
        _kind = kind;
        _search = search;
        _start = request.Start!;
        _target = request.Target;
        _forcedEdge = request.ForcedEdge;
        _forcedMoves = request.ForcedMoves;
        _lessons = lessons;
        _rounds = rounds;
        _frameRate = frameRate;
        _repair = null;
        _job = null;
        _outcome = null;
        _ended = false;
        Volatile.Write(ref _claimed, 0); // last: a thread that claims the job sees every field above
    }

    /// <summary>The request's repair record (what was set aside, and why), once the job has begun running; <c>null</c> before.</summary>
    public JumpRepair? Repair => _repair;

    /// <summary>True once a background thread has run the job to its end (<see cref="RunInBackground"/>): its <see cref="Outcome"/> may then be read on any thread.</summary>
    public bool Ended => _ended;

    /// <summary>The job's outcome once it has ended; <c>null</c> before.</summary>
    public RequestOutcome? Outcome => _outcome;

    /// <summary>
    /// Runs the job unless a thread has already claimed it (<see cref="TryRun"/> or <see cref="Run"/>): the tick thread
    /// waiting for a request may run it itself when no background thread has started it. Null when it was claimed.
    /// </summary>
    public RequestOutcome? TryRun() => Interlocked.Exchange(ref _claimed, 1) == 0 ? Advance(slice: null) : null;

    /// <summary>
    /// <see cref="TryRun"/> on a background thread: when this thread runs the job, it marks it <see cref="Ended"/>
    /// afterwards; true when it ran it.
    /// </summary>
    public bool RunInBackground()
    {
        if (Interlocked.Exchange(ref _claimed, 1) != 0)
        {
            return false;
        }

        try
        {
            Advance(slice: null);
        }
        catch (Exception e)
        {
            // Advance turns what the planner throws into the outcome; anything else (out of memory) ends the job too.
            _outcome ??= new RequestOutcome(null, [], null, e, Searching: false);
        }
        finally
        {
            _ended = true;
        }

        return true;
    }

    /// <summary>Runs the job here, to its end (a world with no background threads); its outcome.</summary>
    public RequestOutcome Run() => Advance(slice: null)!;

    /// <summary>
    /// Advances the job on this thread until it ends or <paramref name="slice"/> says to stop (<see cref="PlanJob.Advance"/>;
    /// <c>null</c>: to its end): its outcome once it has ended, otherwise <c>null</c>. An exception the job throws ends
    /// it with that error as its outcome.
    /// </summary>
    public RequestOutcome? Advance(TerminationCondition? slice)
    {
        if (_outcome is not null)
        {
            return _outcome;
        }

        _claimed = 1;
        if (_job is null)
        {
            // The repair record, taught what the kind's earlier requests found about its stances (the request's own
            // start named first among them when it is one).
            var repair = new JumpRepair { Start = _start!.Id };
            _lessons.Teach(repair);
            _repair = repair;
            IReadOnlyList<Move>? given = _forcedMoves;
            if (_forcedEdge >= 0)
            {
                Roadmap roadmap = _kind!.Roadmap;
                RoadmapEdge edge = roadmap.Edges[_forcedEdge];
                given = [new Jump(roadmap.Nodes[edge.From], roadmap.Nodes[edge.To], edge.Arc)];
            }

            RoadmapSearch search = _search!;
            RoadmapNode start = _start;
            Vector3 target = _target;
            _job = new PlanJob((r, _) => search.Search(start, target, r), _kind!.PathAnimator, repair, _rounds, _frameRate) { Given = given };
        }

        try
        {
            if (!_job.Advance(slice))
            {
                return null;
            }

            (PlanResult result, JumpAnimation? animation, _) = _job.Outcome!.Value;
            _outcome = animation is null
                ? new RequestOutcome(result, [], null, null, Searching: false)
                : new RequestOutcome(result, result.Moves, animation, null, Searching: false, new AgentPath(_target, result.Moves, animation));
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            _outcome = new RequestOutcome(null, [], null, e, Searching: _job.Phase == "searching");
            _job.Dispose();
        }

        return _outcome;
    }

    /// <summary>Steps the job has taken (<see cref="PlanJob.Steps"/>).</summary>
    public int Steps => _job?.Steps ?? 0;

    /// <summary>Ends the job where it stands (its request dropped), releasing the query its search holds.</summary>
    public void Dispose() => _job?.Dispose();
}
