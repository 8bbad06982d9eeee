// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-plot: the pieces its commands share: strings, the command line,
// writing PNGs, text style, the X display check and round axis ticks.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pdfem_plot.h"
#include <boost/algorithm/string/join.hpp>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#ifdef PDFEM_PLOT_WITH_X11
#  include <X11/Xlib.h> // last: it defines macros such as None and Status
#endif

namespace pdfem_plot
{
  namespace
  {
    std::string
    lower(std::string s)
    {
      for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }

    bool
    looks_like_option(const std::string &s)
    {
      // "--foo" is an option; "-1", "-.5" and "-" are values.
      return s.size() > 1 && s[0] == '-' &&
             !(std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.');
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
  } // namespace

  std::string &
  program_name()
  {
    static std::string name = "pdfem-plot";
    return name;
  }

  void
  warn(const std::string &message)
  {
    std::cerr << program_name() << ": warning: " << message << '\n';
  }

  std::string
  in_quotes(const std::string &s)
  {
    return "'" + s + "'";
  }

  std::string
  join(const std::vector<std::string> &items, const std::string &separator)
  {
    return boost::algorithm::join(items, separator);
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

  void
  style_text(vtkTextProperty *p, int font_size, bool bold)
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
        "virtual X server: xvfb-run -a " +
        program_name() + " ...");
#ifdef PDFEM_PLOT_WITH_X11
    Display *connection = XOpenDisplay(nullptr);
    if (connection == nullptr)
      throw RunError("cannot open the X display " + in_quotes(display) +
                     "; run the tool under a virtual X server: xvfb-run -a " +
                     program_name() + " ...");
    window->SetDisplayId(connection);
#else
    (void)window;
#endif
  }

  std::vector<double>
  ticks_inside(const double lo, const double hi, const double step)
  {
    std::vector<double> values;
    const double        eps = 1e-9 * (hi - lo);
    for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps;
         k += 1.0)
      values.push_back(k == 0.0 ? 0.0 : k * step);
    return values;
  }

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
} // namespace pdfem_plot
