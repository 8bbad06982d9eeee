// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>

#include <deal.II/base/function_parser.h>

#include <cmath>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

namespace pdfem
{
  namespace ParameterTools
  {
    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r\n");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t\r\n");
      return s.substr(b, e - b + 1);
    }

    std::vector<std::string>
    split(const std::string &s, const char delimiter)
    {
      std::vector<std::string> parts;
      std::stringstream        in(s);
      std::string              part;
      while (std::getline(in, part, delimiter))
        if (!trim(part).empty())
          parts.push_back(trim(part));
      return parts;
    }

    /// Check that a muparser expression of x, y, z, t parses.
    void
    check_expression(const std::string &expression,
                     const std::string &file,
                     const std::string &parameter)
    {
      // deal.II prints muparser's five-line report to std::cerr before it
      // throws: silenced here, the one-line message below says it.
      std::ostringstream muparser_report;
      std::streambuf    *cerr_buffer = std::cerr.rdbuf(muparser_report.rdbuf());
      try
        {
          dealii::FunctionParser<3> f(1);
          f.initialize("x,y,z,t",
                       expression,
                       std::map<std::string, double>(),
                       true);
          (void)f.value(dealii::Point<3>());
          std::cerr.rdbuf(cerr_buffer);
        }
      catch (...)
        {
          std::cerr.rdbuf(cerr_buffer);
          throw InputError(file,
                           parameter,
                           "cannot parse the expression '" + expression + "'",
                           "a muparser expression of x, y, z and t");
        }
    }

    bool
    parse_number(const std::string &text, double &value)
    {
      std::size_t end = 0;
      try
        {
          value = std::stod(text, &end);
        }
      catch (...)
        {
          return false;
        }
      return !text.empty() && end == text.size() && std::isfinite(value);
    }

    std::array<double, 3>
    parse_point(const std::string &text,
                const std::string &file,
                const std::string &parameter,
                const int          dim)
    {
      std::string s = trim(text);
      if (s.size() < 2 || s.front() != '(' || s.back() != ')')
        throw InputError(file,
                         parameter,
                         "cannot read the point '" + text + "'",
                         "(x, y) in 2D, (x, y, z) in 3D");
      const auto            parts = split(s.substr(1, s.size() - 2), ',');
      std::array<double, 3> p{{0., 0., 0.}};
      if (static_cast<int>(parts.size()) != dim)
        throw InputError(file,
                         parameter,
                         "the point '" + text + "' does not have " +
                           std::to_string(dim) + " coordinates",
                         "(x, y) in 2D, (x, y, z) in 3D");
      for (int d = 0; d < dim; ++d)
        try
          {
            std::size_t used = 0;
            p[d]             = std::stod(parts[d], &used);
            if (used != parts[d].size())
              throw std::invalid_argument("trailing");
          }
        catch (...)
          {
            throw InputError(file,
                             parameter,
                             "'" + parts[d] + "' is not a number",
                             "(x, y) in 2D, (x, y, z) in 3D");
          }
      return p;
    }

    /// Turn a deal.II parameter-parsing exception into one clear line.
    std::string
    clean_dealii_message(const std::string &what)
    {
      // The text after @p key up to the stack trace, on one line.
      const auto part = [&](const std::string &key) {
        const auto  pos = what.find(key);
        std::string msg =
          pos == std::string::npos ? what : what.substr(pos + key.size());
        // deal.II appends the stack trace of where it threw: not for users.
        const auto trace = msg.find("Stacktrace:");
        if (trace != std::string::npos)
          msg.erase(trace);
        const auto info = msg.find("Additional information:");
        if (info != std::string::npos)
          msg.erase(info);
        msg = std::regex_replace(msg, std::regex("-{5,}"), "");
        msg = std::regex_replace(msg, std::regex("\\s+"), " ");
        return trim(msg);
      };
      // The explanation, or else the condition that failed (an Amesos
      // failure has no explanation).
      std::string msg = part("Additional information:");
      if (msg.empty() &&
          what.find("The violated condition was:") != std::string::npos)
        msg = part("The violated condition was:");
      return msg;
    }
  } // namespace ParameterTools
} // namespace pdfem
