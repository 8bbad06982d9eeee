// SPDX-License-Identifier: LGPL-2.1-or-later
// Checkpoint and restart of a run (doc/reliability.md): what the Simulator
// saves besides the driver's loop state, how the folder is replaced without
// ever leaving no whole checkpoint, and how a restart takes it back.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/interrupts.h>
#include <pdfem/fracture/crack_growth.h>

#include <deal.II/base/mpi.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <functional>

#include "simulator_impl.h"
#include <fcntl.h>
#include <unistd.h>

namespace pdfem
{
  using namespace dealii;
  using internal::seconds_since;
  using clock  = std::chrono::steady_clock;
  namespace fs = std::filesystem;

  namespace
  {
    std::string
    rank_file(const std::string &folder, const unsigned int rank)
    {
      return folder + "/rank-" + std::to_string(rank) + ".state";
    }

    /// Flush a folder's entries (renames in it) to the disk.
    void
    sync_folder(const std::string &folder)
    {
      const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
      if (fd >= 0)
        {
          ::fsync(fd);
          ::close(fd);
        }
    }

    /// The checkpoint folder @p path names: itself if it holds a rank
    /// file, else its `checkpoint` folder, else `checkpoint.old` (left by a
    /// run killed while it replaced the checkpoint). InputError if none.
    std::string
    locate_checkpoint(const std::string &path)
    {
      for (const std::string &folder :
           {path, path + "/checkpoint", path + "/checkpoint.old"})
        if (fs::exists(rank_file(folder, 0)))
          return folder;
      throw InputError(path,
                       "--restart",
                       "no checkpoint there (no rank-0.state in it, in its "
                       "checkpoint folder or in checkpoint.old)",
                       "the output folder of a run that wrote a checkpoint");
    }

    /**
     * Fault injection for the kill-and-restart tests (developer.md): with
     * PDFEM_TEST_KILL=step:N the process kills itself (SIGKILL, no
     * clean-up) at the step boundary after step N; with checkpoint:N while
     * writing the checkpoint after step N, its files written but not yet
     * in place.
     */
    void
    kill_if_asked(const char *where, const unsigned int step)
    {
      // Read once: this runs at every step boundary.
      static const char *const asked = std::getenv("PDFEM_TEST_KILL");
      if (asked != nullptr && *asked != '\0' &&
          std::string(asked) == std::string(where) + ":" + std::to_string(step))
        std::raise(SIGKILL);
    }

    /// The first non-empty @p error of the ranks in rank order (empty if
    /// none): the same on every rank, so all can stop alike.
    std::string
    first_error(const MPI_Comm comm, const std::string &error)
    {
      for (const std::string &e : Utilities::MPI::all_gather(comm, error))
        if (!e.empty())
          return e;
      return "";
    }

    /// Run @p f on every rank; if it threw InputError on any, every rank
    /// throws the first rank's message (no rank is left waiting in a
    /// collective call).
    void
    on_every_rank(const MPI_Comm comm, const std::function<void()> &f)
    {
      std::string error;
      try
        {
          f();
        }
      catch (const InputError &e)
        {
          error = e.what();
        }
      error = first_error(comm, error);
      if (!error.empty())
        throw InputError("", "", error);
    }
  } // namespace

