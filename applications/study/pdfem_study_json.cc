// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-study: a small strict JSON reader, enough for pdfem's summary.json
// (objects, arrays, numbers, strings with escapes, true, false, null).
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "pdfem_study.h"

namespace pdfem_study
{
  namespace
  {
    /// Recursive descent over the text; every fault names its offset.
    class Parser
    {
    public:
      explicit Parser(const std::string &text)
        : t(text)
      {}

      Json
      document()
      {
        Json v = value(0);
        space();
        if (i != t.size())
          fail("text after the end of the document");
        return v;
      }

    private:
      const std::string &t;
      std::size_t        i = 0;

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw std::runtime_error("JSON: " + what + " at offset " +
                                 std::to_string(i));
      }

      void
      space()
      {
        while (i < t.size() &&
               (t[i] == ' ' || t[i] == '\n' || t[i] == '\r' || t[i] == '\t'))
          ++i;
      }

      void
      expect(char c)
      {
        space();
        if (i >= t.size() || t[i] != c)
          fail(std::string("expected '") + c + "'");
        ++i;
      }

      bool
      word(const char *w)
      {
        const std::string s(w);
        if (t.compare(i, s.size(), s) != 0)
          return false;
        i += s.size();
        return true;
      }

      /// A code point as UTF-8.
      static void
      append_utf8(std::string &out, unsigned long c)
      {
        if (c < 0x80)
          out += static_cast<char>(c);
        else if (c < 0x800)
          {
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
          }
        else
          {
            out += static_cast<char>(0xE0 | (c >> 12));
            out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (c & 0x3F));
          }
      }

      std::string
      string()
      {
        expect('"');
        std::string out;
        while (true)
          {
            if (i >= t.size())
              fail("unterminated string");
            const char c = t[i++];
            if (c == '"')
              return out;
            if (c != '\\')
              {
                out += c;
                continue;
              }
            if (i >= t.size())
              fail("unterminated escape");
            const char e = t[i++];
            switch (e)
              {
                case '"':
                case '\\':
                case '/':
                  out += e;
                  break;
                case 'b':
                  out += '\b';
                  break;
                case 'f':
                  out += '\f';
                  break;
                case 'n':
                  out += '\n';
                  break;
                case 'r':
                  out += '\r';
                  break;
                case 't':
                  out += '\t';
                  break;
                case 'u':
                  {
                    if (i + 4 > t.size())
                      fail("short \\u escape");
                    char               *end = nullptr;
                    const std::string   hex = t.substr(i, 4);
                    const unsigned long c = std::strtoul(hex.c_str(), &end, 16);
                    if (*end != '\0')
                      fail("bad \\u escape");
                    append_utf8(out, c);
                    i += 4;
                    break;
                  }
                default:
                  fail(std::string("unknown escape '\\") + e + "'");
              }
          }
      }

      Json
      value(int depth)
      {
        if (depth > 64)
          fail("nesting deeper than 64");
        space();
        if (i >= t.size())
          fail("unexpected end");
        Json       v;
        const char c = t[i];
        if (c == '{')
          {
            v.kind = Json::object;
            ++i;
            space();
            if (i < t.size() && t[i] == '}')
              {
                ++i;
                return v;
              }
            while (true)
              {
                std::string key = string();
                expect(':');
                v.members.emplace_back(std::move(key), value(depth + 1));
                space();
                if (i < t.size() && t[i] == ',')
                  ++i;
                else
                  {
                    expect('}');
                    return v;
                  }
              }
          }
        if (c == '[')
          {
            v.kind = Json::array;
            ++i;
            space();
            if (i < t.size() && t[i] == ']')
              {
                ++i;
                return v;
              }
            while (true)
              {
                v.elements.push_back(value(depth + 1));
                space();
                if (i < t.size() && t[i] == ',')
                  ++i;
                else
                  {
                    expect(']');
                    return v;
                  }
              }
          }
        if (c == '"')
          {
            v.kind = Json::string;
            v.text = string();
            return v;
          }
        if (word("true") || word("false"))
          {
            v.kind = Json::boolean;
            v.x    = t[i - 2] == 'u' ? 1. : 0.; // tr(u)e, fal(s)e
            return v;
          }
        if (word("null"))
          return v;
        // A number: JSON's grammar, read by strtod.
        const std::size_t start = i;
        if (t[i] == '-')
          ++i;
        if (i >= t.size() || !std::isdigit(static_cast<unsigned char>(t[i])))
          fail("expected a value");
        while (i < t.size() &&
               (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '.' ||
                t[i] == 'e' || t[i] == 'E' || t[i] == '+' || t[i] == '-'))
          ++i;
        const std::string number = t.substr(start, i - start);
        char             *end    = nullptr;
        v.kind                   = Json::number;
        v.x                      = std::strtod(number.c_str(), &end);
        if (*end != '\0')
          {
            i = start;
            fail("malformed number '" + number + "'");
          }
        return v;
      }
    };
  } // namespace

  Json
  Json::parse(const std::string &text)
  {
    return Parser(text).document();
  }

  Json
  Json::read(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw std::runtime_error("cannot read " + file);
    std::ostringstream s;
    s << in.rdbuf();
    try
      {
        return parse(s.str());
      }
    catch (const std::runtime_error &e)
      {
        throw std::runtime_error(file + ": " + e.what());
      }
  }

  const Json *
  Json::find(const std::string &key) const
  {
    const Json *v     = this;
    std::size_t start = 0;
    while (v != nullptr && start <= key.size())
      {
        const auto        dot  = key.find('.', start);
        const std::string part = key.substr(start, dot - start);
        const Json       *next = nullptr;
        if (v->kind == object)
          {
            for (const auto &[name, member] : v->members)
              if (name == part)
                next = &member;
          }
        else if (v->kind == array && !part.empty() &&
                 part.find_first_not_of("0123456789") == std::string::npos)
          {
            const std::size_t k = std::stoul(part);
            if (k < v->elements.size())
              next = &v->elements[k];
          }
        v = next;
        if (dot == std::string::npos)
          return v;
        start = dot + 1;
      }
    return nullptr;
  }

  double
  Json::number_at(const std::string &key) const
  {
    const Json *v = find(key);
    return v != nullptr && v->kind == number ? v->x : missing;
  }

  std::vector<std::string>
  Json::number_keys(const std::string &prefix) const
  {
    std::vector<std::string> out;
    const std::string        dot = prefix.empty() ? "" : prefix + ".";
    if (kind == number)
      out.push_back(prefix);
    for (const auto &[name, member] : members)
      for (auto &k : member.number_keys(dot + name))
        out.push_back(std::move(k));
    for (std::size_t k = 0; k < elements.size(); ++k)
      for (auto &key : elements[k].number_keys(dot + std::to_string(k)))
        out.push_back(std::move(key));
    return out;
  }
} // namespace pdfem_study
