// SPDX-License-Identifier: LGPL-2.1-or-later
// ThreadTeam: every member runs each job once, work shared through an atomic
// counter is done exactly once, helpers that fell asleep are woken, and an
// exception thrown on a helper reaches the caller.
#include <pdfem/base/thread_team.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace
{
  using pdfem::ThreadTeam;

  TEST(ThreadTeam, EveryMemberRunsEachJobOnce)
  {
    for (const unsigned int size : {1u, 2u, 3u})
      {
        ThreadTeam team(size);
        EXPECT_EQ(team.size(), size);
        for (int round = 0; round < 200; ++round)
          {
            std::vector<std::atomic<int>> calls(size);
            team.run([&](const unsigned int member) { ++calls.at(member); });
            for (unsigned int m = 0; m < size; ++m)
              ASSERT_EQ(calls[m].load(), 1) << "member " << m;
          }
      }
  }

  TEST(ThreadTeam, SharedWorkIsDoneOnceAndHelpersWakeFromSleep)
  {
    ThreadTeam               team(2);
    std::vector<std::size_t> done(10000);
    for (int round = 1; round <= 3; ++round)
      {
        std::atomic<std::size_t> next{0};
        team.run([&](unsigned int) {
          for (std::size_t i = next++; i < done.size(); i = next++)
            done[i] += i;
        });
        // Longer than the helpers poll: the next run has to wake them.
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        for (std::size_t i = 0; i < done.size(); ++i)
          ASSERT_EQ(done[i], round * i) << "entry " << i;
      }
  }

  TEST(ThreadTeam, HelperExceptionReachesTheCaller)
  {
    ThreadTeam team(2);
    EXPECT_THROW(team.run([](const unsigned int member) {
      if (member == 1)
        throw std::runtime_error("helper failed");
    }),
                 std::runtime_error);
    EXPECT_THROW(team.run([](const unsigned int member) {
      if (member == 0)
        throw std::logic_error("caller failed");
    }),
                 std::logic_error);
    // The team stays usable.
    std::atomic<int> calls{0};
    team.run([&](unsigned int) { ++calls; });
    EXPECT_EQ(calls.load(), 2);
  }
} // namespace