  std::string
  checkpoint_output_folder(const std::string &restart_path)
  {
    const std::string folder = locate_checkpoint(restart_path);
    return folder == restart_path ?
             fs::path(folder).lexically_normal().parent_path().string() :
             restart_path;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::check_checkpoint_settings() const
  {
    const bool wanted = setup.checkpoint_steps > 0 ||
                        setup.checkpoint_minutes > 0. ||
                        !setup.restart_from.empty();
    if (wanted && !driver->resumable())
      throw InputError(setup.file,
                       setup.restart_from.empty() ? "Output/Checkpoint steps" :
                                                    "--restart",
                       "a run of Driver/Type = " + setup.driver.type +
                         " cannot be checkpointed and restarted (the "
                         "driver does not save its loop state)",
                       "a driver of pdfem (they all can), or Checkpoint "
                       "steps = 0 and Checkpoint minutes = 0");
  }

  template <int dim>
  void
  Simulator<dim>::Impl::read_restart()
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    on_every_rank(comm, [&]() {
      const std::string folder = locate_checkpoint(setup.restart_from);
      std::error_code   ec;
      if (!fs::equivalent(fs::path(folder).parent_path(), setup.out_dir, ec))
        throw InputError(folder,
                         "--restart",
                         "this checkpoint belongs to the output folder " +
                           fs::path(folder).parent_path().string() +
                           ", and this run writes into " + setup.out_dir +
                           ": it appends to the history there",
                         "--output " + fs::path(folder).parent_path().string());
      const std::string own = rank_file(folder, rank);
      if (!fs::exists(own))
        throw InputError(folder,
                         "--restart",
                         "the checkpoint was written by fewer ranks than the " +
                           std::to_string(n_ranks) + " of this run",
                         "as many ranks as wrote it (rank-N.state files)");
      restart = std::make_unique<StateArchive>(StateArchive::read(own));
      const StateArchive &state    = *restart;
      const auto          mismatch = [&](const std::string &what,
                                const std::string &saved,
                                const std::string &now) {
        if (saved != now)
          throw InputError(own,
                           "--restart",
                           "the checkpoint is of a run with " + what + " " +
                             saved + ", this run has " + now,
                           "a restart of the same scene, mesh and number "
                                    "of ranks");
      };
      mismatch("ranks",
               std::to_string(state.get<unsigned int>("run/ranks")),
               std::to_string(n_ranks));
      mismatch("dimension",
               std::to_string(state.get<int>("run/dimension")),
               std::to_string(dim));
      mismatch("Driver/Type", state.get_text("run/driver"), setup.driver.type);
      mismatch("cells",
               std::to_string(state.get<unsigned int>("run/cells")),
               std::to_string(setup.tria->n_active_cells()));
      const auto pd = state.get_vector<char>("run/cell is pd");
      if (pd.size() != setup.tria->n_active_cells())
        throw InputError(own, "--restart", "the PD region has another size");
      setup.cell_is_pd.assign(pd.begin(), pd.end());
    });
  }

  template <int dim>
  void
  Simulator<dim>::Impl::resume_from_checkpoint(
    const std::vector<std::string> &columns)
  {
    const StateArchive &state = *restart;
    on_every_rank(comm, [&]() {
      if (state.get<types::global_dof_index>("run/dofs") != u.size())
        throw InputError("",
                         "--restart",
                         "the checkpoint has " +
                           std::to_string(
                             state.get<types::global_dof_index>("run/dofs")) +
                           " unknowns, this run " + std::to_string(u.size()));
      state.get_owned("run/u", u);
    });
    coupled->restore_fracture_state(state);
    if (cracks)
      cracks->load_state(state);
    for (const auto &p : postprocessors)
      p->load_state(state);
    n_steps             = state.get<unsigned int>("run/step");
    load_factor         = state.get<double>("run/load factor");
    peak_grip_stiffness = state.get<double>("run/peak grip stiffness");
    n_total_steps       = state.get<unsigned int>("run/total steps");
    step_record         = state.get<Drivers::StepRecord>("run/step record");
    time_step_record =
      state.get<Drivers::DynamicRecord>("run/time step record");
    initial_size         = state.get<Coupling::ProblemSize>("run/initial size");
    last_checkpoint_step = n_steps;
    // The wall clock goes on from where the checkpoint left it.
    setup.total_start -= std::chrono::duration_cast<clock::duration>(
      std::chrono::duration<double>(state.get<double>("run/wall seconds")));
    // history.csv as it was at the checkpoint: the rows written after it
    // go (they are computed again).
    on_every_rank(comm, [&]() {
      std::string error;
      try
        {
          history =
            std::make_unique<IO::History>(setup.out_dir + "/history.csv",
                                          columns,
                                          root,
                                          state.get<std::size_t>(
                                            "run/history rows"));
        }
      catch (const std::runtime_error &e)
        {
          error = e.what();
        }
      if (!error.empty())
        throw InputError(setup.out_dir + "/history.csv", "--restart", error);
    });
    if (progress)
      *progress << "  restarted from the checkpoint after step " << n_steps
                << " (" << setup.restart_from << ")" << std::endl;
  }

