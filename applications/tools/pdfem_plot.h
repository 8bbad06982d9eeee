// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to pdfem-plot and pdfem-render: what their pieces share (the strings,
// the command line and the rendering helpers of pdfem_plot_common.cc; the
// colours and camera of pdfem_plot_view.cc; the data side of field pictures in
// pdfem_plot_grid.cc and their drawing in pdfem_plot_picture.cc) and
// pdfem-plot's two commands.
#ifndef PDFEM_APPLICATIONS_TOOLS_PDFEM_PLOT_H
#define PDFEM_APPLICATIONS_TOOLS_PDFEM_PLOT_H

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkCamera;
class vtkDataArray;
class vtkDataSet;
class vtkFieldData;
class vtkLookupTable;
class vtkPointSet;
class vtkPolyData;
class vtkRenderWindow;
class vtkTextProperty;
class vtkUnstructuredGrid;

namespace pdfem_plot
{
  /// A bad command line: exit status 2.
  struct UsageError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };
  /// Anything else that goes wrong: exit status 1.
  struct RunError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  /// The program's name in messages: "pdfem-plot" unless main() changes it.
  std::string &
  program_name();

  /// "<program>: warning: message" on stderr.
  void
  warn(const std::string &message);

  /// s in single quotes, for messages.
  std::string
  in_quotes(const std::string &s);

  /// The items with separator between them.
  std::string
  join(const std::vector<std::string> &items,
       const std::string              &separator = ", ");

  /// The parts of s between separators (an empty last part after a trailing
  /// separator).
  std::vector<std::string>
  split(const std::string &s, char separator);

  /// s without leading and trailing white space.
  std::string
  trim(const std::string &s);

  /// Does s end in suffix (given in lower case), in any case?
  bool
  ends_with(const std::string &s, const std::string &suffix);

  /// Whole-string number parsing in the formats strtod (and so std::stod)
  /// accepts.
  bool
  parse_number(const std::string &text, double &value);

  // ------------------------------------------------------------------------------------------------
  // Command line
  // ------------------------------------------------------------------------------------------------

  /// An option a command accepts.
  struct OptionSpec
  {
    std::string name;     ///< "--range"
    std::string metavar;  ///< "MIN MAX"; empty for flags
    int         n_values; ///< how many values follow the option
  };

  /// A parsed command line.
  struct Arguments
  {
    std::string              command;    ///< the command, for messages
    std::vector<std::string> positional; ///< arguments that are no options
    std::map<std::string, std::vector<std::string>>
      options; ///< each option given, with its values

    /// Was option `name` given?
    bool
    has(const std::string &name) const
    {
      return options.count(name) != 0;
    }
    /// Value i of option `name` (which must have been given).
    const std::string &
    value(const std::string &name, std::size_t i = 0) const
    {
      return options.at(name).at(i);
    }
    /// The (first) value of option `name`, or fallback.
    std::string
    value_or(const std::string &name, const std::string &fallback) const
    {
      return has(name) ? value(name) : fallback;
    }
  };

  /// The options of args among specs and the rest (positional); UsageError
  /// for an unknown or repeated option or missing values.
  Arguments
  parse_arguments(const std::string              &command,
                  const std::vector<std::string> &args,
                  const std::vector<OptionSpec>  &specs);

  /// Value i of option name as a finite number (what: for the message).
  double
  number_option(const Arguments   &a,
                const std::string &name,
                std::size_t        i,
                const std::string &what);

  /// --size W H, or the defaults.
  std::array<int, 2>
  size_option(const Arguments &a, int default_w, int default_h);

  /// The one positional argument, a readable file (kinds: for the message).
  std::string
  input_file(const Arguments &a, const std::string &kinds);

  /// --out, a .png in an existing directory.
  std::string
  output_file(const Arguments &a);

  // ------------------------------------------------------------------------------------------------
  // Rendering helpers
  // ------------------------------------------------------------------------------------------------

  /// The window's picture as a PNG file (RunError if it cannot be written).
  void
  write_png(vtkRenderWindow *window, const std::string &file);

  /// Black text of font_size in DejaVu Sans when it is installed, else Arial.
  void
  style_text(vtkTextProperty *p, int font_size, bool bold = false);

  /// VTK renders through X and crashes when it cannot open the display: check
  /// first (RunError).
  void
  require_display(vtkRenderWindow *window);

  /// Round axis ticks: lo, lo + step, ..., hi.
  struct Ticks
  {
    double lo, hi, step;
  };

  /// Axis ticks at round values (1, 2 or 5 times a power of ten), at most
  /// max_intervals intervals, covering [lo, hi].
  Ticks
  nice_ticks(double lo, double hi, int max_intervals);

  /// The multiples of @p step inside [lo, hi] (its ends within 1e-9 of the
  /// range count as inside; 0 exactly 0): the labels of an axis or colour
  /// bar that must not reach past its data.
  std::vector<double>
  ticks_inside(double lo, double hi, double step);

  // ------------------------------------------------------------------------------------------------
  // Field pictures (pdfem_plot_view.cc)
  // ------------------------------------------------------------------------------------------------

  /// A 256-colour table on [lo, hi] for the colour map name (coolwarm or
  /// viridis).
  vtkSmartPointer<vtkLookupTable>
  make_lookup_table(const std::string &name, double lo, double hi);

  /// Parallel-projection camera looking from direction `from` (towards the
  /// centre of `bounds`), with the box bounds[0..5] filling the viewport of
  /// aspect ratio `aspect` (width/height) up to `margin`.
  void
  fit_camera(vtkCamera            *camera,
             const double          bounds[6],
             std::array<double, 3> from,
             std::array<double, 3> up,
             double                aspect,
             double                margin);

  /// Colour-bar labels: round values inside [lo, hi] that fit along a bar of
  /// length_px pixels, with lo and hi themselves where they fit when with_ends.
  std::vector<double>
  bar_labels(double lo,
             double hi,
             double length_px,
             double font_px,
             bool   with_ends = true);

  /// Decimals that tell round values `step` apart without an exponent (0 for
  /// step >= 1, 1 for 0.1 <= step < 1, ...).
  int
  decimals_for_step(double step);

  // ------------------------------------------------------------------------------------------------
  // The data of field pictures (pdfem_plot_grid.cc)
  // ------------------------------------------------------------------------------------------------

  /// A .vtu or .pvtu file; RunError with VTK's first message if it cannot be
  /// read.
  vtkSmartPointer<vtkUnstructuredGrid>
  read_grid(const std::string &file);

  /// "name (3 components), name, ..." or "none".
  std::string
  describe_arrays(vtkFieldData *data);

  /// The scalar a field picture is coloured by, added to the grid as its own
  /// array.
  struct FieldScalar
  {
    std::string name = "pdfem_plot_scalar"; ///< the added array
    std::string label; ///< "stress_xx", "displacement magnitude", ...
    bool        on_points = true;   ///< point array (else cell array)
    int         component = -1;     ///< -1: the magnitude of a vector
    double      lo = 0.0, hi = 0.0; ///< range of its finite values
  };

  /// The array `field` of grid (a point array, else a cell array; --component
  /// of a) as a FieldScalar. UsageError for an unknown field (listing the
  /// arrays of `file`) or component.
  FieldScalar
  add_field_scalar(vtkUnstructuredGrid *grid,
                   const std::string   &field,
                   const Arguments     &a,
                   const std::string   &file);

  /// Multiplies the scalar (and its range) by factor, e.g. 1e-6 for MPa.
  void
  scale_field_scalar(vtkUnstructuredGrid *grid, FieldScalar &s, double factor);

  /// The point array "displacement" (2 or 3 components); UsageError naming
  /// option and the arrays of `file` otherwise.
  vtkDataArray *
  displacement_array(vtkUnstructuredGrid *grid,
                     const std::string   &option,
                     const std::string   &file);

  /// The deformed shape: the points moved by factor x displacement.
  vtkSmartPointer<vtkPointSet>
  warp_by_displacement(vtkUnstructuredGrid *grid,
                       double               factor,
                       const std::string   &option,
                       const std::string   &file);

  /// Do all points have the same z (a 2D model)?
  bool
  is_flat(vtkDataSet *data);

  // ------------------------------------------------------------------------------------------------
  // Drawing field pictures (pdfem_plot_picture.cc)
  // ------------------------------------------------------------------------------------------------

  /// What a field picture shows. The defaults and the fields up to `lines`
  /// are pdfem-plot field's picture; `caption`, `outline` and `axes` are
  /// pdfem-render's additions.
  struct FieldPicture
  {
    vtkPointSet *model = nullptr;    ///< the shape to draw (maybe warped)
    FieldScalar  scalar;             ///< the array of model to colour by
    double       lo = 0.0, hi = 1.0; ///< colour range
    std::string  colormap = "auto";  ///< auto, coolwarm or viridis
    std::string  bar_title;          ///< above the colour bar
    /// pdfem-plot: labels "%.3g", with the ends of the range; pdfem-render:
    /// round values only, with as many decimals as their step needs.
    bool        bar_end_labels = true;
    std::string title;                      ///< empty: no title band
    std::string note;                       ///< small, top left of the bar band
    int         width = 1000, height = 800; ///< picture size [pixels]
    bool        auto_height = false;        ///< 2D: as high as the model needs
    bool        edges       = false;        ///< draw the cell edges
    std::optional<std::array<double, 4>> zoom;       ///< x0 x1 y0 y1 (2D)
    std::string                          lines_file; ///< legacy .vtk lines
    std::vector<std::string> caption; ///< parts of the line(s) under the title
    vtkPolyData *outline = nullptr;   ///< lines drawn on top with a halo
    bool         axes    = false;     ///< 2D: framed x/y axes; 3D: a triad
  };

  /// Draws p and writes it to `out` (PNG); returns its width and height.
  /// Needs an X display (RunError).
  std::array<int, 2>
  draw_field_picture(const FieldPicture &p, const std::string &out);

  // ------------------------------------------------------------------------------------------------
  // The commands
  // ------------------------------------------------------------------------------------------------

  /// pdfem-plot field ... (pdfem_plot_field.cc); returns the exit status.
  int
  run_field(const std::vector<std::string> &args);

  /// pdfem-plot chart ... (pdfem_plot_chart.cc); returns the exit status.
  int
  run_chart(const std::vector<std::string> &args);
} // namespace pdfem_plot

#endif
