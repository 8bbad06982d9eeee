// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_EXCEPTIONS_H
#define PDFEM_BASE_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace pdfem
{
  /**
   * Bad input: a missing file, an unknown or out-of-range parameter, a mesh
   * without a named boundary... Thrown before any work is done. The message
   * names the file, the parameter, what is wrong and what is allowed, e.g.
   *
   *   scene.prm: Material/Poisson's ratio = 0.6: out of range for plane
   *   strain (allowed: -1 < nu < 0.5)
   *
   * Applications print what() as one line and exit with status 2.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &file,
               const std::string &parameter,
               const std::string &problem,
               const std::string &allowed = "");

    /// The file the bad input came from (may be empty).
    const std::string file;
    /// The parameter (or keyword, or line) that is wrong.
    const std::string parameter;
  };

  /**
   * A failure during a run that is reported in summary.json as the exit
   * state (e.g. "singular matrix", "diverged") instead of crashing.
   */
  /// A number as a person writes it in a message: 2.5, 7e+10, -1.
  std::string
  number(double value);

  class RunFailure : public std::runtime_error
  {
  public:
    RunFailure(const std::string &exit_state, const std::string &details);

    /// The short machine-readable state written to summary.json.
    const std::string exit_state;
  };
} // namespace pdfem

#endif
