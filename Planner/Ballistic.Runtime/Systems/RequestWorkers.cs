using Ballistic.Runtime.Agents;

namespace Ballistic.Runtime.Systems;

/// <summary>
/// A world's background threads for path requests (<see cref="Core.WorldSettings.AnimationThreads"/> of them, made
/// when the first job is queued): each takes the oldest queued job and runs it unless the tick thread claimed it first
/// (<see cref="RequestJob.RunInBackground"/>). Queuing a job, running it and waiting for it allocate nothing once the
/// queue has grown, where a task per request allocated on the tick thread. Queue and wait on one thread (the tick's);
/// the threads stop, finishing the jobs they are running, on <see cref="Dispose"/>.
/// </summary>
internal sealed class RequestWorkers(int count) : IDisposable
{
    private readonly Queue<RequestJob> _queue = new();
    private readonly object _work = new();
    private readonly object _done = new();
    private Thread[]? _threads;
    private bool _stopping;

    /// <summary>Queues <paramref name="job"/> (begun) for the next free thread.</summary>
    public void Enqueue(RequestJob job)
    {
        _threads ??= Started();
        lock (_work)
        {
            _queue.Enqueue(job);
            Monitor.Pulse(_work);
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

    private Thread[] Started()
    {
        var threads = new Thread[count];
        for (int i = 0; i < count; i++)
        {
            threads[i] = new Thread(Work) { IsBackground = true, Name = $"Ballistic path requests {i + 1}" };
            threads[i].Start();
        }

        return threads;
    }

    private void Work()
    {
        while (true)
        {
            RequestJob job;
            lock (_work)
            {
                while (_queue.Count == 0 && !_stopping)
                {
                    Monitor.Wait(_work);
                }

                if (_stopping)
                {
                    return;
                }

                job = _queue.Dequeue();
            }

            if (job.RunInBackground())
            {
                lock (_done)
                {
                    Monitor.PulseAll(_done);
                }
            }
        }
    }

    /// <summary>Stops the threads: the jobs still queued are not run; those running are finished first.</summary>
    public void Dispose()
    {
        lock (_work)
        {
            _stopping = true;
            Monitor.PulseAll(_work);
        }

        foreach (Thread thread in _threads ?? [])
        {
            thread.Join();
        }
    }
}
