// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_JSON_WRITER_H
#define PDFEM_BASE_JSON_WRITER_H

#include <ostream>
#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    /**
     * A minimal streaming JSON writer for summary.json: objects, numbers
     * (full precision; non-finite values become null), strings and booleans,
     * keys in the order written.
     */
    class JsonWriter
    {
    public:
      explicit JsonWriter(std::ostream &out);
      ~JsonWriter();

      void
      begin_object(const std::string &key = "");
      void
      end_object();
      void
      value(const std::string &key, double v);
      void
      value(const std::string &key, unsigned long v);
      void
      value(const std::string &key, const std::string &v);
      void
      value(const std::string &key, const char *v);
      void
      value(const std::string &key, bool v);

      /// JSON string literal of @p s (quoted and escaped).
      static std::string
      quote(const std::string &s);

    private:
      void
      key(const std::string &k);

      std::ostream     &out;
      std::vector<bool> first; // per open object: no member written yet
    };
  } // namespace IO
} // namespace pdfem

#endif
