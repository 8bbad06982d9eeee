// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_PARAMETER_TOOLS_H
#define PDFEM_BASE_PARAMETER_TOOLS_H

#include <array>
#include <string>
#include <vector>

namespace pdfem
{
  /**
   * Small helpers for reading parameter values, shared by every module that
   * declares and parses its own parameters. Each throws InputError naming
   * @p file and @p parameter where a value cannot be read.
   */
  namespace ParameterTools
  {
    /// @p s without leading and trailing white space.
    std::string
    trim(const std::string &s);

    /// The non-empty, trimmed parts of @p s between @p delimiter.
    std::vector<std::string>
    split(const std::string &s, char delimiter);

    /// Check that a muparser expression of x, y, z, t parses.
    void
    check_expression(const std::string &expression,
                     const std::string &file,
                     const std::string &parameter);

    /// A point "(x, y)" in 2D or "(x, y, z)" in 3D (z = 0 in 2D).
    std::array<double, 3>
    parse_point(const std::string &text,
                const std::string &file,
                const std::string &parameter,
                int                dim);

    /// Is all of @p text one finite number? Then it is in @p value.
    bool
    parse_number(const std::string &text, double &value);

    /// A deal.II parameter-parsing exception's text as one clear line.
    std::string
    clean_dealii_message(const std::string &what);
  } // namespace ParameterTools
} // namespace pdfem

#endif
