// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem_check: numeric checks on pdfem's outputs for the test suite (no
// deal.II, so it compiles in a second).
//
//   pdfem_check value  summary.json KEY EXPECTED rel|abs TOL
//       KEY is a dotted path (final.max_displacement.x); passes if
//       |v - e| <= TOL |e| (rel) or |v - e| <= TOL (abs).
//   pdfem_check string summary.json KEY EXPECTED
//   pdfem_check get    summary.json KEY        (prints the value)
//   pdfem_check bound  summary.json KEY >|< BOUND
//   pdfem_check nondecreasing history.csv COLUMN
//       passes if the column never decreases from one row to the next.
//   pdfem_check csv    a.csv b.csv TOL [SKIP,...]
//       same header and rows; every column agrees to TOL relative to the
//       largest magnitude among the columns of its quantity (same first
//       letter); the columns named in SKIP (comma-separated) are not
//       compared.
//   pdfem_check summaries a.json b.json TOL
//       two summary.json files of one scene run from two inputs: the same
//       members, equal strings and booleans, and numbers that agree to TOL
//       relative to the largest magnitude among the numbers of their object
//       (as csv does per quantity); the run-dependent members (timings,
//       peak_memory_mb_rank0, input_file, message, linear_solver.choice)
//       are skipped.
//   pdfem_check fields a.csv b.csv l2|max COLUMNS TOL
//       two field files of one mesh (nodes.csv of two runs), rows in the
//       same order: l2 passes if sqrt(sum (a - b)^2) <= TOL sqrt(sum b^2)
//       over the comma-separated COLUMNS (the relative L2 difference of a
//       vector field), max if max |a - b| <= TOL over them.
//   pdfem_check column history.csv COLUMN max|min|maxabs|last >|< BOUND
//       a statistic of one column of a history (rows after the header).
//   pdfem_check wave-speed history.csv COL_A X_A COL_B X_B LEVEL EXPECTED TOL
//       the first times t_A, t_B at which |COL_A|, |COL_B| reach LEVEL
//       (linear interpolation in the column "time"), the speed
//       c = (X_B - X_A) / (t_B - t_A); passes if |c - EXPECTED| <= TOL
//       EXPECTED.
// Prints one line per check and exits 1 on any failure.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /// Just enough JSON: objects, numbers, strings, true/false/null.
  struct Value
  {
    enum Kind
    {
      object,
      number,
      text,
      boolean,
      null
    } kind                                       = null;
    double                                     x = 0.;
    std::string                                s;
    std::vector<std::pair<std::string, Value>> members;
  };

  struct Parser
  {
    const std::string &t;
    std::size_t        i = 0;

    void
    ws()
    {
      while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i])))
        ++i;
    }
    std::string
    string()
    {
      std::string out;
      ++i; // opening quote
      while (i < t.size() && t[i] != '"')
        {
          if (t[i] == '\\' && i + 1 < t.size())
            ++i;
          out += t[i++];
        }
      ++i;
      return out;
    }
    Value
    value()
    {
      ws();
      Value v;
      if (t[i] == '{')
        {
          v.kind = Value::object;
          ++i;
          ws();
          if (t[i] == '}')
            {
              ++i;
              return v;
            }
          while (true)
            {
              ws();
              const std::string key = string();
              ws();
              ++i; // ':'
              v.members.emplace_back(key, value());
              ws();
              if (t[i++] == '}')
                break;
            }
        }
      else if (t[i] == '"')
        {
          v.kind = Value::text;
          v.s    = string();
        }
      else if (t.compare(i, 4, "true") == 0 || t.compare(i, 5, "false") == 0)
        {
          v.kind = Value::boolean;
          v.x    = t[i] == 't';
          i += t[i] == 't' ? 4 : 5;
        }
      else if (t.compare(i, 4, "null") == 0)
        i += 4;
      else
        {
          v.kind          = Value::number;
          const char *b   = t.c_str() + i;
          char       *end = nullptr;
          v.x             = std::strtod(b, &end);
          i += end - b;
        }
      return v;
    }
  };

  const Value *
  find(const Value &root, const std::string &key)
  {
    const Value      *v = &root;
    std::stringstream path(key);
    std::string       part;
    while (std::getline(path, part, '.'))
      {
        const Value *next = nullptr;
        for (const auto &[k, m] : v->members)
          if (k == part)
            next = &m;
        if (!next)
          return nullptr;
        v = next;
      }
    return v;
  }

  Value
  load(const std::string &file)
  {
    std::ifstream     in(file);
    std::stringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    if (text.empty())
      {
        std::cerr << "pdfem_check: cannot read " << file << "\n";
        std::exit(1);
      }
    Parser p{text};
    return p.value();
  }

  std::vector<std::vector<std::string>>
  read_csv(const std::string &file)
  {
    std::ifstream                         in(file);
    std::vector<std::vector<std::string>> rows;
    std::string                           line;
    while (std::getline(in, line))
      {
        std::vector<std::string> row;
        std::stringstream        s(line);
        std::string              cell;
        while (std::getline(s, cell, ','))
          row.push_back(cell);
        rows.push_back(row);
      }
    return rows;
  }

  /// Compare two summaries (see the header); prints one line per difference.
  bool
  same_summary(const Value       &a,
               const Value       &b,
               const std::string &path,
               const double       tol,
               unsigned int      &n_compared)
  {
    // linear_solver.choice (Type = auto) holds measured costs and the
    // memory available; its outcome (path, factorizations) is compared.
    static const std::vector<std::string> skipped = {
      "timings", "peak_memory_mb_rank0", "input_file", "message", "choice"};
    bool ok = true;
    // The force balance is a fraction of the load, round-off in a
    // conservative run: judged against 1 (as in the csv comparison).
    double scale = path == "force_balance" ? 1. : 0.;
    for (const auto *v : {&a, &b})
      for (const auto &[k, m] : v->members)
        if (m.kind == Value::number)
          scale = std::max(scale, std::abs(m.x));
    const auto names = [](const Value &v) {
      std::vector<std::string> n;
      for (const auto &[k, m] : v.members)
        n.push_back(k);
      return n;
    };
    if (names(a) != names(b))
      {
        std::cout << "FAIL " << (path.empty() ? "(top)" : path)
                  << ": different members\n";
        return false;
      }
    for (std::size_t i = 0; i < a.members.size(); ++i)
      {
        const auto &[key, x] = a.members[i];
        const Value      &y  = b.members[i].second;
        const std::string p  = path.empty() ? key : path + "." + key;
        if (std::find(skipped.begin(), skipped.end(), key) != skipped.end())
          continue;
        if (x.kind != y.kind)
          {
            std::cout << "FAIL " << p << ": different kinds\n";
            ok = false;
          }
        else if (x.kind == Value::object)
          ok = same_summary(x, y, p, tol, n_compared) && ok;
        else if (x.kind == Value::number)
          {
            ++n_compared;
            const double error = std::abs(x.x - y.x);
            if (!(error <= tol * scale))
              {
                std::cout.precision(17);
                std::cout << "FAIL " << p << ": " << x.x << " vs " << y.x
                          << " (difference " << error << ", scale " << scale
                          << ")\n";
                ok = false;
              }
          }
        else if (x.s != y.s || x.x != y.x)
          {
            ++n_compared;
            std::cout << "FAIL " << p << ": '" << x.s << "' vs '" << y.s
                      << "'\n";
            ok = false;
          }
      }
    return ok;
  }

  /// Index of @p name in the header of @p rows, or exit with a message.
  std::size_t
  column_index(const std::vector<std::vector<std::string>> &rows,
               const std::string                           &file,
               const std::string                           &name)
  {
    if (!rows.empty())
      for (std::size_t c = 0; c < rows[0].size(); ++c)
        if (rows[0][c] == name)
          return c;
    std::cout << "FAIL " << file << " has no column " << name << "\n";
    std::exit(1);
  }

  /// The first time |column| >= level, interpolated linearly; -1 if never.
  double
  first_crossing(const std::vector<std::vector<std::string>> &rows,
                 const std::size_t                            time,
                 const std::size_t                            column,
                 const double                                 level)
  {
    double t0 = 0., v0 = 0.;
    for (std::size_t r = 1; r < rows.size(); ++r)
      {
        const double t = std::stod(rows[r].at(time));
        const double v = std::abs(std::stod(rows[r].at(column)));
        if (v >= level)
          return r == 1 ? t : t0 + (level - v0) / (v - v0) * (t - t0);
        t0 = t;
        v0 = v;
      }
    return -1.;
  }
} // namespace

