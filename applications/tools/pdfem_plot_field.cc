// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot field: an unstructured grid (.vtu/.pvtu) coloured by one array,
// as a PNG.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

#include "pdfem_plot.h"
#include <vtkPointSet.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace pdfem_plot
{
  namespace
  {
    std::string
    format_number(double v)
    {
      std::ostringstream s;
      s.precision(4);
      s << v;
      return s.str();
    }
  } // namespace

  int
  run_field(const std::vector<std::string> &args)
  {
    const Arguments a =
      parse_arguments("field",
                      args,
                      {{"--field", "NAME", 1},
                       {"--component", "K", 1},
                       {"--warp", "FACTOR", 1},
                       {"--range", "MIN MAX", 2},
                       {"--colormap", "auto, coolwarm or viridis", 1},
                       {"--title", "TEXT", 1},
                       {"--size", "W H", 2},
                       {"--edges", "", 0},
                       {"--zoom", "X0 X1 Y0 Y1", 4},
                       {"--lines", "FILE.vtk", 1},
                       {"--out", "OUT.png", 1}});
    const std::string file = input_file(a, ".vtu or .pvtu");
    if (!ends_with(file, ".vtu") && !ends_with(file, ".pvtu"))
      throw UsageError("'field' reads .vtu or .pvtu files, got " +
                       in_quotes(file));
    if (!a.has("--field"))
      throw UsageError("'field' needs --field NAME (the array to colour by)");
    const std::string field = a.value("--field");
    const std::string out   = output_file(a);
    int               width = 1000, height = 800;
    if (a.has("--size"))
      {
        const auto size = size_option(a, width, height);
        width           = size[0];
        height          = size[1];
      }
    const std::string colormap = a.value_or("--colormap", "auto");
    if (colormap != "auto" && colormap != "coolwarm" && colormap != "viridis")
      throw UsageError("--colormap must be auto, coolwarm or viridis, got " +
                       in_quotes(colormap));
    double warp = 0.0;
    if (a.has("--warp"))
      warp = number_option(a, "--warp", 0, "a number FACTOR");
    std::array<double, 2> range{};
    if (a.has("--range"))
      {
        range = {number_option(a, "--range", 0, "two numbers MIN MAX"),
                 number_option(a, "--range", 1, "two numbers MIN MAX")};
        if (!(range[0] < range[1]))
          throw UsageError("--range needs MIN < MAX, got " +
                           a.value("--range", 0) + " " + a.value("--range", 1));
      }
    std::array<double, 4> zoom{};
    if (a.has("--zoom"))
      {
        for (std::size_t i = 0; i < 4; ++i)
          zoom[i] = number_option(a, "--zoom", i, "four numbers X0 X1 Y0 Y1");
        if (!(zoom[0] < zoom[1] && zoom[2] < zoom[3]))
          throw UsageError("--zoom needs X0 < X1 and Y0 < Y1, got " +
                           join(a.options.at("--zoom"), " "));
      }
    vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(file);
    const FieldScalar scalar = add_field_scalar(grid, field, a, file);
    double            lo = scalar.lo, hi = scalar.hi;
    if (a.has("--range"))
      {
        lo = range[0];
        hi = range[1];
      }
    else if (lo == hi)
      {
        const double pad = lo != 0.0 ? 0.01 * std::abs(lo) : 1.0;
        lo -= pad;
        hi += pad;
      }

    // Optionally deform.
    vtkSmartPointer<vtkPointSet> shown = grid;
    if (a.has("--warp"))
      shown = warp_by_displacement(grid, warp, "--warp", file);
    if (a.has("--zoom") && !is_flat(shown))
      throw UsageError("--zoom works on 2D models only; " + in_quotes(file) +
                       " is 3D");

    FieldPicture p;
    p.model     = shown;
    p.scalar    = scalar;
    p.lo        = lo;
    p.hi        = hi;
    p.colormap  = colormap;
    p.bar_title = scalar.label;
    p.title     = a.value_or("--title", "");
    if (a.has("--warp"))
      p.note = "displacement x " + format_number(warp);
    p.width       = width;
    p.height      = height;
    p.auto_height = !a.has("--size");
    p.edges       = a.has("--edges");
    if (a.has("--zoom"))
      p.zoom = zoom;
    p.lines_file = a.value_or("--lines", "");
    draw_field_picture(p, out);
    return 0;
  }
} // namespace pdfem_plot
