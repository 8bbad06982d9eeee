// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/interrupts.h>

#include <csignal>

namespace pdfem
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    remember_signal(const int s)
    {
      received = s;
      // The next one of this kind takes the default action.
      std::signal(s, SIG_DFL);
    }
  } // namespace

  struct StopOnSignals::Saved
  {
    void (*interrupt)(int);
    void (*terminate)(int);
  };

  StopOnSignals::StopOnSignals()
    : saved(new Saved)
  {
    received         = 0;
    saved->interrupt = std::signal(SIGINT, remember_signal);
    saved->terminate = std::signal(SIGTERM, remember_signal);
  }

  StopOnSignals::~StopOnSignals()
  {
    std::signal(SIGINT, saved->interrupt);
    std::signal(SIGTERM, saved->terminate);
    delete saved;
  }

  int
  StopOnSignals::stop_requested(MPI_Comm comm)
  {
    int local = received, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, comm);
    return global;
  }

  const char *
  StopOnSignals::name(const int s)
  {
    return s == SIGINT ? "SIGINT" : s == SIGTERM ? "SIGTERM" : "a signal";
  }
} // namespace pdfem
