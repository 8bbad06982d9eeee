// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-study: the command line and the grid of runs it spans.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "pdfem_study.h"

namespace pdfem_study
{
  namespace
  {
    const char *const allowed_options =
      "(allowed: SCENE.prm, --vary PATH=V1,V2,..., --output KEY, "
      "--reference VALUE|run:\"PATH=V;...\", --set PATH=VALUE, -o DIR, "
      "--no-chart, --mpiexec PROGRAM, --help)";

    std::string
    trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t");
      if (b == std::string::npos)
        return "";
      const auto e = s.find_last_not_of(" \t");
      return s.substr(b, e - b + 1);
    }

    /// A whole string as a finite number, or NaN.
    double
    to_number(const std::string &text)
    {
      const std::string t = trim(text);
      if (t.empty())
        return missing;
      char *end      = nullptr;
      errno          = 0;
      const double x = std::strtod(t.c_str(), &end);
      if (*end != '\0' || errno == ERANGE || !std::isfinite(x))
        return missing;
      return x;
    }

    /// "A/B=v1;C/D=v2": split at each ';' that starts a new "Path=" (a
    /// value such as a Dirichlet list may hold ';' itself).
    std::vector<Override>
    parse_override_list(const std::string &text, const std::string &option)
    {
      std::vector<std::string> parts;
      std::size_t              start = 0;
      for (std::size_t i = 0; i <= text.size(); ++i)
        {
          if (i < text.size() && text[i] != ';')
            continue;
          bool new_part = i == text.size();
          if (!new_part)
            {
              // The text after ';' up to the next '=' or ';' names a path.
              const std::string next = text.substr(i + 1);
              const auto        stop = next.find_first_of("=;");
              const std::string name = trim(next.substr(0, stop));
              new_part = stop != std::string::npos && next[stop] == '=' &&
                         name.find('/') != std::string::npos &&
                         std::isalpha(static_cast<unsigned char>(name[0]));
            }
          if (new_part)
            {
              parts.push_back(text.substr(start, i - start));
              start = i + 1;
            }
        }
      std::vector<Override> out;
      for (const auto &part : parts)
        if (!trim(part).empty())
          out.push_back(parse_assignment(trim(part), option));
      if (out.empty())
        throw UsageError(option + ": no override given (allowed: run:\"" +
                         "Section/Entry=value[;Section/Entry=value...]\", "
                         "e.g. run:\"Mesh/Global refinements=2\")");
      return out;
    }

