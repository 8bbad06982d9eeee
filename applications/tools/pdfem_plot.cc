// pdfem-plot: PNG pictures of pdfem results (.vtu/.pvtu fields) and line charts
// of CSV files.
//
// A plain VTK program: it links neither deal.II nor the pdfem library, so it
// compiles in seconds and can be used on any machine that has VTK 9. VTK
// renders through X, so run it under `xvfb-run -a` on machines without a
// display. See doc/tools.md.

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkChart.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkColorTransferFunction.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkCoordinate.h>
#include <vtkDataArray.h>
#include <vtkDataSetMapper.h>
#include <vtkDoubleArray.h>
#include <vtkLight.h>
#include <vtkLogger.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataReader.h>
#include <vtkProperty.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWarpVector.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#ifdef PDFEM_PLOT_WITH_X11
#  include <X11/Xlib.h> // last: it defines macros such as None and Status
#endif

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
                        drawn dashed (with crosses under --points) in the colours of the first file's
  --y2 COLS             columns of FILE2.csv (default: the --y columns)
  --x2 COLUMN           x column of FILE2.csv (default: the --x column)
  --label L1,L2,...     legend entries, one per series, first file's series first
                        (default: column names, with the file names when --csv2 is given)
  --logx, --logy        logarithmic axes (values <= 0 are left out, with a warning)
  --xlabel T, --ylabel T  axis titles (default: the x column; the y column if there is one)
  --title T             chart title
  --legend POS          auto (default: the corner that hides the fewest data), top-right,
                        top-left, bottom-right, bottom-left or none
  --points              draw markers instead of lines
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
  warn(const std::string &message)
  {
    std::cerr << "pdfem-plot: warning: " << message << '\n';
  }

  std::string
  in_quotes(const std::string &s)
  {
    return "'" + s + "'";
  }

  std::string
  join(const std::vector<std::string> &items,
       const std::string              &separator = ", ")
  {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i)
      out += (i ? separator : "") + items[i];
    return out;
  }

  std::vector<std::string>
  split(const std::string &s, char separator)
  {
    std::vector<std::string> parts;
    std::string              part;
    std::istringstream       in(s);
    while (std::getline(in, part, separator))
      parts.push_back(part);
    if (!s.empty() && s.back() == separator)
      parts.emplace_back();
    return parts;
  }

  std::string
  trim(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
      return "";
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
  }

  std::string
  lower(std::string s)
  {
    for (char &c : s)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }

  bool
  ends_with(const std::string &s, const std::string &suffix)
  {
    return s.size() >= suffix.size() &&
           lower(s.substr(s.size() - suffix.size())) == suffix;
  }

  // Whole-string number parsing in the formats strtod (and so std::stod)
  // accepts.
  bool
  parse_number(const std::string &text, double &value)
  {
    const std::string t = trim(text);
    if (t.empty())
      return false;
    char *end = nullptr;
    value     = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size();
  }

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

  bool
  looks_like_option(const std::string &s)
  {
    // "--foo" is an option; "-1", "-.5" and "-" are values.
    return s.size() > 1 && s[0] == '-' &&
           !(std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.');
  }

  Arguments
  parse_arguments(const std::string              &command,
                  const std::vector<std::string> &args,
                  const std::vector<OptionSpec>  &specs)
  {
    Arguments parsed;
    parsed.command = command;
    std::vector<std::string> allowed;
    for (const auto &spec : specs)
      allowed.push_back(spec.name);

    for (std::size_t i = 0; i < args.size(); ++i)
      {
        const std::string &arg = args[i];
        if (!looks_like_option(arg))
          {
            parsed.positional.push_back(arg);
            continue;
          }
        const auto spec =
          std::find_if(specs.begin(), specs.end(), [&](const OptionSpec &s) {
            return s.name == arg;
          });
        if (spec == specs.end())
          throw UsageError("unknown option " + in_quotes(arg) + " for '" +
                           command + "'; allowed: " + join(allowed));
        if (parsed.has(arg))
          throw UsageError("option " + arg + " is given twice");
        std::vector<std::string> values;
        for (int k = 0; k < spec->n_values; ++k)
          {
            if (i + 1 >= args.size() || (looks_like_option(args[i + 1]) &&
                                         args[i + 1].rfind("--", 0) == 0))
              throw UsageError(
                "option " + arg + " needs " + std::to_string(spec->n_values) +
                (spec->n_values == 1 ? " value (" : " values (") +
                spec->metavar + ")" +
                (i + 1 < args.size() ? ", got " + in_quotes(args[i + 1]) : ""));
            values.push_back(args[++i]);
          }
        parsed.options[arg] = values;
      }
    return parsed;
  }

  double
  number_option(const Arguments   &a,
                const std::string &name,
                std::size_t        i,
                const std::string &what)
  {
    double v;
    if (!parse_number(a.value(name, i), v) || !std::isfinite(v))
      throw UsageError(name + " needs " + what + ", got " +
                       in_quotes(a.value(name, i)));
    return v;
  }

  int
  integer_option(const Arguments   &a,
                 const std::string &name,
                 std::size_t        i,
                 int                lo,
                 int                hi,
                 const std::string &what)
  {
    double             v;
    const std::string &text = a.value(name, i);
    if (!parse_number(text, v) || v != std::floor(v) || v < lo || v > hi)
      throw UsageError(name + " needs " + what + " (an integer from " +
                       std::to_string(lo) + " to " + std::to_string(hi) +
                       "), got " + in_quotes(text));
    return static_cast<int>(v);
  }

  std::array<int, 2>
  size_option(const Arguments &a, int default_w, int default_h)
  {
    if (!a.has("--size"))
      return {default_w, default_h};
    return {integer_option(a, "--size", 0, 100, 8000, "a width W in pixels"),
            integer_option(a, "--size", 1, 100, 8000, "a height H in pixels")};
  }

  std::string
  input_file(const Arguments &a, const std::string &kinds)
  {
    if (a.positional.size() != 1)
      throw UsageError("'" + a.command + "' needs exactly one input file (" +
                       kinds + "), got " +
                       (a.positional.empty() ?
                          std::string("none") :
                          in_quotes(join(a.positional, " "))));
    const std::string &file = a.positional[0];
    std::error_code    ec;
    if (!std::filesystem::is_regular_file(file, ec) || !std::ifstream(file))
      throw UsageError("input file " + in_quotes(file) +
                       " does not exist or cannot be read");
    return file;
  }

  std::string
  output_file(const Arguments &a)
  {
    if (!a.has("--out"))
      throw UsageError("'" + a.command +
                       "' needs --out OUT.png (the picture to write)");
    const std::string &out = a.value("--out");
    if (!ends_with(out, ".png"))
      throw UsageError("--out needs a file name ending in .png, got " +
                       in_quotes(out));
    const std::filesystem::path dir = std::filesystem::path(out).parent_path();
    std::error_code             ec;
    if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
      throw UsageError("--out: directory " + in_quotes(dir.string()) +
                       " does not exist");
    return out;
  }

  // ------------------------------------------------------------------------------------------------
  // Rendering helpers
  // ------------------------------------------------------------------------------------------------

  void
  write_png(vtkRenderWindow *window, const std::string &file)
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->SetInputBufferTypeToRGB();
    grab->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputConnection(grab->GetOutputPort());
    writer->Write();
    if (writer->GetErrorCode() != 0)
      throw RunError("cannot write " + in_quotes(file));
  }

  // DejaVu Sans when it is installed (it has brackets, Greek letters,
  // superscripts, ...); VTK's built-in Arial otherwise.
  const std::string &
  font_file(bool bold)
  {
    static const std::string regular =
      "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    static const std::string bold_face =
      "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
    static const std::string none;
    const std::string       &file = bold ? bold_face : regular;
    std::error_code          ec;
    return std::filesystem::is_regular_file(file, ec) ? file : none;
  }

  void
  style_text(vtkTextProperty *p, int font_size, bool bold = false)
  {
    p->SetColor(0.0, 0.0, 0.0);
    const std::string &file = font_file(bold);
    if (file.empty())
      p->SetFontFamilyToArial();
    else
      {
        p->SetFontFamily(VTK_FONT_FILE);
        p->SetFontFile(file.c_str());
      }
    p->SetFontSize(font_size);
    p->SetBold(bold);
    p->SetItalic(false);
    p->SetShadow(false);
  }

  // Collects what VTK reports (instead of printing it) while it is the active
  // output window.
  class CapturingOutputWindow : public vtkOutputWindow
  {
  public:
    static CapturingOutputWindow *
    New()
    {
      auto *window = new CapturingOutputWindow;
      window->InitializeObjectBase();
      return window;
    }
    void
    DisplayText(const char *text) override
    {
      keep(text);
    }
    void
    DisplayErrorText(const char *text) override
    {
      keep(text);
    }
    void
    DisplayWarningText(const char *text) override
    {
      keep(text);
    }
    void
    DisplayGenericWarningText(const char *text) override
    {
      keep(text);
    }
    void
    DisplayDebugText(const char *) override
    {}

    // The first message, reduced to its text: VTK's messages read
    // "ERROR: In FILE, line N\nvtkClass (0x...): text"; pipeline failures that
    // only repeat an earlier error are skipped.
    std::string
    first_message() const
    {
      for (const auto &m : messages)
        {
          std::string line;
          for (const auto &l : split(m, '\n'))
            if (!trim(l).empty() && l.rfind("ERROR: In ", 0) != 0 &&
                l.rfind("Warning: In ", 0) != 0)
              {
                line = trim(l);
                break;
              }
          if (line.empty() ||
              line.find("returned failure for request") != std::string::npos)
            continue;
          if (const auto colon = line.find("): ");
              line.rfind("vtk", 0) == 0 && colon != std::string::npos)
            line = line.substr(colon + 3);
          return line;
        }
      return "";
    }
    std::vector<std::string> messages;

  private:
    void
    keep(const char *text)
    {
      if (text != nullptr)
        messages.emplace_back(text);
    }
  };

  // VTK renders through X and crashes when it cannot open the display: check
  // first. The connection opened for the check is handed on to the render
  // window (closing it could make Xvfb reset the server, refusing connections
  // for a moment); it is closed when the program ends.
  void
  require_display(vtkRenderWindow *window)
  {
    const char *display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0')
      throw RunError(
        "no X display (DISPLAY is not set); VTK renders through X, so run the tool under a "
        "virtual X server: xvfb-run -a pdfem-plot ...");
#ifdef PDFEM_PLOT_WITH_X11
    Display *connection = XOpenDisplay(nullptr);
    if (connection == nullptr)
      throw RunError(
        "cannot open the X display " + in_quotes(display) +
        "; run the tool under a virtual X server: xvfb-run -a pdfem-plot ...");
    window->SetDisplayId(connection);
#else
    (void)window;
#endif
  }

  // Axis ticks at round values (1, 2 or 5 times a power of ten), at most
  // max_intervals intervals, covering [lo, hi].
  struct Ticks
  {
    double lo, hi, step;
  };

  Ticks
  nice_ticks(double lo, double hi, int max_intervals)
  {
    if (!(hi > lo))
      {
        const double pad = lo != 0.0 ? 0.05 * std::abs(lo) : 1.0;
        lo -= pad;
        hi += pad;
      }
    const double power =
      std::pow(10.0, std::floor(std::log10((hi - lo) / max_intervals)));
    double step = 10.0 * power;
    for (double f : {1.0, 2.0, 5.0, 10.0})
      if (std::ceil(hi / (f * power) - 1e-9) -
            std::floor(lo / (f * power) + 1e-9) <=
          max_intervals)
        {
          step = f * power;
          break;
        }
    return {std::floor(lo / step + 1e-9) * step,
            std::ceil(hi / step - 1e-9) * step,
            step};
  }

  // ------------------------------------------------------------------------------------------------
  // field
  // ------------------------------------------------------------------------------------------------

  vtkSmartPointer<vtkUnstructuredGrid>
  read_grid(const std::string &file)
  {
    vtkSmartPointer<vtkXMLReader> reader;
    if (ends_with(file, ".pvtu"))
      reader = vtkSmartPointer<vtkXMLPUnstructuredGridReader>::New();
    else
      reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    // Catch VTK's own error output, so that a bad file gives one clear line.
    vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
    vtkNew<CapturingOutputWindow>    capture;
    vtkOutputWindow::SetInstance(capture);
    const vtkLogger::Verbosity verbosity =
      vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(
      vtkLogger::VERBOSITY_OFF); // VTK logs errors there as well
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkLogger::SetStderrVerbosity(verbosity);
    vtkOutputWindow::SetInstance(previous);
    auto *grid =
      vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (!capture->messages.empty() &&
        (grid == nullptr || grid->GetNumberOfPoints() == 0))
      throw RunError("cannot read " + in_quotes(file) + ": " +
                     capture->first_message());
    for (const auto &m :
         capture->messages) // the file was read, but VTK had something to say
      std::cerr << m;
    if (grid == nullptr || grid->GetNumberOfPoints() == 0)
      throw RunError("no points in " + in_quotes(file));
    vtkSmartPointer<vtkUnstructuredGrid> copy =
      vtkSmartPointer<vtkUnstructuredGrid>::New();
    copy->ShallowCopy(grid);
    return copy;
  }

  std::string
  describe_arrays(vtkFieldData *data)
  {
    std::vector<std::string> names;
    for (int i = 0; i < data->GetNumberOfArrays(); ++i)
      if (vtkDataArray *a = data->GetArray(i);
          a != nullptr && a->GetName() != nullptr)
        names.push_back(std::string(a->GetName()) +
                        (a->GetNumberOfComponents() > 1 ?
                           " (" + std::to_string(a->GetNumberOfComponents()) +
                             " components)" :
                           ""));
    return names.empty() ? "none" : join(names);
  }

  // Samples the colour map at t in [0, 1].
  using Colormap = std::function<std::array<double, 3>(double)>;

  Colormap
  viridis_map()
  {
    // The viridis colour map at t = 0, 0.1, ..., 1, interpolated linearly in
    // RGB.
    static const unsigned int stops[11] = {0x440154,
                                           0x482475,
                                           0x414487,
                                           0x355f8d,
                                           0x2a788e,
                                           0x21918c,
                                           0x22a884,
                                           0x44bf70,
                                           0x7ad151,
                                           0xbddf26,
                                           0xfde725};
    return [](double t) {
      t                       = std::clamp(t, 0.0, 1.0) * 10.0;
      const int             i = std::min(static_cast<int>(t), 9);
      const double          f = t - i;
      std::array<double, 3> rgb{};
      for (int c = 0; c < 3; ++c)
        {
          const int    shift = 16 - 8 * c;
          const double a     = ((stops[i] >> shift) & 0xff) / 255.0,
                       b     = ((stops[i + 1] >> shift) & 0xff) / 255.0;
          rgb[c]             = a + f * (b - a);
        }
      return rgb;
    };
  }

  Colormap
  coolwarm_map()
  {
    // Moreland's diverging "cool to warm" map, interpolated by VTK in its
    // diverging colour space.
    vtkSmartPointer<vtkColorTransferFunction> ctf =
      vtkSmartPointer<vtkColorTransferFunction>::New();
    ctf->SetColorSpaceToDiverging();
    ctf->AddRGBPoint(0.0, 0.230, 0.299, 0.754);
    ctf->AddRGBPoint(1.0, 0.706, 0.016, 0.150);
    return [ctf](double t) {
      std::array<double, 3> rgb{};
      ctf->GetColor(std::clamp(t, 0.0, 1.0), rgb.data());
      return rgb;
    };
  }

  // A 256-colour table on [lo, hi]. For coolwarm the white middle sits at 0
  // when the range contains 0 (so the sign of a value can be read off the
  // colour), else at the middle of the range.
  vtkSmartPointer<vtkLookupTable>
  make_lookup_table(const std::string &name, double lo, double hi)
  {
    const bool straddles_zero = lo < 0.0 && hi > 0.0;
    const bool coolwarm =
      name == "coolwarm" || (name == "auto" && straddles_zero);
    const Colormap map  = coolwarm ? coolwarm_map() : viridis_map();
    const double   half = std::max(std::abs(lo), std::abs(hi));

    const int n   = 256;
    auto      lut = vtkSmartPointer<vtkLookupTable>::New();
    lut->SetNumberOfTableValues(n);
    lut->SetTableRange(lo, hi);
    for (int i = 0; i < n; ++i)
      {
        const double v = lo + (i + 0.5) / n * (hi - lo);
        double       t = (i + 0.5) / n;
        if (coolwarm && straddles_zero)
          t = 0.5 + 0.5 * v / half;
        const auto rgb = map(t);
        lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
      }
    lut->SetNanColor(0.6, 0.6, 0.6, 1.0);
    return lut;
  }

  // Parallel-projection camera looking from direction `from` (towards the
  // centre of `bounds`), with the box bounds[0..5] filling the viewport of
  // aspect ratio `aspect` (width/height) up to `margin`.
  void
  fit_camera(vtkCamera            *camera,
             const double          bounds[6],
             std::array<double, 3> from,
             std::array<double, 3> up,
             double                aspect,
             double                margin)
  {
    auto dot = [](const std::array<double, 3> &a,
                  const std::array<double, 3> &b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    auto cross = [](const std::array<double, 3> &a,
                    const std::array<double, 3> &b) {
      return std::array<double, 3>{a[1] * b[2] - a[2] * b[1],
                                   a[2] * b[0] - a[0] * b[2],
                                   a[0] * b[1] - a[1] * b[0]};
    };
    auto normalize = [&](std::array<double, 3> a) {
      const double n = std::sqrt(dot(a, a));
      for (double &x : a)
        x /= n;
      return a;
    };
    from = normalize(from);
    const std::array<double, 3> view{-from[0], -from[1], -from[2]};
    const std::array<double, 3> right = normalize(cross(view, up));
    up                                = cross(right, view);

    const std::array<double, 3> centre{(bounds[0] + bounds[1]) / 2,
                                       (bounds[2] + bounds[3]) / 2,
                                       (bounds[4] + bounds[5]) / 2};
    double u0 = std::numeric_limits<double>::max(), u1 = -u0, v0 = u0, v1 = -u0;
    for (int corner = 0; corner < 8; ++corner)
      {
        const std::array<double, 3> p{bounds[corner & 1] - centre[0],
                                      bounds[2 + ((corner >> 1) & 1)] -
                                        centre[1],
                                      bounds[4 + ((corner >> 2) & 1)] -
                                        centre[2]};
        u0 = std::min(u0, dot(p, right));
        u1 = std::max(u1, dot(p, right));
        v0 = std::min(v0, dot(p, up));
        v1 = std::max(v1, dot(p, up));
      }
    std::array<double, 3> focal{};
    for (int c = 0; c < 3; ++c)
      focal[c] = centre[c] + right[c] * (u0 + u1) / 2 + up[c] * (v0 + v1) / 2;
    double scale = std::max((v1 - v0) / 2, (u1 - u0) / 2 / aspect) * margin;
    const double diagonal =
      std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
                (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
                (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    if (!(scale > 0))
      scale = diagonal > 0 ? diagonal / 2 : 1.0;
    const double distance = std::max(diagonal, scale) * 4 + 1.0;

    camera->ParallelProjectionOn();
    camera->SetFocalPoint(focal.data());
    camera->SetPosition(focal[0] + from[0] * distance,
                        focal[1] + from[1] * distance,
                        focal[2] + from[2] * distance);
    camera->SetViewUp(up.data());
    camera->SetParallelScale(scale);
  }

  // Colour-bar labels: round values (see nice_ticks) inside [lo, hi], as many
  // as fit along a bar of length_px pixels, plus lo and hi themselves where
  // they fit.
  std::vector<double>
  bar_labels(double lo, double hi, double length_px, double font_px)
  {
    auto text_px = [&](double v) {
      char text[64];
      std::snprintf(text, sizeof(text), "%.3g", v);
      return 0.62 * std::strlen(text) * font_px;
    };
    auto fits = [&](const std::vector<double> &values) {
      for (std::size_t i = 0; i + 1 < values.size(); ++i)
        if ((values[i + 1] - values[i]) / (hi - lo) * length_px <
            (text_px(values[i]) + text_px(values[i + 1])) / 2 + 1.5 * font_px)
          return false;
      return true;
    };
    for (int max_intervals = 8; max_intervals >= 1; --max_intervals)
      {
        const Ticks         t = nice_ticks(lo, hi, max_intervals);
        std::vector<double> values;
        const double        eps = 1e-9 * (hi - lo);
        for (double k = std::ceil((lo - eps) / t.step); k * t.step <= hi + eps;
             k += 1.0)
          values.push_back(k == 0.0 ? 0.0 : k * t.step);
        if (values.empty() || !fits(values))
          continue;
        if (values.front() - lo > eps)
          {
            values.insert(values.begin(), lo);
            if (!fits(values))
              values.erase(values.begin());
          }
        if (hi - values.back() > eps)
          {
            values.push_back(hi);
            if (!fits(values))
              values.pop_back();
          }
        if (values.size() >= 2)
          return values;
      }
    return {lo, hi};
  }

  std::string
  format_number(double v)
  {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
  }

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

    // Find the array: point data first, then cell data.
    bool          on_points = true;
    vtkDataArray *array     = grid->GetPointData()->GetArray(field.c_str());
    if (array == nullptr)
      {
        array     = grid->GetCellData()->GetArray(field.c_str());
        on_points = false;
      }
    if (array == nullptr)
      throw UsageError(
        "--field " + in_quotes(field) + " is not in " + in_quotes(file) +
        "; point arrays: " + describe_arrays(grid->GetPointData()) +
        "; cell arrays: " + describe_arrays(grid->GetCellData()));

    const int n_components = array->GetNumberOfComponents();
    int       component    = -1; // -1: magnitude
    if (a.has("--component"))
      {
        std::vector<std::string> allowed;
        for (int c = 0; c < n_components; ++c)
          allowed.push_back(std::to_string(c));
        double k;
        if (!parse_number(a.value("--component"), k) || k != std::floor(k) ||
            k < 0 || k >= n_components)
          throw UsageError(
            "--component for " + in_quotes(field) + " (" +
            std::to_string(n_components) +
            (n_components == 1 ? " component" : " components") + ") must be " +
            (n_components == 1 ? "0" : "one of " + join(allowed)) + ", got " +
            in_quotes(a.value("--component")));
        component = static_cast<int>(k);
      }
    else if (n_components == 1)
      component = 0;

    std::string label = field;
    if (n_components > 1)
      {
        if (component < 0)
          label = field + " magnitude";
        else if (n_components <= 3)
          label = field + " (" + std::string(1, "xyz"[component]) + ")";
        else
          label = field + " [" + std::to_string(component) + "]";
      }

    // The scalar to colour by, as its own array (so that the colour range is
    // easy to get right).
    const std::string      scalar_name = "pdfem_plot_scalar";
    vtkNew<vtkDoubleArray> scalar;
    scalar->SetName(scalar_name.c_str());
    scalar->SetNumberOfTuples(array->GetNumberOfTuples());
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      {
        double v = 0.0;
        if (component >= 0)
          v = array->GetComponent(i, component);
        else
          {
            for (int c = 0; c < n_components; ++c)
              v += array->GetComponent(i, c) * array->GetComponent(i, c);
            v = std::sqrt(v);
          }
        scalar->SetValue(i, v);
        if (std::isfinite(v))
          {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
      }
    if (lo > hi)
      throw RunError(in_quotes(field) + " in " + in_quotes(file) +
                     " has no finite values");
    if (on_points)
      grid->GetPointData()->AddArray(scalar);
    else
      grid->GetCellData()->AddArray(scalar);

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
      {
        vtkDataArray *u = grid->GetPointData()->GetArray("displacement");
        if (u == nullptr || u->GetNumberOfComponents() < 2 ||
            u->GetNumberOfComponents() > 3)
          throw UsageError(
            "--warp needs a point array 'displacement' with 2 or 3 components; " +
            in_quotes(file) +
            " has point arrays: " + describe_arrays(grid->GetPointData()));
        vtkNew<vtkDoubleArray> u3; // vtkWarpVector wants 3 components
        u3->SetName("pdfem_plot_displacement");
        u3->SetNumberOfComponents(3);
        u3->SetNumberOfTuples(u->GetNumberOfTuples());
        for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
          for (int c = 0; c < 3; ++c)
            u3->SetComponent(i,
                             c,
                             c < u->GetNumberOfComponents() ?
                               u->GetComponent(i, c) :
                               0.0);
        grid->GetPointData()->AddArray(u3);
        vtkNew<vtkWarpVector> warper;
        warper->SetInputData(grid);
        warper->SetInputArrayToProcess(0,
                                       0,
                                       0,
                                       vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                       "pdfem_plot_displacement");
        warper->SetScaleFactor(warp);
        warper->Update();
        shown = vtkPointSet::SafeDownCast(warper->GetOutputDataObject(0));
      }

    double bounds[6];
    shown->GetBounds(bounds);
    const double extent_xy =
      std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]);
    const bool is_2d =
      bounds[5] - bounds[4] <= 1e-9 * std::max(extent_xy, 1e-300);
    if (a.has("--zoom") && !is_2d)
      throw UsageError("--zoom works on 2D models only; " + in_quotes(file) +
                       " is 3D");

    // Layout (pixels): title band on top, colour bar band at the bottom, the
    // model in between. Without --size, a 2D model gets a picture 1000 pixels
    // wide and as high as its shape needs.
    const int font     = std::clamp(static_cast<int>(std::lround(
                                  std::sqrt(1.0 * width * height) / 45.0)),
                                12,
                                72);
    const int title_px = a.has("--title") ? static_cast<int>(2.4 * font) : 0;
    const int bar_px   = static_cast<int>(5.6 * font);
    if (is_2d && !a.has("--size"))
      {
        const double w =
          a.has("--zoom") ? zoom[1] - zoom[0] : bounds[1] - bounds[0];
        const double h =
          a.has("--zoom") ? zoom[3] - zoom[2] : bounds[3] - bounds[2];
        const double model_px = h > 0 && w > 0 ? width * h / w * 1.04 : width;
        height =
          static_cast<int>(std::clamp(model_px, 0.3 * width, 0.8 * width)) +
          title_px + bar_px;
      }
    const double title_frac = static_cast<double>(title_px) / height;
    const double bar_frac   = static_cast<double>(bar_px) / height;

    vtkNew<vtkRenderWindow> window;
    require_display(window);
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    // Multisampling smooths curved boundaries, but with --edges it leaves faint
    // seams along the diagonals of quadrilaterals (they are drawn as two
    // triangles): off in that case.
    window->SetMultiSamples(a.has("--edges") ? 0 : 8);

    auto lut = make_lookup_table(colormap, lo, hi);

    // The model.
    vtkNew<vtkDataSetMapper> mapper;
    mapper->SetInputData(shown);
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOn();
    if (on_points)
      mapper->SetScalarModeToUsePointFieldData();
    else
      mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(scalar_name.c_str());
    mapper->ScalarVisibilityOn();

    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    if (is_2d)
      {
        // Flat colours: exactly those of the colour bar.
        actor->GetProperty()->SetAmbient(1.0);
        actor->GetProperty()->SetDiffuse(0.0);
        actor->GetProperty()->SetSpecular(0.0);
      }
    else
      {
        actor->GetProperty()->SetAmbient(0.3);
        actor->GetProperty()->SetDiffuse(0.8);
        actor->GetProperty()->SetSpecular(0.0);
      }
    if (a.has("--edges"))
      {
        actor->GetProperty()->EdgeVisibilityOn();
        actor->GetProperty()->SetEdgeColor(0.15, 0.15, 0.15);
        actor->GetProperty()->SetLineWidth(1.0);
      }

    vtkNew<vtkRenderer> model;
    model->SetViewport(0.0, bar_frac, 1.0, 1.0 - title_frac);
    model->SetBackground(1.0, 1.0, 1.0);
    model->AddActor(actor);
    if (a.has("--lines"))
      {
        // Polylines on top (crack paths): lifted a little towards the
        // viewer so that they are not hidden in the model's plane.
        const std::string lines_file = a.options.at("--lines")[0];
        if (!std::filesystem::exists(lines_file))
          throw UsageError("--lines: the file " + in_quotes(lines_file) +
                           " does not exist");
        vtkNew<vtkPolyDataReader> lines_reader;
        lines_reader->SetFileName(lines_file.c_str());
        lines_reader->Update();
        vtkNew<vtkPolyDataMapper> lines_mapper;
        lines_mapper->SetInputConnection(lines_reader->GetOutputPort());
        lines_mapper->ScalarVisibilityOff();
        vtkNew<vtkActor> lines_actor;
        lines_actor->SetMapper(lines_mapper);
        lines_actor->GetProperty()->SetColor(0., 0., 0.);
        lines_actor->GetProperty()->SetLineWidth(3.0);
        if (is_2d)
          lines_actor->SetPosition(0., 0., 1e-3 * (bounds[1] - bounds[0]));
        model->AddActor(lines_actor);
      }
    window->AddRenderer(model);
    vtkNew<vtkLight> head_light, key_light;
    if (!is_2d)
      {
        // In an isometric view the three visible faces of a box are equally
        // inclined to the view direction, so a headlight alone shades them
        // alike: add a key light from the upper left.
        model->AutomaticLightCreationOff();
        head_light->SetLightTypeToCameraLight();
        head_light->SetPosition(0.0, 0.0, 1.0);
        head_light->SetFocalPoint(0.0, 0.0, 0.0);
        head_light->SetIntensity(0.7);
        key_light->SetLightTypeToCameraLight();
        key_light->SetPosition(-0.5, 1.0, 0.5);
        key_light->SetFocalPoint(0.0, 0.0, 0.0);
        key_light->SetIntensity(0.5);
        model->AddLight(head_light);
        model->AddLight(key_light);
      }

    const double model_aspect =
      width / std::max(1.0, height * (1.0 - bar_frac - title_frac));
    if (is_2d)
      {
        if (a.has("--zoom"))
          {
            const double box[6] = {
              zoom[0], zoom[1], zoom[2], zoom[3], bounds[4], bounds[5]};
            fit_camera(model->GetActiveCamera(),
                       box,
                       {0, 0, 1},
                       {0, 1, 0},
                       model_aspect,
                       1.0);
          }
        else
          fit_camera(model->GetActiveCamera(),
                     bounds,
                     {0, 0, 1},
                     {0, 1, 0},
                     model_aspect,
                     1.04);
      }
    else
      fit_camera(model->GetActiveCamera(),
                 bounds,
                 {1, 1, 1},
                 {0, 0, 1},
                 model_aspect,
                 1.06);
    model->ResetCameraClippingRange();

    // The colour bar, horizontal, in its own band: its title above, the numbers
    // below.
    vtkNew<vtkRenderer> bar_renderer;
    bar_renderer->SetViewport(0.0, 0.0, 1.0, bar_frac);
    bar_renderer->SetBackground(1.0, 1.0, 1.0);
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetOrientationToHorizontal();
    vtkNew<vtkDoubleArray> bar_values;
    for (double v : bar_labels(lo, hi, 0.7 * width, 0.85 * font))
      bar_values->InsertNextValue(v);
    bar->SetCustomLabels(bar_values);
    bar->SetUseCustomLabels(true);
    bar->SetLabelFormat("%.3g");
    bar->SetMaximumNumberOfColors(256);
    bar->UnconstrainedFontSizeOn();
    bar->SetTextPositionToPrecedeScalarBar();
    style_text(bar->GetLabelTextProperty(), static_cast<int>(0.85 * font));
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(0.15, 0.04);
    bar->SetWidth(0.7);
    bar->SetHeight(0.6);
    bar->SetBarRatio(0.45);
    bar_renderer->AddActor2D(bar);
    vtkNew<vtkTextActor> bar_title;
    bar_title->SetInput(label.c_str());
    style_text(bar_title->GetTextProperty(), font);
    bar_title->GetTextProperty()->SetJustificationToCentered();
    bar_title->GetTextProperty()->SetVerticalJustificationToCentered();
    bar_title->GetPositionCoordinate()
      ->SetCoordinateSystemToNormalizedViewport();
    bar_title->GetPositionCoordinate()->SetValue(0.5, 0.8);
    bar_renderer->AddActor2D(bar_title);
    vtkNew<vtkTextActor> warp_note;
    if (a.has("--warp"))
      {
        warp_note->SetInput(("displacement x " + format_number(warp)).c_str());
        style_text(warp_note->GetTextProperty(),
                   std::max(10, static_cast<int>(0.75 * font)));
        warp_note->GetTextProperty()->SetColor(0.3, 0.3, 0.3);
        warp_note->GetTextProperty()->SetVerticalJustificationToTop();
        warp_note->SetPosition(0.5 * font, bar_px - 0.4 * font);
        bar_renderer->AddActor2D(warp_note);
      }
    window->AddRenderer(bar_renderer);

    if (a.has("--title"))
      {
        vtkNew<vtkRenderer> title_renderer;
        title_renderer->SetViewport(0.0, 1.0 - title_frac, 1.0, 1.0);
        title_renderer->SetBackground(1.0, 1.0, 1.0);
        vtkNew<vtkTextActor> title;
        title->SetInput(a.value("--title").c_str());
        style_text(title->GetTextProperty(),
                   static_cast<int>(1.3 * font),
                   true);
        title->GetTextProperty()->SetJustificationToCentered();
        title->GetTextProperty()->SetVerticalJustificationToCentered();
        title->GetPositionCoordinate()
          ->SetCoordinateSystemToNormalizedViewport();
        title->GetPositionCoordinate()->SetValue(0.5, 0.45);
        title_renderer->AddActor2D(title);
        window->AddRenderer(title_renderer);
      }

    window->Render();
    write_png(window, out);
    return 0;
  }

  // ------------------------------------------------------------------------------------------------
  // chart
  // ------------------------------------------------------------------------------------------------

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
              << std::setprecision(std::max(0, exponent - step_exponent)) << v;
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
      const bool right = u > 1.0 - box_w, left = u<box_w, top = v> 1.0 - box_h,
                 bottom = v < box_h;
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
                if (logx || logy) // interpolate where the line is straight: in
                                  // the plotted coordinates
                  {
                    const double x = logx ?
                                       std::pow(10.0,
                                                std::log10(s.x[i]) +
                                                  f * (std::log10(s.x[i + 1]) -
                                                       std::log10(s.x[i]))) :
                                       s.x[i] + f * (s.x[i + 1] - s.x[i]);
                    const double y = logy ?
                                       std::pow(10.0,
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
        series.back().colour           = static_cast<int>(i);
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
        vtkPlot *plot = chart->AddPlot(
          points || s.x.size() == 1 ? vtkChart::POINTS : vtkChart::LINE);
        plot->SetInputData(table, 0, 1);
        plot->SetLabel(s.label);
        const unsigned char *rgb = palette[s.colour % n_palette];
        plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
        plot->SetWidth(points ? 1.5f : 2.5f);
        if (auto *pp = vtkPlotPoints::SafeDownCast(plot))
          {
            if (points || s.x.size() == 1)
              {
                pp->SetMarkerStyle(s.from_second_file ? vtkPlotPoints::CROSS :
                                                        vtkPlotPoints::CIRCLE);
                pp->SetMarkerSize(std::max(6.0f, font * 0.5f));
              }
            else
              pp->SetMarkerStyle(vtkPlotPoints::NONE);
          }
        if (s.from_second_file && !points)
          plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
      }

    auto style_axis = [&](vtkAxis *axis, const std::string &title, bool log) {
      axis->SetTitle(title);
      style_text(axis->GetTitleProperties(), font);
      style_text(axis->GetLabelProperties(), static_cast<int>(0.85 * font));
      axis->GetPen()->SetColor(0, 0, 0, 255);
      axis->GetGridPen()->SetColor(220, 220, 220, 255);
      axis->SetLogScale(log);
    };
    std::string ylabel;
    {
      std::vector<std::string> all = y1names;
      all.insert(all.end(), y2names.begin(), y2names.end());
      if (std::all_of(all.begin(), all.end(), [&](const std::string &n) {
            return n == all.front();
          }))
        ylabel = all.front();
    }
    style_axis(chart->GetAxis(vtkAxis::BOTTOM),
               a.value_or("--xlabel", xname),
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
        points ? 0.02 : 0.0; // room for whole markers at the ends of the axes
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

} // namespace

int
main(int argc, char **argv)
{
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
