// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-render: a picture of one pdfem result a paper could print: one field
// on the deformed shape with the cracks open, a colour bar with the field's
// unit, coordinate axes and the outline of the PD region.
//
// Built from pdfem-plot's pieces (pdfem_plot.h: reading, the scalar, colour
// maps, camera and drawing) plus pdfem_render_data.cc (pdfem_render.h). A plain
// VTK program; VTK renders through X, so run it under `xvfb-run -a` on
// machines without a display. See doc/tools.md.
#include "pdfem_render.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "pdfem_plot.h"
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

namespace
{
  using namespace pdfem_plot;
  using namespace pdfem_render;

  const char *const help_text =
    R"(pdfem-render: a picture of one field of a pdfem result, as a paper could print it.

Usage:
  pdfem-render RESULT.pvd|FILE.pvtu|FILE.vtu --field NAME -o OUT.png [options]
  pdfem-render --help

The picture shows the field on the deformed shape, with the cracks open (cells whose cell array
"cracked" is 1 are left out, so a crack shows as a gap), the outline of the PD region (cell
array "pd_region" = 1) as a black line, a colour bar titled with the field and its unit, and
coordinate axes (x [m], y [m]) around a 2D model or an x-y-z triad beside a 3D one. What it
did (dataset, range, warp factor, cracked cells, colour-bar title) is printed on stdout.

Options:
  --field NAME        point (else cell) array to show, e.g. von_mises_stress, stress_xx, damage,
                      displacement (a vector: its magnitude unless --component K), pd_region.
                      An unknown NAME is reported with the list of the file's arrays
  --component K       component K (0 = x, 1 = y, 2 = z) of a vector array
  --step N            which dataset of a .pvd: 0-based, negative counts from the end
                      (default -1, the last). A .vtu/.pvtu is one dataset
  --warp FACTOR       points moved by FACTOR x displacement; 0: the undeformed shape.
                      Default: automatic, a round factor (1, 2, 2.5 or 5 times a power of ten,
                      at least 1) that makes the largest displacement 5-10 % of the model size
  --range MIN MAX     colour range in the file's units (Pa, m, ...); default: the data's range
                      ([0, 1] for damage)
  --colormap NAME     auto (default: coolwarm, white at 0, when the range has both signs and
                      the smaller side is at least 5 % of the larger; else viridis), coolwarm
                      or viridis
  --title TEXT        title above the picture
  --size W H          picture size in pixels (default: 1200 wide and as high as a 2D model
                      needs; 1200 900 for 3D)
  --edges             draw the cell edges
  --zoom X0 X1 Y0 Y1  show this x/y window of a 2D model (coordinates of the drawn shape)
  -o, --out OUT.png   the picture to write (required)

Units: displacement [m], stress_*, *_stress [Pa], damage, pd_region, node_kind, material_id,
rank, cracked [-]; stresses and displacements get the prefix (kPa, MPa, GPa; mm, µm, nm) that
keeps the colour-bar numbers between 1 and 1000.

Example:
  xvfb-run -a pdfem-render output-plate_with_hole/solution.pvd --field von_mises_stress \
      -o picture.png

Exit status: 0 on success; 2 for a bad command line (unknown option or field, step out of range,
missing input file), with one line naming the option or file and what is allowed; 1 if reading,
rendering or writing fails (e.g. no X display).
)";

  std::string
  g3(double v)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.3g", v);
    return text;
  }

  // v with (up to) 3 significant digits and no exponent where that stays
  // short (for the picture: "1", "21.5", "-0.579", "0.00123").
  std::string
  s3(double v)
  {
    if (v == 0.0 || !std::isfinite(v) || std::abs(v) < 1e-4 ||
        std::abs(v) >= 1e6)
      return g3(v);
    return fixed_trimmed(
      v,
      std::max(0, 2 - static_cast<int>(std::floor(std::log10(std::abs(v))))));
  }

  int
  run(std::vector<std::string> args)
  {
    for (auto &arg : args)
      if (arg == "-o")
        arg = "--out";
    const Arguments a =
      parse_arguments("pdfem-render",
                      args,
                      {{"--field", "NAME", 1},
                       {"--component", "K", 1},
                       {"--step", "N", 1},
                       {"--warp", "FACTOR", 1},
                       {"--range", "MIN MAX", 2},
                       {"--colormap", "auto, coolwarm or viridis", 1},
                       {"--title", "TEXT", 1},
                       {"--size", "W H", 2},
                       {"--edges", "", 0},
                       {"--zoom", "X0 X1 Y0 Y1", 4},
                       {"--out", "OUT.png", 1}});
    const std::string input = input_file(a, ".pvd, .pvtu or .vtu");
    if (!ends_with(input, ".pvd") && !ends_with(input, ".vtu") &&
        !ends_with(input, ".pvtu"))
      throw UsageError(
        "the input file must be a .pvd, .pvtu or .vtu file, got " +
        in_quotes(input));
    const std::string out      = output_file(a);
    const std::string colormap = a.value_or("--colormap", "auto");
    if (colormap != "auto" && colormap != "coolwarm" && colormap != "viridis")
      throw UsageError("--colormap must be auto, coolwarm or viridis, got " +
                       in_quotes(colormap));
    std::optional<std::array<double, 2>> range;
    if (a.has("--range"))
      {
        range = {number_option(a, "--range", 0, "two numbers MIN MAX"),
                 number_option(a, "--range", 1, "two numbers MIN MAX")};
        if (!((*range)[0] < (*range)[1]))
          throw UsageError("--range needs MIN < MAX, got " +
                           a.value("--range", 0) + " " + a.value("--range", 1));
      }
    std::optional<double> warp;
    if (a.has("--warp"))
      {
        warp = number_option(a, "--warp", 0, "a number FACTOR (0: undeformed)");
        if (*warp < 0)
          throw UsageError("--warp needs a FACTOR >= 0, got " +
                           in_quotes(a.value("--warp")));
      }
    const auto                           size = size_option(a, 1200, 900);
    std::optional<std::array<double, 4>> zoom;
    if (a.has("--zoom"))
      {
        zoom.emplace();
        for (std::size_t i = 0; i < 4; ++i)
          (*zoom)[i] =
            number_option(a, "--zoom", i, "four numbers X0 X1 Y0 Y1");
        if (!((*zoom)[0] < (*zoom)[1] && (*zoom)[2] < (*zoom)[3]))
          throw UsageError("--zoom needs X0 < X1 and Y0 < Y1, got " +
                           join(a.options.at("--zoom"), " "));
      }

    // The dataset.
    const std::vector<Dataset> datasets = datasets_of(input);
    const std::size_t          step =
      pick_step(a.value_or("--step", "-1"), datasets.size(), input);
    const Dataset  &dataset = datasets[step];
    std::error_code ec;
    if (!std::filesystem::is_regular_file(dataset.file, ec))
      throw UsageError("dataset " + std::to_string(step) + " of " +
                       in_quotes(input) + ", " + in_quotes(dataset.file) +
                       ", does not exist");
    if (!ends_with(dataset.file, ".vtu") && !ends_with(dataset.file, ".pvtu"))
      throw RunError("dataset " + std::to_string(step) + " of " +
                     in_quotes(input) + ", " + in_quotes(dataset.file) +
                     ", is not a .vtu or .pvtu file");
    vtkSmartPointer<vtkUnstructuredGrid> grid = read_grid(dataset.file);
    if (!a.has("--field"))
      throw UsageError(
        "--field NAME is required; arrays of " + in_quotes(dataset.file) +
        ": point arrays: " + describe_arrays(grid->GetPointData()) +
        "; cell arrays: " + describe_arrays(grid->GetCellData()));
    const std::string field = a.value("--field");
    std::cout << "input: " << dataset.file;
    if (ends_with(input, ".pvd"))
      std::cout << " (step " << step << " of 0.." << datasets.size() - 1
                << (dataset.time ? ", time " + g3(*dataset.time) : "") << ")";
    std::cout << '\n';

    // The field, in a unit that keeps its numbers between 1 and 1000.
    FieldScalar scalar = add_field_scalar(grid, field, a, dataset.file);
    std::cout << "field: " << scalar.label << " ("
              << (scalar.on_points ? "point" : "cell") << " array), "
              << g3(scalar.lo) << " .. " << g3(scalar.hi);
    double lo = scalar.lo, hi = scalar.hi;
    if (range)
      {
        lo = (*range)[0];
        hi = (*range)[1];
      }
    else if (field == "damage" && lo >= 0.0 && hi <= 1.0)
      {
        lo = 0.0;
        hi = 1.0;
      }
    const Unit unit = unit_of(field, std::max(std::abs(lo), std::abs(hi)));
    std::cout << (unit.base.empty() || unit.base == "-" ? "" : " " + unit.base)
              << '\n';
    if (unit.factor != 1.0)
      {
        scale_field_scalar(grid, scalar, unit.factor);
        lo *= unit.factor;
        hi *= unit.factor;
      }
    if (lo == hi)
      {
        const double pad = lo != 0.0 ? 0.01 * std::abs(lo) : 1.0;
        lo -= pad;
        hi += pad;
      }
    std::cout << "colour range: " << g3(lo) << " .. " << g3(hi)
              << (unit.symbol.empty() ? "" : " " + unit.symbol)
              << (range ? " (--range)" : "") << '\n';
    // auto: the diverging map when the range has both signs in earnest, so
    // that a few slightly negative values do not wash out the picture.
    std::string map = colormap;
    if (map == "auto")
      map = lo < 0 && hi > 0 && std::min(-lo, hi) >= 0.05 * std::max(-lo, hi) ?
              "coolwarm" :
              "viridis";
    std::cout << "colour map: " << map << (colormap == "auto" ? " (auto)" : "")
              << '\n';

    // The deformed shape.
    std::string warp_caption;
    double      factor = 0.0;
    if (warp)
      {
        factor = *warp;
        if (factor > 0)
          displacement_array(grid, "--warp", dataset.file);
        std::cout << "warp: " << plain_number(factor) << " (--warp)\n";
      }
    else
      {
        const AutoWarp w = auto_warp(grid);
        factor           = w.factor;
        if (!w.has_displacement)
          std::cout << "warp: none (no point array 'displacement')\n";
        else if (factor == 0.0)
          std::cout << "warp: none (the displacement is 0)\n";
        else
          std::cout << "warp: " << plain_number(factor)
                    << " (automatic: the largest displacement, "
                    << g3(w.largest) << " m, is "
                    << g3(100 * factor * w.largest / w.model_size)
                    << " % of the model size " << g3(w.model_size) << " m)\n";
      }
    vtkSmartPointer<vtkPointSet> warped = grid;
    if (factor > 0)
      {
        warped = warp_by_displacement(grid, factor, "--warp", dataset.file);
        warp_caption = factor == 1.0 ?
                         "deformed shape (true scale)" :
                         "displacement \u00d7 " + plain_number(factor);
      }
    else
      warp_caption = "undeformed shape";
    const bool is_2d = is_flat(grid);
    if (zoom && !is_2d)
      throw UsageError("--zoom works on 2D models only; " +
                       in_quotes(dataset.file) + " is 3D");

    // Cracks as gaps, the PD region's outline.
    long                         n_cracked = 0, n_pd = 0;
    vtkSmartPointer<vtkPointSet> shown =
      without_cracked_cells(warped, n_cracked);
    const long n_cells = grid->GetNumberOfCells();
    if (n_cracked == n_cells && n_cells > 0)
      shown = warped; // nothing would be left to draw
    if (n_cracked < 0)
      std::cout
        << "cracks: no cell array 'cracked' in " << in_quotes(dataset.file)
        << " (pdfem writes it since 2026-11-25): cracks are not shown as gaps\n";
    else
      std::cout << "cracks: " << n_cracked << " of " << n_cells
                << " cells cracked"
                << (n_cracked == 0  ? "" :
                    shown == warped ? " (all: drawn all the same, no gaps)" :
                                      ", left out (gaps)")
                << '\n';
    vtkSmartPointer<vtkPolyData> outline = pd_outline(warped, is_2d, n_pd);
    if (outline == nullptr)
      std::cout << "PD region: no cell array 'pd_region'\n";
    else
      std::cout << "PD region: " << n_pd << " of " << n_cells << " cells"
                << (outline->GetNumberOfLines() > 0 ? ", outlined" : "")
                << '\n';

    // The picture.
    FieldPicture p;
    p.model          = shown;
    p.scalar         = scalar;
    p.lo             = lo;
    p.hi             = hi;
    p.colormap       = map;
    p.bar_title      = with_unit(scalar.label, unit);
    p.bar_end_labels = false;
    p.title          = a.value_or("--title", "");
    std::vector<std::string> caption;
    if (dataset.time)
      caption.push_back("t = " + s3(*dataset.time));
    caption.push_back(warp_caption);
    caption.push_back(
      scalar.label + " " + s3(scalar.lo) + " \u2026 " + s3(scalar.hi) +
      (unit.symbol.empty() || unit.symbol == "-" ? "" : " " + unit.symbol));
    if (outline != nullptr && outline->GetNumberOfLines() > 0)
      caption.push_back("black line: PD region");
    if (n_cracked > 0 && shown != warped)
      caption.push_back("gaps: cracked cells");
    p.caption     = caption;
    p.width       = size[0];
    p.height      = size[1]; // without --size in 2D: sets the font size only
    p.auto_height = is_2d && !a.has("--size");
    p.edges       = a.has("--edges");
    p.zoom        = zoom;
    p.outline     = outline != nullptr && outline->GetNumberOfLines() > 0 ?
                      outline.GetPointer() :
                      nullptr;
    p.axes        = true;
    std::cout << "colour bar: " << p.bar_title << '\n';
    std::cout << "caption: " << join(caption, "; ") << '\n';
    const auto drawn = draw_field_picture(p, out);
    std::cout << "picture: " << out << " (" << drawn[0] << " x " << drawn[1]
              << " pixels)\n";
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  pdfem_plot::program_name() = "pdfem-render";
  const std::vector<std::string> args(argv + 1, argv + argc);
  try
    {
      if (std::find_if(args.begin(), args.end(), [](const std::string &s) {
            return s == "--help" || s == "-h";
          }) != args.end())
        {
          std::cout << help_text;
          return 0;
        }
      return run(args);
    }
  catch (const pdfem_plot::UsageError &e)
    {
      std::cerr << "pdfem-render: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "pdfem-render: error: " << e.what() << '\n';
      return 1;
    }
}
