// SPDX-License-Identifier: LGPL-2.1-or-later
// Drivers::ProgressPulse: a line at most once per interval, made only when
// it is printed, nothing without a printer.
#include <pdfem/drivers/progress_pulse.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace
{
  using pdfem::Drivers::ProgressPulse;

  TEST(ProgressPulse, PrintsAtMostOncePerInterval)
  {
    std::vector<std::string> lines;
    unsigned int             made = 0;
    const auto               line = [&made]() {
      ++made;
      return std::string("line ") + std::to_string(made);
    };

    // Interval 0: every call prints.
    ProgressPulse every([&lines](const std::string &l) { lines.push_back(l); },
                        0.);
    every(line);
    every(line);
    EXPECT_EQ(lines, (std::vector<std::string>{"line 1", "line 2"}));

    // A long interval: nothing before it has passed, and the line is not
    // even made.
    lines.clear();
    made = 0;
    ProgressPulse rarely([&lines](const std::string &l) { lines.push_back(l); },
                         3600.);
    for (unsigned int i = 0; i < 100; ++i)
      rarely(line);
    EXPECT_TRUE(lines.empty());
    EXPECT_EQ(made, 0u);
  }

  TEST(ProgressPulse, SilentWithoutAPrinter)
  {
    unsigned int  made = 0;
    ProgressPulse none;
    none([&made]() {
      ++made;
      return std::string();
    });
    EXPECT_EQ(made, 0u);
  }
} // namespace
