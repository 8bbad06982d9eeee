// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_DRIVERS_RESUME_H
#define PDFEM_DRIVERS_RESUME_H

#include <functional>

namespace pdfem
{
  class StateArchive;

  namespace Drivers
  {
    /// Puts a driver's state between two steps into an archive.
    using SaveState = std::function<void(StateArchive &)>;

    /**
     * How a driver loop takes part in checkpoint and restart
     * (doc/reliability.md): it starts from @p from when given (the state
     * it saved at the checkpoint) and calls @p boundary between two steps
     * with a function that saves its state; the host writes a checkpoint
     * there when one is due, and stops the run there on a signal.
     */
    struct Resume
    {
      /// The state to go on from (nullptr: the first step).
      const StateArchive *from = nullptr;
      /// Called before every step but the first one run.
      std::function<void(const SaveState &)> boundary;
    };
  } // namespace Drivers
} // namespace pdfem

#endif
