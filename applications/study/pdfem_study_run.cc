// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-study: running one point of the grid and measuring it.
//
// In process, Scene::run does the run: the process starts (MPI, deal.II,
// the plugin registries) once for the whole study. Its terminal output is sent
// to the run's run.log by pointing file descriptors 1 and 2 there for the
// run's duration. The wall time is measured around Scene::run; the peak
// memory is the process's resident high-water mark (VmHWM), which Linux lets
// a process reset by writing "5" to /proc/self/clear_refs: reset before the
// run, read after, it is the peak of this run (the process's own baseline,
// its libraries and what earlier runs left allocated, included).
//
// `--vary ranks=...` points run as `mpirun -np K pdfem ...`, with the
// environment this program started with (not the variables that MPI's
// start-up set in it); their wall time includes the launcher's start-up and
// their memory is the rank-0 peak summary.json reports.
#include <pdfem/scene/scene.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pdfem_study.h"
#include <fcntl.h>
#include <mpi.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pdfem_study
{
  namespace
  {
    using clock = std::chrono::steady_clock;

    /// While alive, file descriptors 1 and 2 (and so std::cout, std::cerr
    /// and C's stdio) write into a file.
    class Redirect
    {
    public:
      explicit Redirect(const std::string &file)
      {
        flush();
        const int fd =
          ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (fd < 0)
          return;
        saved_out = ::dup(1);
        saved_err = ::dup(2);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
      }
      ~Redirect()
      {
        flush();
        if (saved_out >= 0)
          {
            ::dup2(saved_out, 1);
            ::close(saved_out);
          }
        if (saved_err >= 0)
          {
            ::dup2(saved_err, 2);
            ::close(saved_err);
          }
      }
      Redirect(const Redirect &) = delete;
      Redirect &
      operator=(const Redirect &) = delete;

    private:
      int saved_out = -1, saved_err = -1;

      static void
      flush()
      {
        std::cout.flush();
        std::cerr.flush();
        std::fflush(stdout);
        std::fflush(stderr);
      }
    };

    /// Resets the process's peak resident memory (VmHWM); false if Linux
    /// does not let us.
    bool
    reset_peak_memory()
    {
      std::ofstream clear("/proc/self/clear_refs");
      if (!clear)
        return false;
      clear << "5";
      clear.flush();
      return static_cast<bool>(clear);
    }

    /// VmHWM of /proc/self/status in MB; NaN if it cannot be read.
    double
    peak_memory_mb()
    {
      std::ifstream status("/proc/self/status");
      std::string   line;
      while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0)
          {
            std::istringstream s(line.substr(6));
            double             kb = 0;
            if (s >> kb)
              return kb / 1024.;
          }
      return missing;
    }

    /// An empty run folder for a run (its summary.json of an earlier study
    /// removed, so that it is never taken for this run's).
    void
    prepare_folder(const std::string &folder)
    {
      std::error_code ec;
      fs::create_directories(folder, ec);
      if (ec)
        throw UsageError("-o: cannot create the folder '" + folder + "': " +
                         ec.message() + " (allowed: a writable folder)");
      fs::remove(folder + "/summary.json", ec);
      fs::remove(folder + "/summary.json.tmp", ec);
    }

    /// Fills @p r from folder/summary.json (exit state, timings, size and
    /// the outputs); without one, the exit state says why (r.exit_code 2:
    /// "input error").
    void
    read_summary(RunResult                      &r,
                 const std::string              &folder,
                 const std::vector<std::string> &outputs)
    {
      r.outputs.assign(outputs.size(), missing);
      const std::string file = folder + "/summary.json";
      if (!fs::exists(file))
        {
          r.exit_state = r.exit_code == 2 ? "input error" : "no summary.json";
          return;
        }
      try
        {
          auto        summary = std::make_shared<Json>(Json::read(file));
          const Json *state   = summary->find("exit_state");
          r.exit_state    = state != nullptr && state->kind == Json::string ?
                              state->text :
                              "no exit_state";
          r.total_seconds = summary->number_at("timings.total");
          r.dofs          = summary->number_at("problem.dofs");
          r.bonds         = summary->number_at("problem.bonds");
          for (std::size_t k = 0; k < outputs.size(); ++k)
            r.outputs[k] = summary->number_at(outputs[k]);
          r.summary = summary;
        }
      catch (const std::exception &)
        {
          r.exit_state = "unreadable summary.json";
        }
    }

    /// argv as C strings (pointing into @p args), with a null at the end.
    std::vector<char *>
    c_strings(std::vector<std::string> &args)
    {
      std::vector<char *> out;
      for (auto &a : args)
        out.push_back(a.data());
      out.push_back(nullptr);
      return out;
    }
  } // namespace

  std::vector<std::string> &
  original_environment()
  {
    static std::vector<std::string> environment;
    return environment;
  }

  std::string
  program_folder()
  {
    std::error_code ec;
    const fs::path  self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string(".") : self.parent_path().string();
  }

  std::string
  find_executable(const std::string &name)
  {
    if (name.find('/') != std::string::npos)
      return ::access(name.c_str(), X_OK) == 0 ? name : "";
    const char       *path = std::getenv("PATH");
    std::stringstream folders(path != nullptr ? path : "/usr/bin:/bin");
    std::string       folder;
    while (std::getline(folders, folder, ':'))
      {
        const std::string candidate =
          (folder.empty() ? std::string(".") : folder) + "/" + name;
        struct stat st;
        if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
            ::access(candidate.c_str(), X_OK) == 0)
          return candidate;
      }
    return "";
  }

  int
  run_program(const std::vector<std::string> &argv, const std::string &log)
  {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(
      &actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);

    std::vector<std::string> args        = argv;
    std::vector<std::string> environment = original_environment();
    std::vector<char *>      c_args      = c_strings(args);
    std::vector<char *>      c_env       = c_strings(environment);
    pid_t                    pid         = 0;
    std::cout.flush();
    std::fflush(stdout);
    const int error = posix_spawn(
      &pid, c_args[0], &actions, nullptr, c_args.data(), c_env.data());
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
      return -1;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
      if (errno != EINTR)
        return -1;
    if (WIFEXITED(status))
      return WEXITSTATUS(status);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
  }

  std::string
  check_scene(const std::string &scene, const std::vector<Override> &overrides)
  {
    pdfem::Scene::RunOptions options;
    options.overrides        = overrides;
    options.print_parameters = true;
    options.quiet            = true;
    // Scene::run prints the resolved parameters to std::cout and a fault
    // to std::cerr: keep both.
    std::ostringstream out, err;
    std::streambuf    *old_out = std::cout.rdbuf(out.rdbuf());
    std::streambuf    *old_err = std::cerr.rdbuf(err.rdbuf());
    int                code    = 0;
    std::string        what;
    try
      {
        code = pdfem::Scene::run(scene, options, MPI_COMM_WORLD);
      }
    catch (const std::exception &e)
      {
        code = 2;
        what = e.what();
      }
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    if (code == 0)
      return "";
    std::string       message = what.empty() ? err.str() : what;
    const std::string prefix  = "pdfem: error: ";
    if (message.rfind(prefix, 0) == 0)
      message.erase(0, prefix.size());
    // Only the first line: the messages are one line each.
    message = message.substr(0, message.find('\n'));
    if (message.rfind("--set: ", 0) == 0)
      message.erase(0, 7);
    return message.empty() ? "the scene was refused (exit status " +
                               std::to_string(code) + ")" :
                             message;
  }

  RunResult
  run_in_process(const std::string              &scene,
                 const std::vector<Override>    &overrides,
                 const std::string              &folder,
                 const std::vector<std::string> &outputs)
  {
    prepare_folder(folder);
    RunResult                r;
    pdfem::Scene::RunOptions options;
    options.output_directory = folder;
    options.quiet            = true;
    options.overrides        = overrides;
    std::string crash;
    {
      Redirect   to_log(folder + "/run.log");
      const bool reset = reset_peak_memory();
      const auto start = clock::now();
      try
        {
          r.exit_code = pdfem::Scene::run(scene, options, MPI_COMM_WORLD);
        }
      catch (const std::exception &e)
        {
          r.exit_code = -1;
          crash       = e.what();
          std::cerr << "pdfem-study: the run threw: " << crash << std::endl;
        }
      r.wall_seconds =
        std::chrono::duration<double>(clock::now() - start).count();
      if (reset)
        r.peak_memory_mb = peak_memory_mb();
    }
    read_summary(r, folder, outputs);
    if (!crash.empty())
      r.exit_state = "exception";
    return r;
  }

  RunResult
  run_launched(const std::string              &mpiexec,
               unsigned int                    ranks,
               const std::string              &scene,
               const std::vector<Override>    &overrides,
               const std::string              &folder,
               const std::vector<std::string> &outputs)
  {
    prepare_folder(folder);
    std::vector<std::string> argv = {find_executable(mpiexec),
                                     "-np",
                                     std::to_string(ranks),
                                     program_folder() + "/pdfem",
                                     scene,
                                     "--output",
                                     folder,
                                     "--quiet"};
    for (const auto &[path, value] : overrides)
      {
        argv.push_back("--set");
        argv.push_back(path + "=" + value);
      }
    RunResult  r;
    const auto start = clock::now();
    r.exit_code      = run_program(argv, folder + "/run.log");
    r.wall_seconds =
      std::chrono::duration<double>(clock::now() - start).count();
    r.in_process = false;
    read_summary(r, folder, outputs);
    if (r.exit_code < 0)
      r.exit_state = "launcher failed";
    if (r.summary)
      r.peak_memory_mb = r.summary->number_at("peak_memory_mb_rank0");
    return r;
  }
} // namespace pdfem_study
