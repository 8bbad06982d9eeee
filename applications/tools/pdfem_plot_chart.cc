// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot chart: a line chart of columns of CSV files, as a PNG.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "pdfem_plot.h"
#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChart.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace pdfem_plot
{
  namespace
  {
    struct Csv
    {
      std::string              file;
      std::vector<std::string> header;
      std::vector<std::vector<std::string>>
                       rows; // cells as text; parsed when a column is used
      std::vector<int> line_numbers;

      int
      column(const std::string &name, const std::string &option) const
      {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end())
          throw UsageError(option + ": no column " + in_quotes(name) + " in " +
                           in_quotes(file) + "; columns: " + join(header));
        return static_cast<int>(it - header.begin());
      }

      // The value in row r, column c; NaN for an empty or missing cell.
      double
      value(std::size_t r, int c) const
      {
        if (static_cast<std::size_t>(c) >= rows[r].size() ||
            trim(rows[r][c]).empty())
          return std::numeric_limits<double>::quiet_NaN();
        double v;
        if (!parse_number(rows[r][c], v))
          throw RunError(in_quotes(file) + " line " +
                         std::to_string(line_numbers[r]) + ", column " +
                         in_quotes(header[c]) + ": " +
                         in_quotes(trim(rows[r][c])) + " is not a number");
        return v;
      }
    };

    std::string
    unquote(std::string s)
    {
      s = trim(s);
      if (s.size() >= 2 && s.front() == '"' && s.back() == '"')
        s = s.substr(1, s.size() - 2);
      return s;
    }

    Csv
    read_csv(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw RunError("cannot read " + in_quotes(file));
      Csv csv;
      csv.file = file;
      std::string line;
      int         number = 0;
      while (std::getline(in, line))
        {
          ++number;
          if (number == 1 &&
              line.rfind("\xEF\xBB\xBF", 0) == 0) // UTF-8 byte order mark
            line = line.substr(3);
          const std::string t = trim(line);
          if (t.empty() || t[0] == '#')
            continue;
          std::vector<std::string> cells = split(t, ',');
          if (csv.header.empty())
            {
              for (auto &cell : cells)
                csv.header.push_back(unquote(cell));
              continue;
            }
          if (cells.size() > csv.header.size())
            throw RunError(in_quotes(file) + " line " + std::to_string(number) +
                           " has " + std::to_string(cells.size()) +
                           " values but the header has " +
                           std::to_string(csv.header.size()) + " columns");
          csv.rows.push_back(std::move(cells));
          csv.line_numbers.push_back(number);
        }
      if (csv.header.empty())
        throw RunError(in_quotes(file) + " is empty (no header row)");
      return csv;
    }

    std::string
    file_stem(const std::string &file)
    {
      return std::filesystem::path(file).stem().string();
    }

    // The unit of a column of pdfem's history.csv ("" for counts, the
    // pseudo-time of static runs and names it does not know).
    std::string
    history_unit(const std::string &name)
    {
      auto starts  = [&](const char *p) { return name.rfind(p, 0) == 0; };
      auto indexed = [&](const char *p) { // p followed by a tip number
        const std::size_t n = std::string(p).size();
        return starts(p) && name.size() > n &&
               name.find_first_not_of("0123456789", n) == std::string::npos;
      };
      if (name == "load_factor" || name == "residual" || name == "max_damage")
        return "-";
      if (starts("reaction_"))
        return "N";
      if (starts("u_") || (starts("tip") && (name.size() > 2) &&
                           (name.compare(name.size() - 2, 2, "_x") == 0 ||
                            name.compare(name.size() - 2, 2, "_y") == 0 ||
                            name.compare(name.size() - 2, 2, "_z") == 0)))
        return "m";
      if (indexed("K_I") || indexed("K_II") || indexed("K_III") ||
          indexed("K_eq"))
        return "Pa\u221am";
      if (indexed("J"))
        return "J/m\u00b2";
      if (name == "kinetic_energy" || name == "strain_energy" ||
          name == "external_work" || name == "dissipated_energy")
        return "J";
      if (name == "wall_seconds" || name == "time_step")
        return "s";
      return "";
    }

    // "name [unit]", or the name alone when its unit is unknown.
    std::string
    with_history_unit(const std::string &name)
    {
      const std::string unit = history_unit(name);
      return unit.empty() ? name : name + " [" + unit + "]";
    }

    struct Series
    {
      std::string         label;
      std::vector<double> x, y;
      bool                from_second_file = false;
      int                 colour           = 0;
    };

    Series
    make_series(const Csv &csv, int xc, int yc, bool logx, bool logy)
    {
      Series      s;
      std::size_t non_positive = 0;
      for (std::size_t r = 0; r < csv.rows.size(); ++r)
        {
          const double x = csv.value(r, xc), y = csv.value(r, yc);
          if (!std::isfinite(x) || !std::isfinite(y))
            continue;
          if ((logx && x <= 0) || (logy && y <= 0))
            {
              ++non_positive;
              continue;
            }
          s.x.push_back(x);
          s.y.push_back(y);
        }
      if (non_positive > 0)
        warn("left out " + std::to_string(non_positive) + " point(s) of " +
             in_quotes(csv.header[yc]) + " in " + in_quotes(csv.file) +
             " with values <= 0 on a log axis");
      if (s.x.empty())
        warn("no points to plot for " + in_quotes(csv.header[yc]) + " in " +
             in_quotes(csv.file));
      return s;
    }

    // Tick labels with as many digits as the tick spacing needs; powers of ten
    // for very large or small.
    std::vector<std::string>
    tick_labels(const std::vector<double> &values, double step)
    {
      double largest = 0.0;
      for (double v : values)
        largest = std::max(largest, std::abs(v));
      const bool scientific = largest >= 1e5 || largest < 1e-3;
      const int  step_exponent =
        static_cast<int>(std::floor(std::log10(step) + 1e-9));
      std::vector<std::string> labels;
      for (double v : values)
        {
          std::ostringstream s;
          if (std::abs(v) < 1e-9 * step)
            s << "0";
          else if (scientific)
            {
              const int exponent =
                static_cast<int>(std::floor(std::log10(std::abs(v)) + 1e-9));
              s << std::scientific
                << std::setprecision(std::max(0, exponent - step_exponent))
                << v;
            }
          else
            s << std::fixed << std::setprecision(std::max(0, -step_exponent))
              << v;
          labels.push_back(s.str());
        }
      return labels;
    }

    // A linear axis with round ticks; for a horizontal axis the number of ticks
    // is chosen so that the labels do not crowd each other.
    std::array<double, 2>
    set_linear_ticks(vtkAxis *axis,
                     double   lo,
                     double   hi,
                     double   length_px,
                     double   font_px,
                     bool     horizontal,
                     double   pad)
    {
      Ticks                    t{};
      std::vector<double>      values;
      std::vector<std::string> labels;
      for (int max_intervals = 10; max_intervals >= 2; --max_intervals)
        {
          t = nice_ticks(lo, hi, max_intervals);
          values.clear();
          for (double k = std::round(t.lo / t.step);
               k <= std::round(t.hi / t.step);
               k += 1.0)
            values.push_back(k * t.step);
          labels             = tick_labels(values, t.step);
          std::size_t widest = 0;
          for (const auto &l : labels)
            widest = std::max(widest, l.size());
          const double label_px =
            horizontal ? (0.6 * widest + 1.5) * font_px : 2.2 * font_px;
          if (values.size() * label_px <= length_px)
            break;
        }
      vtkNew<vtkDoubleArray> positions;
      vtkNew<vtkStringArray> names;
      for (std::size_t i = 0; i < values.size(); ++i)
        {
          positions->InsertNextValue(values[i]);
          names->InsertNextValue(labels[i]);
        }
      const double margin = pad * (t.hi - t.lo);
      axis->SetBehavior(vtkAxis::FIXED);
      axis->SetRange(t.lo - margin, t.hi + margin);
      axis->SetCustomTickPositions(positions, names);
      return {t.lo - margin, t.hi + margin};
    }

    // The corner of the plot area where a legend box (given as fractions of the
    // plot area) hides the fewest data: points along the lines are sampled and
    // counted. Ties go to the earlier corner.
    std::string
    quietest_corner(const std::vector<Series>   &series,
                    const std::array<double, 2> &xr,
                    const std::array<double, 2> &yr,
                    bool                         logx,
                    bool                         logy,
                    double                       box_w,
                    double                       box_h)
    {
      const char *const          corners[4] = {"top-right",
                                               "top-left",
                                               "bottom-right",
                                               "bottom-left"};
      std::array<std::size_t, 4> hidden{};
      auto                       count = [&](double x, double y) {
        const double u = ((logx ? std::log10(x) : x) - xr[0]) / (xr[1] - xr[0]);
        const double v = ((logy ? std::log10(y) : y) - yr[0]) / (yr[1] - yr[0]);
        const bool   right = u > 1.0 - box_w,
                   left = u<box_w, top = v> 1.0 - box_h, bottom = v < box_h;
        hidden[0] += top && right;
        hidden[1] += top && left;
        hidden[2] += bottom && right;
        hidden[3] += bottom && left;
      };
      for (const auto &s : series)
        for (std::size_t i = 0; i < s.x.size(); ++i)
          {
            count(s.x[i], s.y[i]);
            if (i + 1 < s.x.size())
              for (int k = 1; k < 16; ++k)
                {
                  const double f = k / 16.0;
                  if (logx || logy) // interpolate where the line is straight:
                                    // in the plotted coordinates
                    {
                      const double x =
                        logx ? std::pow(10.0,
                                        std::log10(s.x[i]) +
                                          f * (std::log10(s.x[i + 1]) -
                                               std::log10(s.x[i]))) :
                               s.x[i] + f * (s.x[i + 1] - s.x[i]);
                      const double y =
                        logy ? std::pow(10.0,
                                        std::log10(s.y[i]) +
                                          f * (std::log10(s.y[i + 1]) -
                                               std::log10(s.y[i]))) :
                               s.y[i] + f * (s.y[i + 1] - s.y[i]);
                      count(x, y);
                    }
                  else
                    count(s.x[i] + f * (s.x[i + 1] - s.x[i]),
                          s.y[i] + f * (s.y[i + 1] - s.y[i]));
                }
          }
      int best = 0;
      for (int c = 1; c < 4; ++c)
        if (hidden[c] < hidden[best])
          best = c;
      return corners[best];
    }
  } // namespace

  int
  run_chart(const std::vector<std::string> &args)
  {
    const Arguments a = parse_arguments(
      "chart",
      args,
      {{"--x", "COLUMN", 1},
       {"--y", "COL1[,COL2...]", 1},
       {"--csv2", "FILE2.csv", 1},
       {"--x2", "COLUMN", 1},
       {"--y2", "COL1[,COL2...]", 1},
       {"--label", "L1,L2,...", 1},
       {"--logx", "", 0},
       {"--logy", "", 0},
       {"--xlabel", "TEXT", 1},
       {"--ylabel", "TEXT", 1},
       {"--title", "TEXT", 1},
       {"--legend",
        "auto, top-right, top-left, bottom-right, bottom-left or none",
        1},
       {"--points", "", 0},
       {"--markers", "", 0},
       {"--size", "W H", 2},
       {"--out", "OUT.png", 1}});
    const std::string file = input_file(a, "a .csv file");
    if (!a.has("--x"))
      throw UsageError(
        "'chart' needs --x COLUMN (the column for the horizontal axis)");
    if (!a.has("--y"))
      throw UsageError(
        "'chart' needs --y COL1[,COL2...] (the columns to plot)");
    if ((a.has("--y2") || a.has("--x2")) && !a.has("--csv2"))
      throw UsageError(std::string(a.has("--y2") ? "--y2" : "--x2") +
                       " needs --csv2 FILE2.csv");
    const std::string        out   = output_file(a);
    const std::array<int, 2> size  = size_option(a, 1000, 700);
    const int                width = size[0], height = size[1];
    std::string              legend = a.value_or("--legend", "auto");
    if (legend != "auto" && legend != "top-right" && legend != "top-left" &&
        legend != "bottom-right" && legend != "bottom-left" && legend != "none")
      throw UsageError(
        "--legend must be auto, top-right, top-left, bottom-right, bottom-left or none, got " +
        in_quotes(legend));
    const bool logx = a.has("--logx"), logy = a.has("--logy"),
               points = a.has("--points");
    // --markers: lines with a marker at every point (a path through a
    // parameter's values, say).
    const bool markers = a.has("--markers");
    if (points && markers)
      throw UsageError("--points and --markers exclude each other (--points: "
                       "markers only; --markers: lines and markers)");

    auto column_list = [](const std::string &option, const std::string &text) {
      std::vector<std::string> names;
      for (const auto &n : split(text, ','))
        {
          if (trim(n).empty())
            throw UsageError(option +
                             " needs comma-separated column names, got " +
                             in_quotes(text));
          names.push_back(trim(n));
        }
      return names;
    };

    const Csv                      csv1    = read_csv(file);
    const std::string              xname   = a.value("--x");
    const int                      xcol1   = csv1.column(xname, "--x");
    const std::vector<std::string> y1names = column_list("--y", a.value("--y"));
    std::vector<int>               ycols1;
    for (const auto &n : y1names)
      ycols1.push_back(csv1.column(n, "--y"));

    Csv                      csv2;
    int                      xcol2 = -1;
    std::vector<std::string> y2names;
    std::vector<int>         ycols2;
    if (a.has("--csv2"))
      {
        const std::string &f2 = a.value("--csv2");
        std::error_code    ec;
        if (!std::filesystem::is_regular_file(f2, ec) || !std::ifstream(f2))
          throw UsageError("--csv2: file " + in_quotes(f2) +
                           " does not exist or cannot be read");
        csv2  = read_csv(f2);
        xcol2 = csv2.column(a.value_or("--x2", xname),
                            a.has("--x2") ? "--x2" : "--x (in --csv2)");
        y2names =
          a.has("--y2") ? column_list("--y2", a.value("--y2")) : y1names;
        for (const auto &n : y2names)
          ycols2.push_back(
            csv2.column(n, a.has("--y2") ? "--y2" : "--y (in --csv2)"));
      }

    const std::size_t        n_series = ycols1.size() + ycols2.size();
    std::vector<std::string> labels;
    if (a.has("--label"))
      {
        labels = split(a.value("--label"), ',');
        if (labels.size() != n_series)
          throw UsageError("--label needs " + std::to_string(n_series) +
                           " comma-separated labels (one per series), got " +
                           std::to_string(labels.size()));
      }
    else
      {
        for (const auto &n : y1names)
          labels.push_back(a.has("--csv2") ? n + " (" + file_stem(file) + ")" :
                                             n);
        for (const auto &n : y2names)
          labels.push_back(n + " (" + file_stem(a.value("--csv2")) + ")");
        if (a.has("--csv2") && file_stem(file) == file_stem(a.value("--csv2")))
          {
            // Same file names in different folders: say "file 1" and "file 2".
            for (std::size_t i = 0; i < n_series; ++i)
              labels[i] =
                (i < ycols1.size() ? y1names[i] + " (file 1)" :
                                     y2names[i - ycols1.size()] + " (file 2)");
          }
      }

    std::vector<Series> series;
    for (std::size_t i = 0; i < ycols1.size(); ++i)
      {
        series.push_back(make_series(csv1, xcol1, ycols1[i], logx, logy));
        series.back().colour = static_cast<int>(i);
      }
    for (std::size_t i = 0; i < ycols2.size(); ++i)
      {
        series.push_back(make_series(csv2, xcol2, ycols2[i], logx, logy));
        series.back().from_second_file = true;
        series.back().colour           = static_cast<int>(ycols1.size() + i);
      }
    for (std::size_t i = 0; i < series.size(); ++i)
      series[i].label = labels[i];
    if (std::all_of(series.begin(), series.end(), [](const Series &s) {
          return s.x.empty();
        }))
      throw RunError(
        "nothing to plot: no finite (x, y) pairs in the chosen columns");

    // Okabe & Ito's colour-blind-safe palette (yellow left out: too pale on
    // white).
    static const unsigned char palette[][3] = {{0, 114, 178},
                                               {213, 94, 0},
                                               {0, 158, 115},
                                               {204, 121, 167},
                                               {230, 159, 0},
                                               {86, 180, 233},
                                               {0, 0, 0}};
    const int                  n_palette = sizeof(palette) / sizeof(palette[0]);

    const int font = std::clamp(static_cast<int>(std::lround(
                                  std::sqrt(1.0 * width * height) / 40.0)),
                                12,
                                72);

    vtkNew<vtkContextView> view;
    require_display(view->GetRenderWindow());
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetSize(width, height);
    view->GetRenderWindow()->SetMultiSamples(8);
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);

    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);

    std::vector<vtkSmartPointer<vtkTable>>
      tables; // keep the data alive until rendering
    for (const auto &s : series)
      {
        if (s.x.empty())
          continue;
        auto                   table = vtkSmartPointer<vtkTable>::New();
        vtkNew<vtkDoubleArray> xs, ys;
        xs->SetName("x");
        ys->SetName(s.label.c_str());
        xs->SetNumberOfValues(static_cast<vtkIdType>(s.x.size()));
        ys->SetNumberOfValues(static_cast<vtkIdType>(s.y.size()));
        for (std::size_t i = 0; i < s.x.size(); ++i)
          {
            xs->SetValue(static_cast<vtkIdType>(i), s.x[i]);
            ys->SetValue(static_cast<vtkIdType>(i), s.y[i]);
          }
        table->AddColumn(xs);
        table->AddColumn(ys);
        tables.push_back(table);

        // A single point gets a marker: a line through one point would not
        // show.
        const bool point_plot = points || s.x.size() == 1;
        vtkPlot   *plot =
          chart->AddPlot(point_plot ? vtkChart::POINTS : vtkChart::LINE);
        plot->SetInputData(table, 0, 1);
        plot->SetLabel(s.label);
        // Past the palette's seven colours the series differ also in their
        // marker and their dashes, so that no two of 35 look the same.
        const int            round = s.colour / n_palette;
        const unsigned char *rgb   = palette[s.colour % n_palette];
        plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
        plot->SetWidth(points ? 1.5f : 2.5f);
        if (auto *pp = vtkPlotPoints::SafeDownCast(plot))
          {
            if (point_plot || markers)
              {
                // The second file's crosses are larger and drawn later, so
                // that they show on top of the first file's dots.
                static const int styles[] = {vtkPlotPoints::CIRCLE,
                                             vtkPlotPoints::SQUARE,
                                             vtkPlotPoints::DIAMOND,
                                             vtkPlotPoints::PLUS,
                                             vtkPlotPoints::CROSS};
                pp->SetMarkerStyle(s.from_second_file ? vtkPlotPoints::CROSS :
                                                        styles[round % 5]);
                pp->SetMarkerSize(std::max(6.0f, font * 0.5f) *
                                  (s.from_second_file ? 1.8f : 1.0f));
                if (s.from_second_file && point_plot)
                  plot->SetWidth(3.0f);
              }
            else
              pp->SetMarkerStyle(vtkPlotPoints::NONE);
          }
        if (!point_plot)
          {
            static const int dashes[] = {vtkPen::SOLID_LINE,
                                         vtkPen::DASH_LINE,
                                         vtkPen::DOT_LINE,
                                         vtkPen::DASH_DOT_LINE};
            plot->GetPen()->SetLineType(s.from_second_file ? vtkPen::DASH_LINE :
                                                             dashes[round % 4]);
          }
      }

    auto style_axis = [&](vtkAxis *axis, const std::string &title, bool log) {
      axis->SetTitle(title);
      style_text(axis->GetTitleProperties(), font);
      style_text(axis->GetLabelProperties(), static_cast<int>(0.85 * font));
      axis->GetPen()->SetColor(0, 0, 0, 255);
      axis->GetGridPen()->SetColor(220, 220, 220, 255);
      axis->SetLogScale(log);
    };
    // Default axis titles: the column with its unit where pdfem's history.csv
    // has a known one; for different y columns of one unit, the unit alone.
    std::string ylabel;
    {
      std::vector<std::string> all = y1names;
      all.insert(all.end(), y2names.begin(), y2names.end());
      if (std::all_of(all.begin(), all.end(), [&](const std::string &n) {
            return n == all.front();
          }))
        ylabel = with_history_unit(all.front());
      else if (const std::string unit = history_unit(all.front());
               !unit.empty() &&
               std::all_of(all.begin(), all.end(), [&](const std::string &n) {
                 return history_unit(n) == unit;
               }))
        ylabel = "[" + unit + "]";
    }
    style_axis(chart->GetAxis(vtkAxis::BOTTOM),
               a.value_or("--xlabel", with_history_unit(xname)),
               logx);
    style_axis(chart->GetAxis(vtkAxis::LEFT),
               a.value_or("--ylabel", ylabel),
               logy);

    // The title is drawn above the chart (vtkChartXY's own title collides with
    // the top tick label).
    const int title_px = a.has("--title") ? static_cast<int>(2.6 * font) : 0;
    chart->SetLayoutStrategy(vtkChart::FILL_RECT);
    // A right margin keeps the last tick label of the x axis inside the
    // picture.
    const float right_margin = static_cast<float>(2.5 * font);
    chart->SetSize(vtkRectf(0.0f,
                            0.0f,
                            static_cast<float>(width) - right_margin,
                            static_cast<float>(height - title_px)));
    vtkNew<vtkTextActor> title;
    if (a.has("--title"))
      {
        title->SetInput(a.value("--title").c_str());
        style_text(title->GetTextProperty(),
                   static_cast<int>(1.2 * font),
                   true);
        title->GetTextProperty()->SetJustificationToCentered();
        title->GetTextProperty()->SetVerticalJustificationToCentered();
        title->SetPosition(0.5 * width, height - 0.5 * title_px);
        view->GetRenderer()->AddActor2D(title);
      }

    // Linear axes get round ticks that fit the picture; log axes are left to
    // VTK.
    {
      double x0 = std::numeric_limits<double>::max(), x1 = -x0, yl = x0,
             yh = -x0;
      for (const auto &s : series)
        for (std::size_t i = 0; i < s.x.size(); ++i)
          {
            x0 = std::min(x0, s.x[i]);
            x1 = std::max(x1, s.x[i]);
            yl = std::min(yl, s.y[i]);
            yh = std::max(yh, s.y[i]);
          }
      const double label_font = 0.85 * font;
      const double plot_w     = width - 8.0 * font,
                   plot_h     = height - title_px - 5.0 * font;
      const double pad =
        points || markers ?
          0.02 :
          0.0; // room for whole markers at the ends of the axes
      std::array<double, 2> xr{std::log10(x0), std::log10(x1)},
        yr{std::log10(yl), std::log10(yh)};
      if (!logx)
        xr = set_linear_ticks(chart->GetAxis(vtkAxis::BOTTOM),
                              x0,
                              x1,
                              plot_w,
                              label_font,
                              true,
                              pad);
      if (!logy)
        yr = set_linear_ticks(chart->GetAxis(vtkAxis::LEFT),
                              yl,
                              yh,
                              plot_h,
                              label_font,
                              false,
                              pad);
      if (legend == "auto")
        {
          std::size_t widest = 0;
          for (const auto &l : labels)
            widest = std::max(widest, l.size());
          const double box_w = ((0.6 * widest + 4.0) * label_font) / plot_w;
          const double box_h = ((1.5 * n_series + 1.0) * label_font) / plot_h;
          if (!(xr[1] > xr[0]))
            xr = {xr[0] - 1.0, xr[0] + 1.0};
          if (!(yr[1] > yr[0]))
            yr = {yr[0] - 1.0, yr[0] + 1.0};
          legend = quietest_corner(series, xr, yr, logx, logy, box_w, box_h);
        }
    }

    const bool show_legend =
      legend != "none" && (n_series > 1 || a.has("--label"));
    chart->SetShowLegend(show_legend);
    if (show_legend)
      {
        vtkChartLegend *l = chart->GetLegend();
        l->SetLabelSize(static_cast<int>(0.85 * font));
        style_text(l->GetLabelProperties(), static_cast<int>(0.85 * font));
        l->SetHorizontalAlignment(legend.find("left") != std::string::npos ?
                                    vtkChartLegend::LEFT :
                                    vtkChartLegend::RIGHT);
        l->SetVerticalAlignment(legend.find("top") != std::string::npos ?
                                  vtkChartLegend::TOP :
                                  vtkChartLegend::BOTTOM);
        l->GetBrush()->SetColor(255, 255, 255, 230);
        l->GetPen()->SetColor(160, 160, 160, 255);
      }

    view->GetRenderWindow()->Render();
    write_png(view->GetRenderWindow(), out);
    return 0;
  }
} // namespace pdfem_plot
