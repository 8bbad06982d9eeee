// SPDX-License-Identifier: LGPL-2.1-or-later
// The nearest plugin name, for "did you mean" in messages.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/plugins.h>

#include <algorithm>
#include <cctype>

namespace pdfem
{
  namespace Plugins
  {
    namespace
    {
      std::string
      lower(std::string s)
      {
        for (auto &c : s)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
      }

      /// Levenshtein distance.
      std::size_t
      distance(const std::string &a, const std::string &b)
      {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j)
          row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i)
          {
            std::size_t diagonal = row[0];
            row[0]               = i;
            for (std::size_t j = 1; j <= b.size(); ++j)
              {
                const std::size_t up = row[j];
                row[j]               = std::min({row[j] + 1,
                                                 row[j - 1] + 1,
                                                 diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
                diagonal             = up;
              }
          }
        return row[b.size()];
      }
    } // namespace

    std::string
    nearest_name(const std::string              &name,
                 const std::vector<std::string> &candidates)
    {
      std::string best;
      std::size_t best_distance = std::string::npos;
      for (const auto &c : candidates)
        {
          const std::size_t d = distance(lower(name), lower(c));
          if (d < best_distance)
            {
              best          = c;
              best_distance = d;
            }
        }
      // Close: at most a third of the letters differ.
      return best_distance <= std::max<std::size_t>(1, best.size() / 3) ? best :
                                                                          "";
    }

    void
    throw_unknown(const std::string              &name,
                  const std::vector<std::string> &candidates,
                  const std::string              &file,
                  const std::string              &parameter,
                  const std::string              &what,
                  const std::string              &allowed)
    {
      const std::string near = nearest_name(name, candidates);
      throw InputError(file,
                       parameter,
                       "unknown " + what + " '" + name + "'" +
                         (near.empty() ? "" :
                                         " (did you mean '" + near + "'?)"),
                       allowed);
    }
  } // namespace Plugins
} // namespace pdfem
