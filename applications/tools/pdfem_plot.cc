// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot: PNG pictures of pdfem results (.vtu/.pvtu fields) and line charts
// of CSV files.
//
// A plain VTK program: it links neither deal.II nor the pdfem library, so it
// compiles in seconds and can be used on any machine that has VTK 9. VTK
// renders through X, so run it under `xvfb-run -a` on machines without a
// display. See doc/tools.md.
//
// This file: the help text and main(). The commands are in pdfem_plot_field.cc
// and pdfem_plot_chart.cc, what they share in pdfem_plot_common.cc and
// pdfem_plot_view.cc (declared in pdfem_plot.h).
#include "pdfem_plot.h"

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  const char *const help_text =
    R"(pdfem-plot: PNG pictures of pdfem results and line charts of CSV files.

Usage:
  pdfem-plot field FILE.vtu|FILE.pvtu --field NAME --out OUT.png [options]
  pdfem-plot chart FILE.csv --x COLUMN --y COL1[,COL2...] --out OUT.png [options]
  pdfem-plot --help

VTK renders through X. On a machine without a display (a server, a container, CI) run the tool
under a virtual X server:
  xvfb-run -a pdfem-plot field out/solution_00000.pvtu --field von_mises_stress --out vm.png

field: colour an unstructured grid (.vtu, or .pvtu from parallel runs) by one array.
  --field NAME          point (or, if there is no such point array, cell) array to show; a vector
                        array is shown as its magnitude unless --component is given. An unknown
                        NAME is reported with the list of arrays in the file
  --component K         show component K (0 = x, 1 = y, 2 = z, ...) of a vector array
  --warp FACTOR         draw the deformed shape: points moved by FACTOR x the point array
                        "displacement" (the colours stay those of --field)
  --range MIN MAX       colour range (default: the range of the data); values outside are clamped
  --colormap NAME       auto (default), coolwarm or viridis. auto: coolwarm (blue-white-red, white
                        at 0) when the range contains 0, viridis otherwise
  --title TEXT          title above the picture
  --size W H            picture size in pixels (default: 1000 wide and as high as a 2D model
                        needs; 1000 800 for 3D)
  --edges               draw the cell edges (thin dark lines)
  --zoom X0 X1 Y0 Y1    show this x/y window of a 2D model (coordinates after --warp)
  --lines FILE.vtk      draw the lines of a legacy VTK polydata file on top (thick black; e.g.
                        pdfem's crack_paths.vtk, drawn in the undeformed coordinates)
  --out OUT.png         the picture to write (required)
  2D models (all z equal) are seen from +z; 3D models in an isometric view from (+x,+y,+z),
  z up. The colour bar is drawn below the model.

chart: line chart of columns of comma-separated files with a header row (e.g. history.csv).
  --x COLUMN            column for the horizontal axis
  --y COL1[,COL2...]    columns to plot against it, one series each
  --csv2 FILE2.csv      a second file to overlay (e.g. a reference solution); its series are
                        drawn dashed (with larger crosses, on top, under --points), each series
                        in its own colour
  --y2 COLS             columns of FILE2.csv (default: the --y columns)
  --x2 COLUMN           x column of FILE2.csv (default: the --x column)
  --label L1,L2,...     legend entries, one per series, first file's series first
                        (default: column names, with the file names when --csv2 is given)
  --logx, --logy        logarithmic axes (values <= 0 are left out, with a warning)
  --xlabel T, --ylabel T  axis titles (default: the x column; the y column if there is one;
                        with the unit of pdfem's history.csv columns, e.g. "reaction_top_y [N]")
  --title T             chart title
  --legend POS          auto (default: the corner that hides the fewest data), top-right,
                        top-left, bottom-right, bottom-left or none
  --points              draw markers instead of lines
  --markers             draw lines with a marker at every point
  --size W H            picture size in pixels (default 1000 700)
  --out OUT.png         the picture to write (required)
  Numbers may be in any format std::stod reads (1, -2.5, 1e-3, inf, nan); empty cells and nan/inf
  values are left out. Lines starting with '#' are ignored.

Examples:
  xvfb-run -a pdfem-plot field out/solution_00000.pvtu --field stress_yy --warp 100 --edges \
      --title "Plate with a hole" --out stress_yy.png
  xvfb-run -a pdfem-plot field out/solution_00000.pvtu --field displacement --component 1 \
      --zoom -0.3 0.3 -0.3 0.3 --edges --out uy_zoom.png
  xvfb-run -a pdfem-plot chart out/history.csv --x load_factor --y reaction_right_x \
      --csv2 reference.csv --y2 force --label pdfem,reference --out force.png

Exit status: 0 on success, 2 for a bad command line (unknown option or value, missing input file,
unknown field or column), 1 if reading, rendering or writing fails.
)";
} // namespace

int
main(int argc, char **argv)
{
  using namespace pdfem_plot;
  const std::vector<std::string> args(argv + 1, argv + argc);
  try
    {
      if (args.empty())
        throw UsageError(
          "no command given; use 'pdfem-plot field ...' or 'pdfem-plot chart ...' (see pdfem-plot --help)");
      if (std::find_if(args.begin(), args.end(), [](const std::string &s) {
            return s == "--help" || s == "-h";
          }) != args.end())
        {
          std::cout << help_text;
          return 0;
        }
      const std::string             &command = args[0];
      const std::vector<std::string> rest(args.begin() + 1, args.end());
      if (command == "field")
        return run_field(rest);
      if (command == "chart")
        return run_chart(rest);
      throw UsageError("unknown command " + in_quotes(command) +
                       "; allowed: field, chart (see pdfem-plot --help)");
    }
  catch (const UsageError &e)
    {
      std::cerr << "pdfem-plot: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "pdfem-plot: error: " << e.what() << '\n';
      return 1;
    }
}
