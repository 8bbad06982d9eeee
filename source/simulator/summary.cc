// SPDX-License-Identifier: LGPL-2.1-or-later
// The parts of summary.json that every run writes alike.
#include <pdfem/base/config.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/simulator/summary.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <limits>

namespace pdfem
{
  namespace Summary
  {
    using namespace dealii;

    std::vector<std::string>
    first_history_columns()
    {
      return {"step",
              "time",
              "load_factor",
              "newton_iterations",
              "linear_iterations",
              "residual",
              "n_broken_bonds",
              "max_damage"};
    }

    template <int dim>
    void
    write_header(IO::JsonWriter              &json,
                 const RunSetup<dim>         &setup,
                 MPI_Comm                     comm,
                 const std::string           &exit_state,
                 const std::string           &message,
                 const Coupling::ProblemSize &size,
                 const Coupling::ProblemSize &final_size)
    {
      json.value("pdfem_version", PDFEM_VERSION);
      json.value("scene", setup.name);
      json.value("input_file", setup.file);
      json.value("dimension", static_cast<unsigned long>(dim));
      json.value("ranks",
                 static_cast<unsigned long>(
                   Utilities::MPI::n_mpi_processes(comm)));
      json.value("threads",
                 static_cast<unsigned long>(MultithreadInfo::n_threads()));
      json.value("driver", setup.driver.type);
      json.value("criterion", setup.fracture.criterion);
      json.value("exit_state", exit_state);
      json.value("message", message);
      json.begin_object("problem");
      json.value("nodes", size.n_nodes);
      json.value("pd_nodes", size.n_pd_nodes);
      json.value("interface_nodes", size.n_interface_nodes);
      json.value("cells", size.n_cells);
      json.value("pd_cells", size.n_pd_cells);
      json.value("dofs", size.n_dofs);
      json.value("bonds", size.n_bonds);
      json.value("broken_bonds", final_size.n_broken_bonds);
      json.value("decoupled_nodes", final_size.n_decoupled_nodes);
      json.value("pd_boundary_faces", size.n_pd_boundary_faces);
      json.value("matrix_entries_rank0", size.n_matrix_entries);
      json.value("fe_matrix_entries", size.n_fe_matrix_entries);
      json.end_object();
    }

    template <int dim>
    void
    write_field_extremes(IO::JsonWriter                    &json,
                         const Coupling::NodalResults<dim> &results)
    {
      using Coupling::stress_component;
      const auto          comps  = Coupling::component_names<dim>();
      const auto          scomps = Coupling::stress_component_names<dim>();
      const double        inf    = std::numeric_limits<double>::infinity();
      std::vector<double> umax(dim, -inf), umin(dim, inf),
        smax(scomps.size(), -inf), smin(scomps.size(), inf);
      double s1max = -inf, dmax = 0.;
      for (unsigned int k = 0; k < results.position.size(); ++k)
        {
          for (unsigned int c = 0; c < dim; ++c)
            {
              umax[c] = std::max(umax[c], results.displacement[k][c]);
              umin[c] = std::min(umin[c], results.displacement[k][c]);
            }
          for (unsigned int c = 0; c < scomps.size(); ++c)
            {
              const double v = stress_component(results.stress[k], c);
              smax[c]        = std::max(smax[c], v);
              smin[c]        = std::min(smin[c], v);
            }
          s1max = std::max(s1max, eigenvalues(results.stress[k])[0]);
          dmax  = std::max(dmax, results.damage[k]);
        }
      const auto object = [&](const char                     *name,
                              const std::vector<std::string> &keys,
                              const std::vector<double>      &values) {
        json.begin_object(name);
        for (unsigned int c = 0; c < keys.size(); ++c)
          json.value(keys[c], values[c]);
        json.end_object();
      };
      object("max_displacement", comps, umax);
      object("min_displacement", comps, umin);
      object("max_stress", scomps, smax);
      object("min_stress", scomps, smin);
      json.value("max_principal_stress", s1max);
      json.value("max_damage", dmax);
    }

    template <int dim>
    void
    write_reactions(IO::JsonWriter                            &json,
                    const std::vector<std::string>            &names,
                    const std::vector<dealii::Tensor<1, dim>> &reactions,
                    const std::vector<unsigned int>           &group)
    {
      const auto comps = Coupling::component_names<dim>();
      json.begin_object("reaction");
      for (std::size_t s = 0; s < names.size(); ++s)
        {
          json.begin_object(names[s]);
          for (unsigned int c = 0; c < dim; ++c)
            json.value(comps[c], reactions[s][c]);
          json.end_object();
        }
      json.end_object();
      if (!group.empty())
        {
          Tensor<1, dim> R;
          for (const unsigned int s : group)
            R += reactions[s];
          json.begin_object("reaction_RF");
          for (unsigned int c = 0; c < dim; ++c)
            json.value(comps[c], R[c]);
          json.end_object();
        }
    }

#define INSTANTIATE(dim)                                          \
  template void write_header<dim>(IO::JsonWriter &,               \
                                  const RunSetup<dim> &,          \
                                  MPI_Comm,                       \
                                  const std::string &,            \
                                  const std::string &,            \
                                  const Coupling::ProblemSize &,  \
                                  const Coupling::ProblemSize &); \
  template void write_field_extremes<dim>(                        \
    IO::JsonWriter &, const Coupling::NodalResults<dim> &);       \
  template void write_reactions<dim>(                             \
    IO::JsonWriter &,                                             \
    const std::vector<std::string> &,                             \
    const std::vector<dealii::Tensor<1, dim>> &,                  \
    const std::vector<unsigned int> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Summary
} // namespace pdfem
