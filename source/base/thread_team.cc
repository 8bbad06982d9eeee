// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/thread_team.h>

#include <deal.II/base/multithread_info.h>

#include <algorithm>
#include <chrono>
#include <string>

#include <sched.h>

namespace pdfem
{
  namespace
  {
    /// How long a helper keeps polling for the next job: longer than the
    /// gap between two products of a GMRES solve (a V-cycle and the
    /// vector updates, about 1–2 ms on plateCrack).
    constexpr std::chrono::microseconds polling_time(5000);

    /// Polls between two looks at the clock, and the polls that spin
    /// before a waiting thread starts to yield its core.
    constexpr unsigned int polls_per_clock_check = 64;
    constexpr unsigned int spinning_polls        = 2048;

    /// One poll of a wait: the first ones spin on the core, later ones
    /// yield it to any other runnable thread (oversubscribed machines).
    inline void
    wait_a_moment(const unsigned int polls_so_far)
    {
      if (polls_so_far < spinning_polls)
        {
#if defined(__x86_64__) || defined(__i386__)
          __builtin_ia32_pause();
#endif
        }
      else
        std::this_thread::yield();
    }
  } // namespace

  ThreadTeam::ThreadTeam(const unsigned int size)
  {
    for (unsigned int member = 1; member < size; ++member)
      helpers.emplace_back([this, member] { serve(member); });
  }

  ThreadTeam::~ThreadTeam()
  {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping = true;
    }
    wake_up.notify_all();
    for (auto &helper : helpers)
      helper.join();
  }

  unsigned int
  ThreadTeam::size() const
  {
    return helpers.size() + 1;
  }

  ThreadTeam &
  ThreadTeam::shared()
  {
    static ThreadTeam team(dealii::MultithreadInfo::n_threads());
    return team;
  }

  void
  ThreadTeam::run(const std::function<void(unsigned int)> &work)
  {
    if (helpers.empty())
      {
        work(0);
        return;
      }
    job = &work;
    busy.store(helpers.size());
    // A helper that is about to sleep has counted itself in `sleeping`
    // under the mutex before it looks at the generation again (all
    // sequentially consistent), so either it sees the new generation or
    // this sees it sleeping and wakes it under the same mutex.
    generation.fetch_add(1);
    if (sleeping.load() > 0)
      {
        std::lock_guard<std::mutex> lock(mutex);
        wake_up.notify_all();
      }
    std::exception_ptr own_failure;
    try
      {
        work(0);
      }
    catch (...)
      {
        own_failure = std::current_exception();
      }
    for (unsigned int polls = 0; busy.load() != 0; ++polls)
      wait_a_moment(polls);
    job = nullptr;
    std::exception_ptr helper_failure;
    std::swap(helper_failure, failure);
    if (own_failure)
      std::rethrow_exception(own_failure);
    if (helper_failure)
      std::rethrow_exception(helper_failure);
  }

  void
  ThreadTeam::serve(const unsigned int member)
  {
    std::uint64_t seen = 0;
    for (;;)
      {
        const auto   start = std::chrono::steady_clock::now();
        unsigned int polls = 0;
        while (generation.load() == seen)
          {
            if (stopping.load())
              return;
            wait_a_moment(polls++);
            if (polls % polls_per_clock_check == 0 &&
                std::chrono::steady_clock::now() - start > polling_time)
              {
                std::unique_lock<std::mutex> lock(mutex);
                ++sleeping;
                wake_up.wait(lock, [&] {
                  return generation.load() != seen || stopping.load();
                });
                --sleeping;
                polls = 0;
              }
          }
        seen = generation.load();
        try
          {
            (*job)(member);
          }
        catch (...)
          {
            std::lock_guard<std::mutex> lock(failure_mutex);
            if (!failure)
              failure = std::current_exception();
          }
        busy.fetch_sub(1);
      }
  }

  unsigned int
  cores_allowed()
  {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0)
      return static_cast<unsigned int>(CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
  }

  std::string
  fit_threads_to_cores()
  {
    const unsigned int threads = dealii::MultithreadInfo::n_threads();
    const unsigned int cores   = cores_allowed();
    if (threads <= cores)
      return "";
    dealii::MultithreadInfo::set_thread_limit(cores);
    const std::string s = cores == 1 ? "" : "s";
    return "this process may run on " + std::to_string(cores) + " core" + s +
           " only (its CPU affinity: mpirun binds each rank to a core by "
           "default when it starts one or two ranks), so it uses " +
           std::to_string(cores) + " thread" + s + " instead of " +
           std::to_string(threads) + "; 'mpirun --bind-to none' lets it use " +
           std::to_string(threads);
  }
} // namespace pdfem