  template <int dim>
  void
  Simulator<dim>::Impl::step_boundary(const Drivers::SaveState &save)
  {
    // One collective decision: a signal on any rank, or a checkpoint due
    // (by steps, or by rank 0's clock).
    const int signal = StopOnSignals::stop_requested(comm);
    bool      due =
      signal != 0 || (setup.checkpoint_steps > 0 &&
                      n_steps >= last_checkpoint_step + setup.checkpoint_steps);
    if (!due && setup.checkpoint_minutes > 0.)
      due = Utilities::MPI::broadcast(comm,
                                      seconds_since(last_checkpoint_time) >=
                                        60. * setup.checkpoint_minutes,
                                      0);
    if (due)
      write_checkpoint(save);
    kill_if_asked("step", n_steps);
    // history.csv ends with the step the run stopped at (a restart drops
    // that row again if the history interval skips it: the checkpoint
    // counts the rows before it).
    if (signal != 0 && driver->dynamic() && last_row_step != n_steps)
      write_time_step_row(time_step_record);
    if (signal != 0)
      throw RunFailure("interrupted",
                       std::string(StopOnSignals::name(signal)) +
                         " received: stopped after step " +
                         std::to_string(n_steps) + " (load factor " +
                         number(load_factor) +
                         "), the state the outputs and the checkpoint hold; "
                         "go on with --restart " +
                         setup.out_dir);
  }

  template <int dim>
  void
  Simulator<dim>::Impl::write_checkpoint(const Drivers::SaveState &save)
  {
    const auto         start = clock::now();
    const unsigned int rank  = Utilities::MPI::this_mpi_process(comm);
    StateArchive       state;
    save(state);
    state.put("run/ranks", Utilities::MPI::n_mpi_processes(comm));
    state.put("run/dimension", dim);
    state.put("run/driver", setup.driver.type);
    state.put("run/cells", setup.tria->n_active_cells());
    state.put("run/dofs", u.size());
    state.put("run/cell is pd",
              std::vector<char>(setup.cell_is_pd.begin(),
                                setup.cell_is_pd.end()));
    state.put_owned("run/u", u);
    state.put("run/step", n_steps);
    state.put("run/load factor", load_factor);
    state.put("run/peak grip stiffness", peak_grip_stiffness);
    state.put("run/total steps", n_total_steps);
    state.put("run/step record", step_record);
    state.put("run/time step record", time_step_record);
    state.put("run/initial size", initial_size);
    state.put("run/history rows", history->rows());
    state.put("run/wall seconds", seconds_since(setup.total_start));
    coupled->save_fracture_state(state);
    if (cracks)
      cracks->save_state(state);
    for (const auto &p : postprocessors)
      p->save_state(state);

    // Into checkpoint.new; when every rank's file is on disk, rank 0 puts
    // it in place of checkpoint (kept as checkpoint.old until then), so
    // that a kill at any moment leaves one whole checkpoint.
    const std::string folder   = setup.out_dir + "/checkpoint";
    const std::string incoming = folder + ".new", old = folder + ".old";
    std::error_code   ec;
    if (rank == 0)
      {
        fs::remove_all(incoming, ec);
        fs::create_directories(incoming, ec);
      }
    std::string error = Utilities::MPI::broadcast(
      comm,
      ec ? "cannot create " + incoming + ": " + ec.message() : std::string(),
      0);
    if (error.empty())
      error = state.write(rank_file(incoming, rank));
    error = first_error(comm, error);
    if (!error.empty())
      throw RunFailure("io error", "writing the checkpoint failed: " + error);
    kill_if_asked("checkpoint", n_steps);
    if (rank == 0)
      {
        sync_folder(incoming);
        fs::remove_all(old, ec);
        if (fs::exists(folder))
          fs::rename(folder, old, ec);
        if (!ec)
          fs::rename(incoming, folder, ec);
        sync_folder(setup.out_dir);
        if (!ec)
          fs::remove_all(old, ec);
      }
    error =
      Utilities::MPI::broadcast(comm,
                                ec ? "putting " + incoming +
                                       " in place failed: " + ec.message() :
                                     std::string(),
                                0);
    if (!error.empty())
      throw RunFailure("io error", error);
    // From here on, the run's solves start as a restarted run's do.
    coupled->forget_preconditioner();
    last_checkpoint_step = n_steps;
    last_checkpoint_time = clock::now();
    ++n_checkpoints;
    output_time += seconds_since(start);
    if (progress)
      *progress << "  checkpoint after step " << n_steps << " written to "
                << folder << std::endl;
  }

#define INSTANTIATE(dim)                                                 \
  template void Simulator<dim>::Impl::check_checkpoint_settings() const; \
  template void Simulator<dim>::Impl::read_restart();                    \
  template void Simulator<dim>::Impl::resume_from_checkpoint(            \
    const std::vector<std::string> &);                                   \
  template void Simulator<dim>::Impl::step_boundary(                     \
    const Drivers::SaveState &);                                         \
  template void Simulator<dim>::Impl::write_checkpoint(                  \
    const Drivers::SaveState &);
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
