// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_PROGRESS_PULSE_H
#define PDFEM_DRIVERS_PROGRESS_PULSE_H

#include <chrono>
#include <functional>
#include <string>

namespace pdfem
{
  namespace Drivers
  {
    /**
     * A line of progress from inside a long step (Newton iterations, the
     * states of a snap-back path, relaxation iterations), at most one per
     * `interval`, so that a run is never silent for long (issue 20: a line
     * at least every few seconds in every driver). The line is made only
     * when it is printed. Without a printer (no host, a quiet run) nothing
     * happens.
     */
    class ProgressPulse
    {
    public:
      using Printer = std::function<void(const std::string &)>;

      ProgressPulse() = default;

      /// Print through @p printer, at most once per @p interval seconds
      /// (0: every call), the first time @p interval after construction.
      explicit ProgressPulse(Printer printer, double interval = 5.)
        : printer(std::move(printer))
        , interval(interval)
        , last(std::chrono::steady_clock::now())
      {}

      /// Print make_line() if the interval has passed since the last line.
      void
      operator()(const std::function<std::string()> &make_line)
      {
        if (!printer)
          return;
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last).count() < interval)
          return;
        last = now;
        printer(make_line());
      }

      /// A step ended (its own line was printed): the interval starts anew.
      void
      restart()
      {
        last = std::chrono::steady_clock::now();
      }

    private:
      Printer                               printer;
      double                                interval = 5.;
      std::chrono::steady_clock::time_point last;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
