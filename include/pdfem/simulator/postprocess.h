// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SIMULATOR_POSTPROCESS_H
#define PDFEM_SIMULATOR_POSTPROCESS_H

#include <pdfem/base/config.h>
#include <pdfem/base/plugins.h>
#include <pdfem/simulator/simulator.h>

#include <memory>
#include <string>
#include <vector>

namespace pdfem
{
  class StateArchive;
  namespace IO
  {
    class JsonWriter;
  } // namespace IO

  /**
   * Postprocessors: what a run writes besides the solution itself. Each
   * is a plugin (ExaDG's postprocessor fed by the driver, ASPECT's
   * registered postprocessors): it adds columns to history.csv, members
   * to summary.json and files to the output folder, reading the run
   * through SimulatorAccess.
   */
  namespace Postprocess
  {
    /**
     * A postprocessor. Register one with PDFEM_REGISTER_POSTPROCESSOR at
     * the end of its `.cc` file: every registered postprocessor is offered
     * to every run and takes part where initialize() says so.
     */
    template <int dim>
    class Interface : public SimulatorAccess<dim>
    {
    public:
      /// Once the system exists: does this postprocessor take part in the
      /// run? (For example: energy balance only in dynamic runs.)
      virtual bool
      initialize()
      {
        return true;
      }

      /// Its history.csv columns.
      virtual std::vector<std::string>
      history_columns()
      {
        return {};
      }

      /// Their values at a recorded step (appended to @p row).
      virtual void
      history_values(std::vector<double> &row)
      {
        (void)row;
      }

      /// Dynamic runs: after every time step, recorded in history.csv or
      /// not.
      virtual void
      every_time_step()
      {}

      /// Field output at time or step @p t (intermediate steps and the
      /// last one).
      virtual void
      write_fields(double t)
      {
        (void)t;
      }

      /// The end of the run (files that are written once). Collective.
      virtual void
      finish()
      {}

      /// Members of summary.json's "final" object (rank 0).
      virtual void
      write_final(IO::JsonWriter &json) const
      {
        (void)json;
      }

      /// Top-level sections of summary.json (rank 0).
      virtual void
      write_sections(IO::JsonWriter &json) const
      {
        (void)json;
      }

      /// Put what this postprocessor carries from step to step (peaks,
      /// files written so far) into a checkpoint, under a prefix of its own;
      /// files it writes in the background are complete on return.
      /// Collective.
      virtual void
      save_state(StateArchive &state)
      {
        (void)state;
      }

      /// Take it back on restart (after initialize()).
      virtual void
      load_state(const StateArchive &state)
      {
        (void)state;
      }
    };

    /// The registry of postprocessors for dimension @p dim.
    template <int dim>
    Plugins::Registry<Interface<dim>> &
    registry();

    /// Register @p Class<2> and @p Class<3> (a template on dim).
    template <template <int> class Class>
    bool
    register_postprocessor(const std::string &name,
                           const std::string &description)
    {
      registry<2>().add(name, description, {}, []() {
        return std::unique_ptr<Interface<2>>(new Class<2>());
      });
#if PDFEM_WITH_3D
      registry<3>().add(name, description, {}, []() {
        return std::unique_ptr<Interface<3>>(new Class<3>());
      });
#endif
      return true;
    }
  } // namespace Postprocess
} // namespace pdfem

/**
 * Register the postprocessor class template @p classname (on dim) under
 * @p name with a one-line @p description; at namespace scope in its `.cc`.
 */
#define PDFEM_REGISTER_POSTPROCESSOR(classname, name, description)          \
  namespace                                                                 \
  {                                                                         \
    const bool PDFEM_PLUGIN_CONCAT(pdfem_postprocessor_registered_,         \
                                   __LINE__) =                              \
      ::pdfem::Postprocess::register_postprocessor<classname>(name,         \
                                                              description); \
  }

#endif
