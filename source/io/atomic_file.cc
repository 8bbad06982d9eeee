// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/io/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace pdfem
{
  namespace IO
  {
    std::string
    write_atomically(const std::string                         &file,
                     const std::function<void(std::ostream &)> &write)
    {
      const std::string temporary = file + ".tmp";
      std::string       error;
      {
        std::ofstream out(temporary);
        if (!out)
          return "cannot create " + temporary + ": " + std::strerror(errno);
        write(out);
        out.flush();
        if (!out)
          error = "writing " + temporary + " failed: " + std::strerror(errno);
        out.close();
        if (error.empty() && out.fail())
          error = "closing " + temporary + " failed: " + std::strerror(errno);
      }
      if (error.empty() && std::rename(temporary.c_str(), file.c_str()) != 0)
        error = "renaming " + temporary + " to " + file +
                " failed: " + std::strerror(errno);
      if (!error.empty())
        std::remove(temporary.c_str());
      return error;
    }
  } // namespace IO
} // namespace pdfem
