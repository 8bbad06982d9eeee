// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/io/atomic_file.h>
#include <pdfem/io/history.h>

#include <algorithm>
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

    History::History(const std::string              &file,
                     const std::vector<std::string> &columns,
                     const bool                      active,
                     const std::size_t               rows)
      : n_columns(columns.size())
      , n_rows(rows)
      , columns(columns)
    {
      if (!active)
        return;
      std::ifstream            in(file);
      std::vector<std::string> lines;
      for (std::string line; lines.size() < rows + 1 && std::getline(in, line);)
        lines.push_back(line);
      std::string header;
      for (std::size_t c = 0; c < columns.size(); ++c)
        header += (c ? "," : "") + columns[c];
      if (lines.empty() || lines[0] != header)
        throw std::runtime_error(file + " is missing or has other columns "
                                        "than this run writes");
      if (lines.size() < rows + 1)
        throw std::runtime_error(
          file + " has " + std::to_string(lines.size() - 1) +
          " rows, fewer than the " + std::to_string(rows) +
          " the checkpoint was taken after");
      in.close();
      const std::string error = write_atomically(file, [&](std::ostream &o) {
        for (const auto &line : lines)
          o << line << '\n';
      });
      if (!error.empty())
        throw std::runtime_error(error);
      out.open(file, std::ios::app);
      if (!out)
        throw std::runtime_error("cannot write " + file);
    }

    bool
    History::add_row(const std::vector<double> &values)
    {
      ++n_rows; // on every rank, so that each one's checkpoint agrees
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
      // A point "(x, y[, z])" reads as at_x<x>_y<y>[_z<z>]: the coordinates
      // named, as the bare numbers (-0.5_-1.5) did not say what they were.
      if (name.size() > 2 && name.front() == '(' && name.back() == ')')
        {
          std::string       point = "at";
          std::size_t       from  = 1;
          const std::string axes  = "xyz";
          for (std::size_t axis = 0; axis < axes.size(); ++axis)
            {
              const std::size_t to =
                std::min(name.find(',', from), name.size() - 1);
              std::string value;
              for (std::size_t i = from; i < to; ++i)
                if (!std::isspace(static_cast<unsigned char>(name[i])))
                  value += name[i];
              point += std::string("_") + axes[axis] + value;
              if (to == name.size() - 1)
                return point;
              from = to + 1;
            }
        }
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
