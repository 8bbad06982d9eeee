// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/io/history.h>

#include <cctype>
#include <iomanip>
#include <limits>
#include <stdexcept>

namespace pdfem
{
  namespace IO
  {
    History::History(const std::string              &file,
                     const std::vector<std::string> &columns,
                     const bool                      active)
      : n_columns(columns.size())
      , columns(columns)
    {
      if (!active)
        return;
      out.open(file);
      if (!out)
        throw std::runtime_error("cannot write " + file);
      for (std::size_t c = 0; c < columns.size(); ++c)
        out << (c ? "," : "") << columns[c];
      out << std::endl;
    }

    bool
    History::add_row(const std::vector<double> &values)
    {
      if (!out.is_open())
        return true;
      out << std::setprecision(std::numeric_limits<double>::max_digits10);
      for (std::size_t c = 0; c < values.size() && c < n_columns; ++c)
        out << (c ? "," : "") << values[c];
      out << std::endl;
      return static_cast<bool>(out);
    }

    std::string
    History::column_name(const std::string &name)
    {
      std::string s;
      for (const char c : name)
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-')
          s += c;
        else if (!s.empty() && s.back() != '_')
          s += '_';
      while (!s.empty() && s.back() == '_')
        s.pop_back();
      return s;
    }
  } // namespace IO
} // namespace pdfem
