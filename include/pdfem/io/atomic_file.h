// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_ATOMIC_FILE_H
#define PDFEM_IO_ATOMIC_FILE_H

#include <functional>
#include <ostream>
#include <string>

namespace pdfem
{
  namespace IO
  {
    /**
     * Write @p file through @p write into `file.tmp`, check that every byte
     * reached the disk (stream state after flush and close), then rename it
     * to @p file: a reader sees the old file or the whole new one, never a
     * truncated one. Returns an empty string, or why it failed (the
     * temporary file is removed then).
     */
    std::string
    write_atomically(const std::string                         &file,
                     const std::function<void(std::ostream &)> &write);
  } // namespace IO
} // namespace pdfem

#endif
