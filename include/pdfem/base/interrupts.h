// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_INTERRUPTS_H
#define PDFEM_BASE_INTERRUPTS_H

#include <mpi.h>

namespace pdfem
{
  /**
   * SIGINT and SIGTERM during a run: while a StopOnSignals object lives,
   * those signals only set a flag (the previous handlers are restored when
   * it goes out of scope), and the run asks stop_requested() after each
   * completed step, so that it ends with its outputs written and the exit
   * state `interrupted` instead of being killed mid-write. A second signal
   * of the same kind ends the process at once (the default action).
   */
  class StopOnSignals
  {
  public:
    StopOnSignals();
    ~StopOnSignals();
    StopOnSignals(const StopOnSignals &) = delete;
    StopOnSignals &
    operator=(const StopOnSignals &) = delete;

    /// The signal received on any rank of @p comm (0: none). Collective.
    static int
    stop_requested(MPI_Comm comm);

    /// The name of signal @p s ("SIGINT", "SIGTERM").
    static const char *
    name(int s);

  private:
    struct Saved;
    Saved *saved;
  };
} // namespace pdfem

#endif
