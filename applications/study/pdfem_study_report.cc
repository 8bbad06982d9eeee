// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-study: the errors, the Pareto front, study.csv, the table on stdout
// and the chart (drawn by pdfem-plot).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include "pdfem_study.h"
#include <boost/algorithm/string/join.hpp>

namespace pdfem_study
{
  using boost::algorithm::join;

  namespace
  {
    /// A CSV field: quoted when it holds a comma, a quote or a line break.
    std::string
    csv_field(const std::string &s)
    {
      if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
      std::string out = "\"";
      for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
      return out + "\"";
    }

    /// The reference values as the table's title says them.
    std::string
    reference_text(const Options &options, const std::vector<double> &ref)
    {
      switch (options.reference.kind)
        {
          case Reference::none:
            return "none (no errors)";
          case Reference::values:
            return "given (" + options.reference.text + ")";
          case Reference::run:
            {
              std::vector<std::string> values;
              for (double r : ref)
                values.push_back(std::isnan(r) ? "failed" : format(r, 10));
              return "run " + options.reference.text.substr(4) + " (" +
                     join(values, ", ") + ")";
            }
        }
      return "";
    }
  } // namespace

  std::string
  format(double x, int digits)
  {
    if (std::isnan(x))
      return "";
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, x);
    return buffer;
  }

  double
  relative_error(double value, double reference)
  {
    if (!std::isfinite(value) || !std::isfinite(reference))
      return missing;
    return reference == 0 ? std::abs(value) :
                            std::abs(value - reference) / std::abs(reference);
  }

  void
  mark_pareto(std::vector<Row> &rows)
  {
    auto ranked = [](const Row &r) {
      return !r.errors.empty() && std::isfinite(r.errors[0]) &&
             std::isfinite(r.result.wall_seconds);
    };
    for (auto &a : rows)
      {
        a.pareto = -1;
        if (!ranked(a))
          continue;
        const double t = a.result.wall_seconds, e = a.errors[0];
        a.pareto = 1;
        for (const auto &b : rows)
          if (&b != &a && ranked(b))
            {
              const double tb = b.result.wall_seconds, eb = b.errors[0];
              if (tb <= t && eb <= e && (tb < t || eb < e))
                a.pareto = 0;
            }
      }
  }

  void
  write_csv(const std::string         &file,
            const Options             &options,
            const std::vector<Row>    &rows,
            const std::vector<double> &reference)
  {
    std::ofstream            out(file);
    std::vector<std::string> header = {"run", "folder"};
    for (const auto &v : options.vary)
      header.push_back(csv_field(v.path));
    header.push_back("in_process");
    header.push_back("exit_state");
    for (const auto &k : options.outputs)
      header.push_back(k);
    const bool errors = options.reference.kind != Reference::none;
    if (errors)
      {
        for (const auto &k : options.outputs)
          header.push_back(k + ".reference");
        for (const auto &k : options.outputs)
          header.push_back(k + ".error");
      }
    for (const char *c : {"wall_seconds",
                          "pdfem_total_seconds",
                          "peak_memory_mb",
                          "dofs",
                          "bonds",
                          "pareto"})
      header.push_back(c);
    out << join(header, ",") << "\n";

    for (const auto &row : rows)
      {
        const RunResult         &r = row.result;
        std::vector<std::string> cells{std::to_string(row.point.number),
                                       row.point.folder};
        for (const auto &v : row.point.values)
          cells.push_back(csv_field(v));
        cells.push_back(r.in_process ? "1" : "0");
        cells.push_back(csv_field(r.exit_state));
        for (double v : r.outputs)
          cells.push_back(format(v));
        if (errors)
          {
            for (double v : reference)
              cells.push_back(format(v));
            for (double e : row.errors)
              cells.push_back(format(e));
          }
        cells.push_back(format(r.wall_seconds, 6));
        cells.push_back(format(r.total_seconds, 6));
        cells.push_back(
          std::isnan(r.peak_memory_mb) ? "n/a" : format(r.peak_memory_mb, 6));
        cells.push_back(format(r.dofs));
        cells.push_back(format(r.bonds));
        cells.push_back(row.pareto < 0 ? "" : std::to_string(row.pareto));
        out << join(cells, ",") << "\n";
      }
    out.close();
    if (!out)
      throw std::runtime_error("cannot write " + file);
  }

  void
  print_table(const Options             &options,
              const std::vector<Row>    &rows,
              const std::vector<double> &reference)
  {
    std::vector<std::vector<std::string>> table;
    std::vector<std::string>              head = {"run"};
    for (const auto &v : options.vary)
      head.push_back(v.path.substr(v.path.rfind('/') + 1));
    head.push_back("state");
    const bool errors = options.reference.kind != Reference::none;
    for (const auto &k : options.outputs)
      {
        head.push_back(k);
        if (errors)
          head.push_back("error");
      }
    for (const char *c : {"wall [s]", "memory [MB]", "dofs", "pareto"})
      head.push_back(c);
    table.push_back(head);
    for (const auto &row : rows)
      {
        const RunResult         &r = row.result;
        std::vector<std::string> line{std::to_string(row.point.number)};
        for (const auto &v : row.point.values)
          line.push_back(v);
        line.push_back(r.exit_state);
        for (std::size_t k = 0; k < r.outputs.size(); ++k)
          {
            line.push_back(format(r.outputs[k], 7));
            if (errors)
              line.push_back(format(row.errors[k], 3));
          }
        line.push_back(format(r.wall_seconds, 3));
        line.push_back(std::isnan(r.peak_memory_mb) ?
                         "n/a" :
                         format(std::round(r.peak_memory_mb), 6));
        line.push_back(format(r.dofs));
        line.push_back(row.pareto == 1 ? "*" : "");
        table.push_back(line);
      }
    std::vector<std::size_t> width(head.size(), 0);
    for (const auto &line : table)
      for (std::size_t c = 0; c < line.size(); ++c)
        width[c] = std::max(width[c], line[c].size());
    std::cout << "reference: " << reference_text(options, reference) << "\n";
    for (const auto &line : table)
      {
        std::string text;
        for (std::size_t c = 0; c < line.size(); ++c)
          text += line[c] + std::string(width[c] - line[c].size() + 2, ' ');
        std::cout << text.substr(0, text.find_last_not_of(' ') + 1) << "\n";
      }
    std::cout.flush();
  }

  std::string
  draw_chart(const std::string      &folder,
             const Options          &options,
             const std::vector<Row> &rows)
  {
    const std::string &key = options.outputs.front();
    if (options.reference.kind == Reference::none)
      return "no chart: no --reference, no errors";
    std::vector<const Row *> drawn;
    for (const auto &row : rows)
      if (!row.errors.empty() && std::isfinite(row.errors[0]) &&
          row.errors[0] > 0 && std::isfinite(row.result.wall_seconds) &&
          row.result.wall_seconds > 0)
        drawn.push_back(&row);
    if (drawn.empty())
      return "no chart: no run has a positive error of " + key;
    const std::string plot = program_folder() + "/pdfem-plot";
    if (find_executable(plot).empty())
      return "no chart: pdfem-plot is not installed beside pdfem-study (it "
             "is built only where VTK is found)";
    std::vector<std::string> argv;
    const char              *display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0')
      {
        const std::string xvfb = find_executable("xvfb-run");
        if (xvfb.empty())
          return "no chart: no X display and no xvfb-run (apt-get install "
                 "xvfb xauth)";
        argv = {xvfb, "-a"};
      }

    // With one --vary every run is its own one-point series (pdfem-plot
    // draws it as a marker), labelled with its value. With more, the runs
    // that share the values of all but the last --vary are one series, a
    // line with markers through the last parameter's values in their order
    // (e.g. "Type=newmark" along the time steps): a legend of a few lines
    // instead of one per run. The Pareto front is a second file (dashed).
    const bool               grouped = options.vary.size() >= 2;
    const std::size_t        n_group = options.vary.size() - 1;
    std::vector<std::string> columns, labels;
    std::vector<std::size_t> series_of(drawn.size());
    std::vector<std::string> first_value, last_value;
    for (std::size_t i = 0; i < drawn.size(); ++i)
      {
        const Point      &point = drawn[i]->point;
        const std::string name  = grouped ? describe(options, point, n_group) :
                                            std::to_string(point.number) + ": " +
                                             describe(options, point);
        const std::string value =
          point.values.empty() ? "" : point.values.back();
        const auto found = std::find(labels.begin(), labels.end(), name);
        series_of[i]     = found - labels.begin();
        if (found == labels.end())
          {
            labels.push_back(name);
            columns.push_back("series_" + std::to_string(labels.size()));
            first_value.push_back(value);
            last_value.push_back(value);
          }
        last_value[series_of[i]] = value;
      }
    if (grouped)
      {
        const std::string &path = options.vary.back().path;
        const std::string  last = path.substr(path.rfind('/') + 1);
        for (std::size_t s = 0; s < labels.size(); ++s)
          labels[s] += first_value[s] == last_value[s] ?
                         " (" + last + "=" + first_value[s] + ")" :
                         " (" + last + "=" + first_value[s] + " ... " +
                           last_value[s] + ")";
      }
    std::ofstream points(folder + "/study_chart.csv");
    points << "wall_seconds," << join(columns, ",") << "\n";
    for (std::size_t i = 0; i < drawn.size(); ++i)
      {
        points << format(drawn[i]->result.wall_seconds);
        for (std::size_t s = 0; s < columns.size(); ++s)
          points << ","
                 << (series_of[i] == s ? format(drawn[i]->errors[0]) : "");
        points << "\n";
      }
    points.close();
    std::vector<const Row *> front;
    for (const Row *row : drawn)
      if (row->pareto == 1)
        front.push_back(row);
    std::sort(front.begin(), front.end(), [](const Row *a, const Row *b) {
      return a->result.wall_seconds < b->result.wall_seconds;
    });
    std::ofstream pareto(folder + "/study_pareto.csv");
    pareto << "wall_seconds,error\n";
    for (const Row *row : front)
      pareto << format(row->result.wall_seconds) << ","
             << format(row->errors[0]) << "\n";
    pareto.close();
    if (!points || !pareto)
      return "no chart: cannot write the chart's data into " + folder;
    labels.push_back("Pareto front");

    const std::vector<std::string> chart = {plot,
                                            "chart",
                                            folder + "/study_chart.csv",
                                            "--x",
                                            "wall_seconds",
                                            "--y",
                                            join(columns, ","),
                                            "--csv2",
                                            folder + "/study_pareto.csv",
                                            "--x2",
                                            "wall_seconds",
                                            "--y2",
                                            "error",
                                            "--label",
                                            join(labels, ","),
                                            "--logx",
                                            "--logy",
                                            "--xlabel",
                                            "wall time of the run [s]",
                                            "--ylabel",
                                            "relative error of " + key,
                                            "--title",
                                            scene_name(options.scene) +
                                              ": error against run time",
                                            "--legend",
                                            labels.size() <= 11 ? "auto" :
                                                                  "none",
                                            "--out",
                                            folder + "/study.png"};
    argv.insert(argv.end(), chart.begin(), chart.end());
    if (grouped)
      argv.push_back("--markers");
    const int code = run_program(argv, folder + "/chart.log");
    if (code != 0)
      return "no chart: pdfem-plot failed (exit status " +
             std::to_string(code) + "; see " + folder + "/chart.log)";
    return folder + "/study.png";
  }
} // namespace pdfem_study
