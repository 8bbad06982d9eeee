// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to pdfem-study: what its pieces share. The command line and the grid
// of runs (pdfem_study_options.cc), a small JSON reader for summary.json
// (pdfem_study_json.cc), running one point of the grid and measuring it
// (pdfem_study_run.cc), and the errors, the Pareto front, study.csv, the table
// on stdout and the chart (pdfem_study_report.cc). main() is in
// pdfem_study.cc. See doc/tools.md, "pdfem-study".
#ifndef PDFEM_APPLICATIONS_STUDY_PDFEM_STUDY_H
#define PDFEM_APPLICATIONS_STUDY_PDFEM_STUDY_H

#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pdfem_study
{
  /// A bad command line or scene: one line on stderr, exit status 2.
  struct UsageError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  /// Exit status of pdfem-study.
  enum ExitStatus : int
  {
    /// Every run completed (or separated).
    success = 0,
    /// Bad input: nothing was run (or, for an unknown output key, the study
    /// stopped after the first finished run).
    bad_input = 2,
    /// At least one run (or the reference run) did not finish.
    failed_runs = 3
  };

  /// Not a number: an output, error or measurement that is not there.
  inline constexpr double missing = std::numeric_limits<double>::quiet_NaN();

  /// One parameter override "Section/Entry" = "value" (as pdfem's --set).
  using Override = std::pair<std::string, std::string>;

  /// The pseudo-parameter of --vary that sets the number of MPI ranks.
  inline const std::string ranks_parameter = "ranks";

  /// One --vary: a parameter and the values it takes.
  struct Vary
  {
    /// "Section/Entry" (or "Section/Subsection/Entry"), or "ranks".
    std::string path;
    /// The values, in the order given.
    std::vector<std::string> values;
  };

  /// What the outputs are compared with (--reference).
  struct Reference
  {
    enum Kind
    {
      /// No --reference: no errors, no Pareto front, no chart.
      none,
      /// Numbers given on the command line, one per --output.
      values,
      /// One extra run of the scene with these overrides.
      run
    } kind = none;
    /// kind == values: one number per output.
    std::vector<double> numbers;
    /// kind == run: the overrides of the reference run.
    std::vector<Override> overrides;
    /// The option as given, for messages.
    std::string text;
  };

  /// The command line of pdfem-study.
  struct Options
  {
    /// The scene file (.prm).
    std::string scene;
    /// The parameters varied, in the order given (the first varies slowest).
    std::vector<Vary> vary;
    /// Dotted summary.json keys to measure (e.g. final.max_stress.xx).
    std::vector<std::string> outputs;
    /// What the outputs are compared with.
    Reference reference;
    /// --set overrides, applied to every run (before the varied values).
    std::vector<Override> sets;
    /// The study folder (-o); default study-<scene name>.
    std::string directory;
    /// Draw DIR/study.png with pdfem-plot (off with --no-chart).
    bool chart = true;
    /// The MPI launcher of `--vary ranks=...` runs (--mpiexec).
    std::string mpiexec = "mpirun";
  };

  /// The help text (--help).
  extern const char *const help_text;

  /**
   * Reads the command line. Throws UsageError naming the option and what is
   * allowed. Sets @p help when --help was given (and nothing else is read).
   */
  Options
  parse_command_line(int argc, char **argv, bool &help);

  /// "Section/Entry=value" split at the first '='; throws UsageError
  /// (naming @p option) when there is none or either side is empty.
  Override
  parse_assignment(const std::string &text, const std::string &option);

  /// The scene name: the file name without folder and extension.
  std::string
  scene_name(const std::string &file);

  /// One point of the grid.
  struct Point
  {
    /// 1-based number of the run (its row in study.csv).
    std::size_t number = 0;
    /// The value of each --vary, in the order of Options::vary.
    std::vector<std::string> values;
    /// Every override of the run: --set, then the varied parameters (but
    /// ranks).
    std::vector<Override> overrides;
    /// Number of MPI ranks of a `--vary ranks=...` point; 0: in process.
    unsigned int ranks = 0;
    /// The run's folder name inside the study folder (run_001, ...).
    std::string folder;
  };

  /// Every combination of the --vary values; the first --vary varies
  /// slowest. Checks the ranks values (throws UsageError).
  std::vector<Point>
  make_grid(const Options &options);

  /// A short description of a point: "Entry=value; Entry=value", of its
  /// first @p n varied parameters (all by default).
  std::string
  describe(const Options    &options,
           const Point      &point,
           const std::size_t n = static_cast<std::size_t>(-1));

  /// A parsed JSON document (objects, arrays, numbers, strings, true, false,
  /// null): just what summary.json needs.
  struct Json
  {
    enum Kind
    {
      null,
      boolean,
      number,
      string,
      array,
      object
    } kind = null;
    /// number and boolean (1/0) values.
    double x = 0.;
    /// string values.
    std::string text;
    /// object members, in the file's order.
    std::vector<std::pair<std::string, Json>> members;
    /// array elements.
    std::vector<Json> elements;

    /// Parses @p text; throws std::runtime_error naming the offset of a fault.
    static Json
    parse(const std::string &text);

    /// Reads and parses a file; throws std::runtime_error naming the file.
    static Json
    read(const std::string &file);

    /// The value at a dotted key ("final.max_stress.xx"; array elements by
    /// their index), or nullptr.
    const Json *
    find(const std::string &key) const;

    /// The number at @p key; NaN when absent, null or not a number.
    double
    number_at(const std::string &key) const;

    /// The dotted keys of every number below this value, @p prefix before
    /// each.
    std::vector<std::string>
    number_keys(const std::string &prefix = "") const;
  };

  /// What one run gave.
  struct RunResult
  {
    /// summary.json's exit_state, or what went wrong ("input error",
    /// "no summary.json", "launcher failed", ...).
    std::string exit_state;
    /// Exit status of Scene::run or of the launcher.
    int exit_code = 0;
    /// Run by Scene::run in this process (not by mpirun).
    bool in_process = true;
    /// Wall time around the run [s].
    double wall_seconds = missing;
    /// summary.json's timings.total [s].
    double total_seconds = missing;
    /// Peak resident memory of the run [MB] (see pdfem_study_run.cc).
    double peak_memory_mb = missing;
    /// problem.dofs and problem.bonds of summary.json.
    double dofs = missing, bonds = missing;
    /// The --output values (NaN where absent).
    std::vector<double> outputs;
    /// The summary, when there is one.
    std::shared_ptr<const Json> summary;

    /// The run finished: completed or separated.
    bool
    finished() const
    {
      return exit_state == "completed" || exit_state == "separated";
    }
  };

  /// The process environment as it was when main() started (before MPI set
  /// its variables): what child processes get.
  std::vector<std::string> &
  original_environment();

  /// The folder of this program (where pdfem and pdfem-plot are installed).
  std::string
  program_folder();

  /// An executable named @p name in $PATH (or @p name itself when it holds a
  /// '/' and is executable); empty when there is none.
  std::string
  find_executable(const std::string &name);

  /**
   * Checks the scene with @p overrides as pdfem --print-parameters does (the
   * file, every parameter name and value, the plugins named), running
   * nothing. Returns the error message (without "pdfem: error: "), or an
   * empty string.
   */
  std::string
  check_scene(const std::string &scene, const std::vector<Override> &overrides);

  /**
   * Runs the scene once with Scene::run in this process, quietly, into
   * @p folder (its terminal output goes to folder/run.log), and measures it.
   */
  RunResult
  run_in_process(const std::string              &scene,
                 const std::vector<Override>    &overrides,
                 const std::string              &folder,
                 const std::vector<std::string> &outputs);

  /**
   * Runs the scene as `MPIEXEC -np RANKS <pdfem beside this program> scene
   * --output folder --quiet --set ...` (output to folder/run.log) and
   * measures it.
   */
  RunResult
  run_launched(const std::string              &mpiexec,
               unsigned int                    ranks,
               const std::string              &scene,
               const std::vector<Override>    &overrides,
               const std::string              &folder,
               const std::vector<std::string> &outputs);

  /**
   * Runs @p argv (argv[0] a path) with the original environment, stdout and
   * stderr into @p log; returns its exit status (or -1 when it could not be
   * started, 128 + signal when a signal ended it).
   */
  int
  run_program(const std::vector<std::string> &argv, const std::string &log);

  /// One row of study.csv: a point and what its run gave.
  struct Row
  {
    Point     point;
    RunResult result;
    /// Error of each output against the reference (NaN: none).
    std::vector<double> errors;
    /// 1: on the Pareto front, 0: not, -1: not ranked (no error).
    int pareto = -1;
  };

  /// The error of @p value against @p reference: |v - r| / |r|, or |v|
  /// when r is 0; NaN when either is not finite.
  double
  relative_error(double value, double reference);

  /// Sets Row::pareto: a row with a finite first error is on the front when
  /// no other row is at least as fast and as accurate and better in one.
  void
  mark_pareto(std::vector<Row> &rows);

  /// Writes study.csv (see doc/tools.md for the columns).
  void
  write_csv(const std::string         &file,
            const Options             &options,
            const std::vector<Row>    &rows,
            const std::vector<double> &reference);

  /// The short table of the study on stdout.
  void
  print_table(const Options             &options,
              const std::vector<Row>    &rows,
              const std::vector<double> &reference);

  /**
   * Draws folder/study.png (error of the first output against wall time,
   * log-log, every run a marker, the Pareto front a line) with pdfem-plot
   * beside this program, under xvfb-run when there is no display. Returns
   * what happened, for stdout ("study.png" or why not).
   */
  std::string
  draw_chart(const std::string      &folder,
             const Options          &options,
             const std::vector<Row> &rows);

  /// @p x with @p digits significant digits (%.*g); "" for NaN.
  std::string
  format(double x, int digits = 17);
} // namespace pdfem_study

#endif