int
main(int argc, char **argv)
{
  const std::vector<std::string> a(argv + 1, argv + argc);
  if (a.size() == 3 && a[0] == "get")
    {
      const Value  root = load(a[1]);
      const Value *v    = find(root, a[2]);
      if (!v)
        {
          std::cerr << "pdfem_check: no " << a[2] << " in " << a[1] << "\n";
          return 1;
        }
      std::cout.precision(17);
      if (v->kind == Value::text)
        std::cout << v->s << "\n";
      else
        std::cout << v->x << "\n";
      return 0;
    }
  if (a.size() == 5 && a[0] == "bound")
    {
      // pdfem_check bound FILE KEY > VALUE   (or <)
      const Value  root  = load(a[1]);
      const Value *v     = find(root, a[2]);
      const double bound = std::stod(a[4]);
      const bool   above = a[3] == ">";
      const bool   ok =
        v && v->kind == Value::number && (above ? v->x > bound : v->x < bound);
      std::cout.precision(10);
      std::cout << (ok ? "ok   " : "FAIL ") << a[2] << " = " << (v ? v->x : 0.)
                << ", expected " << a[3] << " " << bound << "\n";
      return ok ? 0 : 1;
    }
  if (a.size() == 4 && a[0] == "string")
    {
      const Value  root = load(a[1]);
      const Value *v    = find(root, a[2]);
      const bool   ok   = v && v->kind == Value::text && v->s == a[3];
      std::cout << (ok ? "ok   " : "FAIL ") << a[2] << " = "
                << (v ? v->s : "(missing)") << ", expected " << a[3] << "\n";
      return ok ? 0 : 1;
    }
  if (a.size() == 6 && a[0] == "value")
    {
      const Value  root     = load(a[1]);
      const Value *v        = find(root, a[2]);
      const double expected = std::stod(a[3]);
      const double tol      = std::stod(a[5]);
      if (!v || v->kind != Value::number)
        {
          std::cout << "FAIL " << a[2] << " is missing or not a number\n";
          return 1;
        }
      const double error = std::abs(v->x - expected);
      const double bound = a[4] == "rel" ? tol * std::abs(expected) : tol;
      const bool   ok    = error <= bound;
      std::cout.precision(10);
      std::cout << (ok ? "ok   " : "FAIL ") << a[2] << " = " << v->x
                << ", expected " << expected << " (" << a[4] << " " << tol
                << ")\n";
      return ok ? 0 : 1;
    }
  if (a.size() == 3 && a[0] == "nondecreasing")
    {
      const auto        rows = read_csv(a[1]); // rows[0]: the header
      const std::size_t c =
        rows.empty() ?
          0 :
          std::find(rows[0].begin(), rows[0].end(), a[2]) - rows[0].begin();
      if (rows.size() < 2 || c == rows[0].size())
        {
          std::cout << "FAIL " << a[2] << " is not a column of " << a[1]
                    << " (or it has no rows)\n";
          return 1;
        }
      bool ok = true;
      for (std::size_t r = 2; r < rows.size(); ++r)
        if (std::stod(rows[r].at(c)) < std::stod(rows[r - 1].at(c)))
          {
            std::cout << "FAIL " << a[2] << " decreases at row " << r << ": "
                      << rows[r - 1].at(c) << " -> " << rows[r].at(c) << "\n";
            ok = false;
          }
      if (ok)
        std::cout << "ok   " << a[2] << " never decreases over "
                  << rows.size() - 1 << " rows\n";
      return ok ? 0 : 1;
    }
  if ((a.size() == 4 || a.size() == 5) && a[0] == "csv")
    {
      const auto   x   = read_csv(a[1]);
      const auto   y   = read_csv(a[2]);
      const double tol = std::stod(a[3]);
      if (x.empty() || x.size() != y.size() || x[0] != y[0])
        {
          std::cout << "FAIL " << a[1] << " and " << a[2]
                    << " differ in header or number of rows\n";
          return 1;
        }
      // Columns of one quantity (same first letter: ux, uy; sxx, sxy...) share
      // a scale, so that a component that is zero up to round-off is judged
      // against the size of the quantity, not against its own noise.
      const std::size_t   n_cols = x[0].size();
      std::vector<double> column_max(n_cols, 0.), error(n_cols, 0.);
      for (std::size_t c = 0; c < n_cols; ++c)
        for (std::size_t r = 1; r < x.size(); ++r)
          {
            const double u = std::stod(x[r].at(c)), v = std::stod(y[r].at(c));
            column_max[c] =
              std::max(column_max[c], std::max(std::abs(u), std::abs(v)));
            error[c] = std::max(error[c], std::abs(u - v));
          }
      bool                     ok = true;
      std::vector<std::string> skip; // a[4]: columns not compared (timings)
      if (a.size() == 5)
        {
          std::stringstream s(a[4]);
          std::string       name;
          while (std::getline(s, name, ','))
            skip.push_back(name);
        }
      for (std::size_t c = 0; c < n_cols; ++c)
        {
          if (std::find(skip.begin(), skip.end(), x[0][c]) != skip.end())
            continue;
          // Fractions of a load or of the work (force_imbalance,
          // energy_error, energy_drift) are judged against 1: a
          // conservative run's imbalance is round-off, whose own size is
          // no scale.
          const bool fraction = x[0][c] == "force_imbalance" ||
                                x[0][c] == "energy_error" ||
                                x[0][c] == "energy_drift";
          double scale = fraction ? 1. : 0.;
          for (std::size_t d = 0; d < n_cols; ++d)
            if (x[0][d][0] == x[0][c][0])
              scale = std::max(scale, column_max[d]);
          const bool column_ok = error[c] <= tol * scale;
          ok                   = ok && column_ok;
          std::cout.precision(3);
          std::cout << (column_ok ? "ok   " : "FAIL ") << "column " << x[0][c]
                    << ": max difference " << error[c] << " (scale " << scale
                    << ")\n";
        }
      return ok ? 0 : 1;
    }
  if (a.size() == 4 && a[0] == "summaries")
    {
      unsigned int n = 0;
      const bool   ok =
        same_summary(load(a[1]), load(a[2]), "", std::stod(a[3]), n);
      std::cout << (ok ? "ok   " : "FAIL ") << n << " values of " << a[1]
                << " and " << a[2] << " compared (tol " << a[3] << ")\n";
      return ok && n > 0 ? 0 : 1;
    }
  if (a.size() == 6 && a[0] == "fields" && (a[3] == "l2" || a[3] == "max"))
    {
      const auto x = read_csv(a[1]), y = read_csv(a[2]);
      if (x.size() != y.size() || x.size() < 2)
        {
          std::cout << "FAIL " << a[1] << " and " << a[2]
                    << " have different or no rows\n";
          return 1;
        }
      double            difference = 0., size = 0.;
      std::stringstream names(a[4]);
      std::string       name;
      while (std::getline(names, name, ','))
        {
          const std::size_t cx = column_index(x, a[1], name),
                            cy = column_index(y, a[2], name);
          for (std::size_t r = 1; r < x.size(); ++r)
            {
              const double u = std::stod(x[r].at(cx)),
                           v = std::stod(y[r].at(cy));
              if (a[3] == "l2")
                {
                  difference += (u - v) * (u - v);
                  size += v * v;
                }
              else
                difference = std::max(difference, std::abs(u - v));
            }
        }
      const double measure = a[3] == "l2" ?
                               std::sqrt(difference / std::max(size, 1e-300)) :
                               difference;
      const bool   ok      = measure <= std::stod(a[5]);
      std::cout << (ok ? "ok   " : "FAIL ") << a[3] << " difference of " << a[4]
                << ": " << measure << " (tol " << a[5] << ")\n";
      return ok ? 0 : 1;
    }
  if (a.size() == 6 && a[0] == "column")
    {
      const auto        rows = read_csv(a[1]);
      const std::size_t c    = column_index(rows, a[1], a[2]);
      if (rows.size() < 2)
        {
          std::cout << "FAIL " << a[1] << " has no rows\n";
          return 1;
        }
      double value = a[3] == "min" ? HUGE_VAL : a[3] == "last" ? 0. : -HUGE_VAL;
      for (std::size_t r = 1; r < rows.size(); ++r)
        {
          const double v = std::stod(rows[r].at(c));
          if (a[3] == "max")
            value = std::max(value, v);
          else if (a[3] == "min")
            value = std::min(value, v);
          else if (a[3] == "maxabs")
            value = std::max(value, std::abs(v));
          else
            value = v;
        }
      const double bound = std::stod(a[5]);
      const bool   ok =
        std::isfinite(value) && (a[4] == ">" ? value > bound : value < bound);
      std::cout.precision(10);
      std::cout << (ok ? "ok   " : "FAIL ") << a[3] << "(" << a[2]
                << ") = " << value << ", expected " << a[4] << " " << bound
                << "\n";
      return ok ? 0 : 1;
    }
  if (a.size() == 9 && a[0] == "wave-speed")
    {
      const auto        rows = read_csv(a[1]);
      const std::size_t time = column_index(rows, a[1], "time");
      const std::size_t ca   = column_index(rows, a[1], a[2]);
      const std::size_t cb   = column_index(rows, a[1], a[4]);
      const double      xa = std::stod(a[3]), xb = std::stod(a[5]);
      const double      level    = std::stod(a[6]);
      const double      expected = std::stod(a[7]);
      const double      tol      = std::stod(a[8]);
      const double      ta       = first_crossing(rows, time, ca, level);
      const double      tb       = first_crossing(rows, time, cb, level);
      const double      c  = (ta >= 0. && tb > ta) ? (xb - xa) / (tb - ta) : 0.;
      const bool        ok = std::abs(c - expected) <= tol * std::abs(expected);
      std::cout.precision(6);
      std::cout << (ok ? "ok   " : "FAIL ") << "wave speed " << c << " (|"
                << a[2] << "| and |" << a[4] << "| reach " << level
                << " at t = " << ta << ", " << tb << "), expected " << expected
                << " (rel " << tol << ", error "
                << std::abs(c - expected) / std::abs(expected) << ")\n";
      return ok ? 0 : 1;
    }
  std::cerr << "usage: pdfem_check value FILE KEY EXPECTED rel|abs TOL\n"
               "       pdfem_check string FILE KEY EXPECTED\n"
               "       pdfem_check get FILE KEY\n"
               "       pdfem_check bound FILE KEY >|< BOUND\n"
               "       pdfem_check nondecreasing FILE COLUMN\n"
               "       pdfem_check csv A B TOL [SKIP,...]\n"
               "       pdfem_check summaries A B TOL\n"
               "       pdfem_check column CSV COLUMN max|min|maxabs|last >|< "
               "BOUND\n"
               "       pdfem_check wave-speed CSV COL_A X_A COL_B X_B LEVEL "
               "EXPECTED TOL\n";
  return 2;
}
