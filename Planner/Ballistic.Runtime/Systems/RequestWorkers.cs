using Ballistic.Runtime.Agents;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// A world's background work on path requests, at most <see cref="Core.WorldSettings.AnimationThreads"/> jobs at once
/// on the .NET thread pool: a queue of begun jobs, drained by as many reusable work items as that, each taking the
/// oldest queued job and running it unless the tick thread claimed it first (<see cref="RequestJob.RunInBackground"/>).
/// Queuing a job, running it and waiting for it allocate nothing once the queue has grown, where a task per request
/// allocated on the tick thread. Queue and wait on one thread (the tick's); <see cref="Dispose"/> lets the running jobs
/// finish and runs no queued one.
/// </summary>
internal sealed class RequestWorkers : IDisposable
{
    private readonly Queue<RequestJob> _queue = new();
    private readonly Stack<Drainer> _idle = new();
    private readonly int _count;
    private readonly object _gate = new();
    private readonly object _done = new();
    private bool _stopping;

    /// <summary>Work on at most <paramref name="count"/> jobs at once.</summary>
    public RequestWorkers(int count)
    {
        _count = count;
        for (int i = 0; i < count; i++)
        {
            _idle.Push(new Drainer(this));
        }
    }

    /// <summary>Queues <paramref name="job"/> (begun) for the next free work item, and sends one to the thread pool when one is idle.</summary>
    public void Enqueue(RequestJob job)
    {
        Drainer? idle = null;
        lock (_gate)
        {
            _queue.Enqueue(job);
            if (!_stopping && _idle.Count > 0)
            {
                idle = _idle.Pop();
            }
        }

        if (idle is not null)
        {
            ThreadPool.UnsafeQueueUserWorkItem(idle, preferLocal: false);
        }
    }

    /// <summary>
    /// Waits until a background thread has run <paramref name="job"/> to its end (<see cref="RequestJob.Ended"/>), at most
    /// <paramref name="limit"/> (<c>null</c>: however long); true when it has. Only for a job a background thread has
    /// claimed or will claim: one the caller claimed itself never ends here.
    /// </summary>
    public bool WaitFor(RequestJob job, TimeSpan? limit)
    {
        if (job.Ended)
        {
            return true;
        }

        long began = System.Diagnostics.Stopwatch.GetTimestamp();
        lock (_done)
        {
            while (!job.Ended)
            {
                if (limit is not { } most)
                {
                    Monitor.Wait(_done);
                    continue;
                }

                TimeSpan left = most - System.Diagnostics.Stopwatch.GetElapsedTime(began);
                if (left <= TimeSpan.Zero)
                {
                    return false;
                }

                Monitor.Wait(_done, left);
            }
        }

        return true;
    }

    /// <summary>Runs no more queued jobs and waits until those running have ended.</summary>
    public void Dispose()
    {
        lock (_gate)
        {
            _stopping = true;
            while (_idle.Count < _count)
            {
                Monitor.Wait(_gate);
            }
        }
    }

    /// <summary>One of the work items: on a pool thread, runs queued jobs one after the other until none is left (or the work stops), then goes idle.</summary>
    private sealed class Drainer(RequestWorkers workers) : IThreadPoolWorkItem
    {
        public void Execute()
        {
            while (true)
            {
                RequestJob job;
                lock (workers._gate)
                {
                    if (workers._stopping || workers._queue.Count == 0)
                    {
                        workers._idle.Push(this);
                        Monitor.PulseAll(workers._gate);
                        return;
                    }

                    job = workers._queue.Dequeue();
                }

                if (job.RunInBackground())
                {
                    lock (workers._done)
                    {
                        Monitor.PulseAll(workers._done);
                    }
                }
            }
        }
    }
}
