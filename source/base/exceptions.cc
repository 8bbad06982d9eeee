// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>

#include <sstream>

namespace pdfem
{
  namespace
  {
    std::string
    compose(const std::string &file,
            const std::string &parameter,
            const std::string &problem,
            const std::string &allowed)
    {
      std::string message = file.empty() ? "" : file + ": ";
      if (!parameter.empty())
        message += parameter + ": ";
      message += problem;
      if (!allowed.empty())
        message += " (allowed: " + allowed + ")";
      return message;
    }
  } // namespace

  InputError::InputError(const std::string &file,
                         const std::string &parameter,
                         const std::string &problem,
                         const std::string &allowed)
    : std::runtime_error(compose(file, parameter, problem, allowed))
    , file(file)
    , parameter(parameter)
  {}

  std::string
  number(const double value)
  {
    std::ostringstream s;
    s << value;
    return s.str();
  }

  RunFailure::RunFailure(const std::string &exit_state,
                         const std::string &details)
    : std::runtime_error(exit_state + ": " + details)
    , exit_state(exit_state)
  {}
} // namespace pdfem
