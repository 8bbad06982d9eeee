// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the drivers: the wall clock of their phase timings.
#ifndef PDFEM_SOURCE_DRIVERS_TIMING_H
#define PDFEM_SOURCE_DRIVERS_TIMING_H

#include <chrono>

namespace pdfem
{
  namespace Drivers
  {
    namespace internal
    {
      using clock = std::chrono::steady_clock;

      inline double
      seconds_since(const clock::time_point &start)
      {
        return std::chrono::duration<double>(clock::now() - start).count();
      }
    } // namespace internal
  }   // namespace Drivers
} // namespace pdfem

#endif
