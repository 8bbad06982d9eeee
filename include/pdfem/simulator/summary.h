// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_SIMULATOR_SUMMARY_H
#define PDFEM_SIMULATOR_SUMMARY_H

#include <pdfem/simulator/simulator.h>

#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    class JsonWriter;
  }

  /** The parts of summary.json and history.csv that every run writes alike. */
  namespace Summary
  {
    /// history.csv's first columns, the same for every run: step, time,
    /// load_factor, newton_iterations, linear_iterations, residual,
    /// n_broken_bonds, max_damage.
    std::vector<std::string>
    first_history_columns();

    /// The opening members: version, scene, input file, dimension, ranks,
    /// threads, driver, criterion, exit state, message and "problem" (the
    /// sizes, bonds broken and nodes decoupled from @p final_size).
    template <int dim>
    void
    write_header(IO::JsonWriter              &json,
                 const RunSetup<dim>         &setup,
                 MPI_Comm                     comm,
                 const std::string           &exit_state,
                 const std::string           &message,
                 const Coupling::ProblemSize &size,
                 const Coupling::ProblemSize &final_size);

    /// The extremes of the nodal fields: max and min displacement and
    /// stress per component, max_principal_stress and max_damage.
    template <int dim>
    void
    write_field_extremes(IO::JsonWriter                    &json,
                         const Coupling::NodalResults<dim> &results);

    /// "reaction" per set and, with a group, "reaction_RF" (their sum).
    template <int dim>
    void
    write_reactions(IO::JsonWriter                            &json,
                    const std::vector<std::string>            &names,
                    const std::vector<dealii::Tensor<1, dim>> &reactions,
                    const std::vector<unsigned int>           &group);
  } // namespace Summary
} // namespace pdfem

#endif
