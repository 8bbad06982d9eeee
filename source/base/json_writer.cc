// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/json_writer.h>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>

namespace pdfem
{
  namespace IO
  {
    JsonWriter::JsonWriter(std::ostream &out)
      : out(out)
    {}

    JsonWriter::~JsonWriter()
    {
      while (!first.empty())
        end_object();
      out << "\n";
    }

    std::string
    JsonWriter::quote(const std::string &s)
    {
      std::string q = "\"";
      for (const char c : s)
        switch (c)
          {
            case '"':
              q += "\\\"";
              break;
            case '\\':
              q += "\\\\";
              break;
            case '\n':
              q += "\\n";
              break;
            case '\t':
              q += "\\t";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char buffer[8];
                  std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
                  q += buffer;
                }
              else
                q += c;
          }
      return q + "\"";
    }

    void
    JsonWriter::key(const std::string &k)
    {
      if (first.empty())
        return;
      out << (first.back() ? "\n" : ",\n")
          << std::string(2 * first.size(), ' ');
      first.back() = false;
      out << quote(k) << ": ";
    }

    void
    JsonWriter::begin_object(const std::string &k)
    {
      key(k);
      out << "{";
      first.push_back(true);
    }

    void
    JsonWriter::end_object()
    {
      const bool empty = first.back();
      first.pop_back();
      if (!empty)
        out << "\n" << std::string(2 * first.size(), ' ');
      out << "}";
    }

    void
    JsonWriter::value(const std::string &k, const double v)
    {
      key(k);
      if (std::isfinite(v))
        out << std::setprecision(std::numeric_limits<double>::max_digits10)
            << v;
      else
        out << "null";
    }

    void
    JsonWriter::value(const std::string &k, const unsigned long v)
    {
      key(k);
      out << v;
    }

    void
    JsonWriter::value(const std::string &k, const std::string &v)
    {
      key(k);
      out << quote(v);
    }

    void
    JsonWriter::value(const std::string &k, const char *v)
    {
      value(k, std::string(v));
    }

    void
    JsonWriter::value(const std::string &k, const bool v)
    {
      key(k);
      out << (v ? "true" : "false");
    }
  } // namespace IO
} // namespace pdfem