    /// The value after an option, or a UsageError naming what it needs.
    std::string
    value_of(int &i, int argc, char **argv, const std::string &needs)
    {
      const std::string option = argv[i];
      if (i + 1 >= argc)
        throw UsageError(option + " needs " + needs);
      return argv[++i];
    }
  } // namespace

  Override
  parse_assignment(const std::string &text, const std::string &option)
  {
    const auto eq = text.find('=');
    if (eq == std::string::npos || trim(text.substr(0, eq)).empty() ||
        trim(text.substr(eq + 1)).empty())
      throw UsageError(option + " '" + text +
                       "': expected Section/Entry=value (allowed: e.g. "
                       "\"Mesh/Global refinements=1\")");
    return {trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
  }

  std::string
  scene_name(const std::string &file)
  {
    return std::filesystem::path(file).stem().string();
  }

  Options
  parse_command_line(int argc, char **argv, bool &help)
  {
    Options options;
    help               = false;
    bool reference_run = false;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          {
            help = true;
            return options;
          }
        if (arg == "--vary")
          {
            const std::string text =
              value_of(i,
                       argc,
                       argv,
                       "PATH=V1,V2,... (e.g. --vary "
                       "\"Peridynamics/Horizon factor=3,4\")");
            const Override a = parse_assignment(text, "--vary");
            Vary           vary{a.first, {}};
            std::string    item;
            for (std::size_t k = 0; k <= a.second.size(); ++k)
              if (k == a.second.size() || a.second[k] == ',')
                {
                  if (trim(item).empty())
                    throw UsageError(
                      "--vary '" + text +
                      "': an empty value (allowed: PATH=V1,V2,... with "
                      "values separated by single commas)");
                  vary.values.push_back(trim(item));
                  item.clear();
                }
              else
                item += a.second[k];
            if (vary.path != ranks_parameter &&
                vary.path.find('/') == std::string::npos)
              throw UsageError("--vary '" + text + "': '" + vary.path +
                               "' is not a parameter path (allowed: "
                               "Section/Entry, e.g. \"Mesh/Global "
                               "refinements=0,1\", or ranks=1,2)");
            for (const auto &v : options.vary)
              if (v.path == vary.path)
                throw UsageError("--vary '" + text + "': " + vary.path +
                                 " is varied twice (allowed: each parameter "
                                 "in one --vary, values joined by commas)");
            std::set<std::string> seen;
            for (const auto &v : vary.values)
              if (!seen.insert(v).second)
                throw UsageError("--vary '" + text + "': the value '" + v +
                                 "' is given twice (allowed: distinct "
                                 "values)");
            options.vary.push_back(vary);
          }
        else if (arg == "--output")
          {
            const std::string key = trim(value_of(
              i, argc, argv, "a summary.json key (e.g. final.max_stress.xx)"));
            if (key.empty() || key.find_first_of(" ,\"") != std::string::npos ||
                key.front() == '.' || key.back() == '.' ||
                key.find("..") != std::string::npos)
              throw UsageError("--output '" + key +
                               "': not a summary.json key (allowed: dotted "
                               "keys such as final.max_stress.xx or "
                               "final.crack_tips.tip0.K_I)");
            for (const auto &k : options.outputs)
              if (k == key)
                throw UsageError("--output " + key +
                                 " is given twice (allowed: distinct keys)");
            options.outputs.push_back(key);
          }
        else if (arg == "--reference")
          {
            const std::string text =
              value_of(i, argc, argv, "a number or run:\"PATH=V;...\"");
            const bool run = text.rfind("run:", 0) == 0;
            if (run != reference_run &&
                options.reference.kind != Reference::none)
              throw UsageError("--reference '" + text +
                               "': numbers and a run cannot be mixed "
                               "(allowed: one number per --output, or one "
                               "run:\"PATH=V;...\")");
            if (run)
              {
                if (options.reference.kind == Reference::run)
                  throw UsageError("--reference '" + text +
                                   "': a second reference run (allowed: one "
                                   "run:\"PATH=V;...\")");
                options.reference.kind = Reference::run;
                options.reference.overrides =
                  parse_override_list(text.substr(4), "--reference");
              }
            else
              {
                const double x = to_number(text);
                if (std::isnan(x))
                  throw UsageError("--reference '" + text +
                                   "': not a finite number (allowed: a "
                                   "number such as 3.98e6, or "
                                   "run:\"Section/Entry=value;...\")");
                options.reference.kind = Reference::values;
                options.reference.numbers.push_back(x);
              }
            reference_run = run;
            options.reference.text +=
              (options.reference.text.empty() ? "" : " ") + text;
          }
        else if (arg == "--set")
          options.sets.push_back(
            parse_assignment(value_of(i,
                                      argc,
                                      argv,
                                      "PATH=VALUE (e.g. --set \"Driver/Load "
                                      "steps=2\")"),
                             "--set"));
        else if (arg == "-o" || arg == "--directory")
          options.directory = value_of(i, argc, argv, "the study folder");
        else if (arg == "--no-chart")
          options.chart = false;
        else if (arg == "--mpiexec")
          options.mpiexec = value_of(i, argc, argv, "the MPI launcher");
        else if (!arg.empty() && arg[0] == '-')
          throw UsageError("unknown option '" + arg + "' " + allowed_options);
        else if (options.scene.empty())
          options.scene = arg;
        else
          throw UsageError("more than one scene file given ('" + options.scene +
                           "', '" + arg + "'; allowed: one SCENE.prm)");
      }
    if (options.scene.empty())
      throw UsageError("no scene file given (allowed: pdfem-study SCENE.prm "
                       "--vary PATH=V1,V2 --output KEY ...; see --help)");
    if (std::filesystem::path(options.scene).extension() != ".prm")
      throw UsageError("'" + options.scene +
                       "' is not a scene file (allowed: a .prm scene)");
    if (!std::filesystem::is_regular_file(options.scene))
      throw UsageError("the scene file '" + options.scene +
                       "' does not exist (allowed: an existing .prm file)");
    if (options.outputs.empty())
      throw UsageError("--output: no summary.json key given (allowed: one "
                       "or more, e.g. --output final.max_displacement.x)");
    if (options.reference.kind == Reference::values &&
        options.reference.numbers.size() != options.outputs.size())
      throw UsageError(
        "--reference: " + std::to_string(options.reference.numbers.size()) +
        " number(s) for " + std::to_string(options.outputs.size()) +
        " --output key(s) (allowed: one --reference VALUE per --output, in "
        "their order, or one run:\"PATH=V;...\")");
    for (const auto &s : options.sets)
      for (const auto &v : options.vary)
        if (s.first == v.path)
          throw UsageError("--set " + s.first + " and --vary " + v.path +
                           ": the parameter is both fixed and varied "
                           "(allowed: one of them)");
    if (options.directory.empty())
      options.directory = "study-" + scene_name(options.scene);
    return options;
  }

  std::vector<Point>
  make_grid(const Options &options)
  {
    for (const auto &v : options.vary)
      if (v.path == ranks_parameter)
        for (const auto &value : v.values)
          {
            const double n = to_number(value);
            if (!(n >= 1 && n <= 4096 && n == std::floor(n)))
              throw UsageError("--vary ranks: '" + value +
                               "' is not a number of ranks (allowed: whole "
                               "numbers from 1 to 4096, e.g. ranks=1,2,4)");
          }

    std::size_t n_points = 1;
    for (const auto &v : options.vary)
      n_points *= v.values.size();
    std::vector<Point> grid;
    const int          width = n_points >= 1000 ? 4 : 3;
    for (std::size_t p = 0; p < n_points; ++p)
      {
        Point point;
        point.number    = p + 1;
        point.overrides = options.sets;
        // Mixed radix, the last --vary fastest.
        std::size_t rest = p;
        point.values.resize(options.vary.size());
        for (std::size_t k = options.vary.size(); k-- > 0;)
          {
            const auto &v   = options.vary[k];
            point.values[k] = v.values[rest % v.values.size()];
            rest /= v.values.size();
          }
        for (std::size_t k = 0; k < options.vary.size(); ++k)
          if (options.vary[k].path == ranks_parameter)
            point.ranks = static_cast<unsigned int>(
              std::lround(to_number(point.values[k])));
          else
            point.overrides.emplace_back(options.vary[k].path, point.values[k]);
        char name[32];
        std::snprintf(name, sizeof(name), "run_%0*zu", width, point.number);
        point.folder = name;
        grid.push_back(point);
      }
    return grid;
  }

  std::string
  describe(const Options &options, const Point &point, const std::size_t n)
  {
    std::string out;
    for (std::size_t k = 0; k < std::min(n, options.vary.size()); ++k)
      {
        const std::string &path = options.vary[k].path;
        out += (k ? "; " : "") + path.substr(path.rfind('/') + 1) + "=" +
               point.values[k];
      }
    return out.empty() ? "the scene as it is" : out;
  }
} // namespace pdfem_study
