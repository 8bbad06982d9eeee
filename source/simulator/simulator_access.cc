// SPDX-License-Identifier: LGPL-2.1-or-later
// SimulatorAccess (read access for plugins and programs) and the
// postprocessor registry.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/simulator/postprocess.h>

#include <deal.II/base/mpi.h>

namespace pdfem
{
  template <int dim>
  void
  SimulatorAccess<dim>::initialize_simulator(const Simulator<dim> &s)
  {
    simulator = &s;
  }

  template <int dim>
  const Simulator<dim> &
  SimulatorAccess<dim>::get_simulator() const
  {
    if (simulator == nullptr)
      throw std::logic_error("SimulatorAccess used before "
                             "initialize_simulator()");
    return *simulator;
  }

  template <int dim>
  MPI_Comm
  SimulatorAccess<dim>::get_mpi_communicator() const
  {
    return get_simulator().get_mpi_communicator();
  }

  template <int dim>
  bool
  SimulatorAccess<dim>::is_root() const
  {
    return dealii::Utilities::MPI::this_mpi_process(get_mpi_communicator()) ==
           0;
  }

  template <int dim>
  const RunSetup<dim> &
  SimulatorAccess<dim>::get_setup() const
  {
    return get_simulator().get_setup();
  }

  template <int dim>
  const dealii::parallel::shared::Triangulation<dim, dim> &
  SimulatorAccess<dim>::get_triangulation() const
  {
    return *get_setup().tria;
  }

  template <int dim>
  const Coupling::CoupledSystem<dim> &
  SimulatorAccess<dim>::get_system() const
  {
    return get_simulator().get_system();
  }

  template <int dim>
  Coupling::CoupledSystem<dim> &
  SimulatorAccess<dim>::get_mutable_system() const
  {
    return get_simulator().get_mutable_system();
  }

  template <int dim>
  const dealii::TrilinosWrappers::MPI::Vector &
  SimulatorAccess<dim>::get_solution() const
  {
    return get_simulator().get_solution();
  }

  template <int dim>
  const Coupling::NodalResults<dim> &
  SimulatorAccess<dim>::get_nodal_results() const
  {
    return get_simulator().get_nodal_results();
  }

  template <int dim>
  const Drivers::Interface &
  SimulatorAccess<dim>::get_driver() const
  {
    return get_simulator().get_driver();
  }

  template <int dim>
  bool
  SimulatorAccess<dim>::is_dynamic() const
  {
    return get_driver().dynamic();
  }

  template <int dim>
  const Drivers::StepRecord &
  SimulatorAccess<dim>::get_step_record() const
  {
    return get_simulator().get_step_record();
  }

  template <int dim>
  const Drivers::DynamicRecord &
  SimulatorAccess<dim>::get_time_step_record() const
  {
    return get_simulator().get_time_step_record();
  }

  template <int dim>
  double
  SimulatorAccess<dim>::get_load_factor() const
  {
    return get_simulator().get_load_factor();
  }

  template <int dim>
  const Drivers::StabilityReport *
  SimulatorAccess<dim>::get_last_stability_check() const
  {
    return get_simulator().get_last_stability_check();
  }

  template <int dim>
  std::ostream *
  SimulatorAccess<dim>::get_progress_stream() const
  {
    return get_simulator().get_progress_stream();
  }

  template <int dim>
  const Fracture::CrackGrowth<dim> *
  SimulatorAccess<dim>::get_cracks() const
  {
    return get_simulator().get_cracks();
  }

  template <int dim>
  const Fracture::Assessment &
  SimulatorAccess<dim>::get_assessment() const
  {
    return get_simulator().get_assessment();
  }

  template <int dim>
  const std::string &
  SimulatorAccess<dim>::get_output_directory() const
  {
    return get_setup().out_dir;
  }

  namespace Postprocess
  {
    template <int dim>
    Plugins::Registry<Interface<dim>> &
    registry()
    {
      static Plugins::Registry<Interface<dim>> postprocessors;
      return postprocessors;
    }
  } // namespace Postprocess

#define INSTANTIATE(dim)                                  \
  template class SimulatorAccess<dim>;                    \
  template Plugins::Registry<Postprocess::Interface<dim>> \
    &Postprocess::registry<dim>();
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
