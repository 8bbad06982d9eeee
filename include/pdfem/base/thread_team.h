// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_THREAD_TEAM_H
#define PDFEM_BASE_THREAD_TEAM_H

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace pdfem
{
  /**
   * A fixed team of threads for short parallel loops that follow each other
   * closely: the matrix-free product K x runs twice in every GMRES
   * iteration, 0.2–1 ms each, separated by a single-threaded ML V-cycle.
   *
   * TBB puts an idle worker to sleep within microseconds, and waking it
   * again is a futex system call. On the 2-core VM that wake-up took 8 % of
   * the plateCrack FC1 run (perf), and the product ran only 10 % faster on
   * two threads than on one. The helpers of this team instead keep polling
   * for the next job for a while after each one (first spinning, then
   * yielding the core to any other runnable thread), and only then sleep.
   *
   * run() hands the same job to every member, the caller included as member
   * 0, and returns once all have finished it. Jobs share their work through
   * their own atomic counters; which member takes which piece is free, so
   * results do not depend on the team when each piece is computed in a
   * fixed order.
   */
  class ThreadTeam
  {
  public:
    /// A team of @p size members: the calling thread and size - 1 helpers.
    explicit ThreadTeam(unsigned int size);

    ~ThreadTeam();

    ThreadTeam(const ThreadTeam &) = delete;
    ThreadTeam &
    operator=(const ThreadTeam &) = delete;

    /// The number of members, the caller included.
    unsigned int
    size() const;

    /**
     * Run job(member) on every member (the caller is member 0) and return
     * when all are done. An exception thrown by a helper's job is rethrown
     * here. Not reentrant: a job must not call run() of its own team.
     */
    void
    run(const std::function<void(unsigned int)> &job);

    /// The process's team, with deal.II's thread count (MultithreadInfo),
    /// made at the first call.
    static ThreadTeam &
    shared();

  private:
    void
    serve(unsigned int member);

    std::vector<std::thread>                 helpers;
    const std::function<void(unsigned int)> *job = nullptr;
    std::atomic<std::uint64_t>               generation{0};
    std::atomic<unsigned int>                busy{0};
    std::atomic<unsigned int>                sleeping{0};
    std::atomic<bool>                        stopping{false};
    std::mutex                               mutex;
    std::condition_variable                  wake_up;
    std::exception_ptr                       failure;
    std::mutex                               failure_mutex;
  };
  /// The number of cores this process may run on (its CPU affinity, e.g.
  /// as mpirun's binding set it), or the machine's when it cannot be read.
  unsigned int
  cores_allowed();

  /**
   * Never more threads than cores to run them on: when deal.II's thread
   * count (the machine's cores shared among the ranks on it, capped by
   * DEAL_II_NUM_THREADS) exceeds cores_allowed(), lower it to that and
   * return a note saying so and how to get the threads back; else "".
   *
   * Open MPI binds each rank to one core when it starts one or two ranks:
   * `mpirun -np 1` left two threads on one core, and ThreadTeam's polling
   * helper then took the core from the working thread (3D box, 55 539
   * DoFs: 5.82 s against 4.74 s unbound). Call it before the first
   * ThreadTeam::shared().
   */
  std::string
  fit_threads_to_cores();

} // namespace pdfem

#endif
