// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to pdfem-plot: what its pieces share (the strings, the command line
// and the rendering helpers of pdfem_plot_common.cc; the colours and camera of
// pdfem_plot_view.cc) and its two commands.
#ifndef PDFEM_APPLICATIONS_TOOLS_PDFEM_PLOT_H
#define PDFEM_APPLICATIONS_TOOLS_PDFEM_PLOT_H

#include <array>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkCamera;
class vtkLookupTable;
class vtkRenderWindow;
class vtkTextProperty;

namespace pdfem_plot
{
  // A bad command line: exit status 2.
  struct UsageError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };
  // Anything else that goes wrong: exit status 1.
  struct RunError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  void
  warn(const std::string &message);

  std::string
  in_quotes(const std::string &s);

  std::string
  join(const std::vector<std::string> &items,
       const std::string              &separator = ", ");

  std::vector<std::string>
  split(const std::string &s, char separator);

  std::string
  trim(const std::string &s);

  // Does s end in suffix (given in lower case), in any case?
  bool
  ends_with(const std::string &s, const std::string &suffix);

  // Whole-string number parsing in the formats strtod (and so std::stod)
  // accepts.
  bool
  parse_number(const std::string &text, double &value);

  // ------------------------------------------------------------------------------------------------
  // Command line
  // ------------------------------------------------------------------------------------------------

  struct OptionSpec
  {
    std::string name;    // "--range"
    std::string metavar; // "MIN MAX"; empty for flags
    int         n_values;
  };

  struct Arguments
  {
    std::string                                     command;
    std::vector<std::string>                        positional;
    std::map<std::string, std::vector<std::string>> options;

    bool
    has(const std::string &name) const
    {
      return options.count(name) != 0;
    }
    const std::string &
    value(const std::string &name, std::size_t i = 0) const
    {
      return options.at(name).at(i);
    }
    std::string
    value_or(const std::string &name, const std::string &fallback) const
    {
      return has(name) ? value(name) : fallback;
    }
  };

  // The options of args among specs and the rest (positional); UsageError
  // for an unknown or repeated option or missing values.
  Arguments
  parse_arguments(const std::string              &command,
                  const std::vector<std::string> &args,
                  const std::vector<OptionSpec>  &specs);

  // Value i of option name as a finite number (what: for the message).
  double
  number_option(const Arguments   &a,
                const std::string &name,
                std::size_t        i,
                const std::string &what);

  // --size W H, or the defaults.
  std::array<int, 2>
  size_option(const Arguments &a, int default_w, int default_h);

  // The one positional argument, a readable file (kinds: for the message).
  std::string
  input_file(const Arguments &a, const std::string &kinds);

  // --out, a .png in an existing directory.
  std::string
  output_file(const Arguments &a);

  // ------------------------------------------------------------------------------------------------
  // Rendering helpers
  // ------------------------------------------------------------------------------------------------

  void
  write_png(vtkRenderWindow *window, const std::string &file);

  // Black text of font_size in DejaVu Sans when it is installed, else Arial.
  void
  style_text(vtkTextProperty *p, int font_size, bool bold = false);

  // VTK renders through X and crashes when it cannot open the display: check
  // first (RunError).
  void
  require_display(vtkRenderWindow *window);

  // Axis ticks at round values (1, 2 or 5 times a power of ten), at most
  // max_intervals intervals, covering [lo, hi].
  struct Ticks
  {
    double lo, hi, step;
  };

  Ticks
  nice_ticks(double lo, double hi, int max_intervals);

  // ------------------------------------------------------------------------------------------------
  // Field pictures (pdfem_plot_view.cc)
  // ------------------------------------------------------------------------------------------------

  // A 256-colour table on [lo, hi] for the colour map name (coolwarm or
  // viridis).
  vtkSmartPointer<vtkLookupTable>
  make_lookup_table(const std::string &name, double lo, double hi);

  // Parallel-projection camera looking from direction `from` (towards the
  // centre of `bounds`), with the box bounds[0..5] filling the viewport of
  // aspect ratio `aspect` (width/height) up to `margin`.
  void
  fit_camera(vtkCamera            *camera,
             const double          bounds[6],
             std::array<double, 3> from,
             std::array<double, 3> up,
             double                aspect,
             double                margin);

  // Colour-bar labels: round values inside [lo, hi] that fit along a bar of
  // length_px pixels.
  std::vector<double>
  bar_labels(double lo, double hi, double length_px, double font_px);

  // ------------------------------------------------------------------------------------------------
  // The commands
  // ------------------------------------------------------------------------------------------------

  // pdfem-plot field ... (pdfem_plot_field.cc); returns the exit status.
  int
  run_field(const std::vector<std::string> &args);

  // pdfem-plot chart ... (pdfem_plot_chart.cc); returns the exit status.
  int
  run_chart(const std::vector<std::string> &args);
} // namespace pdfem_plot

#endif
