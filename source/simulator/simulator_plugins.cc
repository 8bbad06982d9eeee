// SPDX-License-Identifier: LGPL-2.1-or-later
// The plugins of a run (driver, PD model, crack criterion), made from their
// names and checked against each other before any work.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/simulator/simulator.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace pdfem
{
  Drivers::RunTraits
  make_run_traits(const std::string       &file,
                  const int                dim,
                  const std::string       &model_name,
                  const bool               nonlinear,
                  const double             density,
                  const Solvers::Settings &linear_solver,
                  const std::string       &driver_name,
                  const bool               smooth_degradation,
                  const bool               tangent_rows)
  {
    Drivers::RunTraits traits;
    traits.tangent_rows       = tangent_rows;
    traits.smooth_degradation = smooth_degradation;
    traits.file               = file;
    traits.dim                = dim;
    traits.model_name         = model_name;
    traits.nonlinear_model    = nonlinear;
    traits.has_mass           = density > 0.;
    traits.assembled_matrix   = !linear_solver.matrix_free();
    traits.driver_name        = driver_name;
    return traits;
  }

  template <int dim>
  Solvers::Settings
  resolve_linear_solver(const Solvers::Settings        &linear_solver,
                        const PDModels::Interface<dim> *model,
                        const Drivers::Interface       &driver)
  {
    if (!model)
      return linear_solver.resolve(false, driver.needs_assembled_matrix());
    const PDModels::Layout &layout = model->layout();
    // Products of a symmetric tangent serve every driver of nonlinear
    // models: the relaxation's row bounds come from the tangent's rows.
    const bool tangent_products =
      layout.tangent_products && model->symmetric() && layout.tangent_rows();
    return linear_solver.resolve(!model->linear(),
                                 driver.needs_assembled_matrix(),
                                 !layout.tangent,
                                 layout.preconditioner,
                                 tangent_products);
  }

  template <int dim>
  void
  check_plugins(const Drivers::Interface       &driver,
                const Fracture::Criterion<dim> *criterion,
                const Drivers::RunTraits       &traits,
                const Fracture::Settings       &fracture)
  {
    driver.check(traits);
    if (criterion && traits.nonlinear_model)
      throw InputError(traits.file,
                       "Fracture/Criterion",
                       "the " + traits.model_name +
                         " model softens its bonds itself: it takes no crack "
                         "criterion",
                       "none");
    if (criterion)
      criterion->check(Fracture::CriterionTraits{traits.file,
                                                 driver.dynamic(),
                                                 traits.driver_name});
    if (fracture.adaptive_margin > 0. && driver.dynamic())
      throw InputError(traits.file,
                       "Fracture/Adaptive margin",
                       "the adaptive PD region belongs to quasi-static runs",
                       "0 with Driver/Type = " + traits.driver_name);
    if (fracture.automatic_region > 0. && !driver.grows_cracks())
      throw InputError(traits.file,
                       "Fracture/Automatic region",
                       "the automatic PD region grows between the steps of "
                       "a quasi-static run",
                       "0 with Driver/Type = " + traits.driver_name +
                         ", or Driver/Type = quasi-static");
  }

  /**
   * A PD model of forces only (no tangent) with a driver that needs one:
   * allowed where the driver's tangent serves only its linear solves
   * (Drivers::Interface::solves_with_products()), the model is linear and
   * symmetric, and the linear solver is matrix-free CG, which applies the
   * operator by force evaluations. Otherwise InputError naming the
   * parameter to change.
   */
  template <int dim>
  void
  check_forces_only_model(const std::string              &file,
                          const std::string              &model_name,
                          const PDModels::Interface<dim> &model,
                          const Drivers::Interface       &driver,
                          const std::string              &driver_name,
                          const Solvers::Settings        &linear_solver)
  {
    const std::string what =
      model_name + " evaluates forces only, without a tangent, and ";
    if (!driver.solves_with_products() || !model.linear() || !model.symmetric())
      throw InputError(file,
                       "Peridynamics/Model",
                       what + "Driver/Type = " + driver_name + " needs one",
                       "a driver of forces only (Driver/Type = explicit, or "
                       "static for a linear model), or another "
                       "Peridynamics/Model");
    if (!linear_solver
           .resolve(false, false, true, model.layout().preconditioner)
           .solves_with_products_only())
      throw InputError(file,
                       "Linear solver/Type",
                       what + "Driver/Type = " + driver_name +
                         " solves with it unless the solver is matrix-free CG",
                       "cg (or auto) with Preconditioner = amg fe or pd "
                       "model");
  }

  std::string
  default_model_name(const bool dynamic_driver,
                     const bool cracks,
                     const bool free_crack_faces)
  {
    const bool energy = dynamic_driver || (cracks && !free_crack_faces);
    return energy ? "pdlsm energy" : "pdlsm";
  }

  template <int dim>
  RunPlugins<dim>
  make_plugins(const std::string        &file,
               const Drivers::Settings  &driver_settings,
               const Fracture::Settings &fracture,
               const ModelChoice        &model,
               dealii::ParameterHandler *parameters,
               const double              density,
               const Solvers::Settings  &linear_solver)
  {
    RunPlugins<dim> plugins;
    plugins.driver = Drivers::create(driver_settings.type, file);
    plugins.driver->initialize(driver_settings, file, dim);
    plugins.model_name = model.name == "auto" ?
                           default_model_name(plugins.driver->dynamic(),
                                              model.pre_existing_cracks ||
                                                fracture.criterion != "none",
                                              model.free_crack_faces) :
                           model.name;
    if (parameters != nullptr)
      {
        plugins.model = PDModels::create<dim>(plugins.model_name, file);
        parameters->enter_subsection("Peridynamics");
        plugins.model->parse_parameters(*parameters, file);
        parameters->leave_subsection();
        const PDModels::Layout layout = plugins.model->layout();
        if (model.free_crack_faces && !layout.free_crack_faces)
          throw InputError(file,
                           "Peridynamics/Crack faces",
                           "'free surface' is an option of the collocated "
                           "pdlsm; " +
                             plugins.model_name + " treats crack faces itself",
                           "'cut bonds', or Peridynamics/Model = pdlsm");
        // Type = auto chooses the preconditioner itself.
        if (linear_solver.model_preconditioner() &&
            linear_solver.type != "auto" && !layout.preconditioner)
          throw InputError(file,
                           "Linear solver/Preconditioner",
                           "'pd model' asks the PD model for an approximate "
                           "inverse of its own, and " +
                             plugins.model_name + " has none",
                           "amg fe, amg or ilu, or Peridynamics/Model = lps "
                           "fft");
        if (!layout.tangent && plugins.driver->needs_tangent())
          check_forces_only_model(file,
                                  plugins.model_name,
                                  *plugins.model,
                                  *plugins.driver,
                                  driver_settings.type,
                                  linear_solver);
        if (!layout.breakable_bonds &&
            (model.pre_existing_cracks || fracture.criterion != "none"))
          throw InputError(file,
                           "Peridynamics/Model",
                           plugins.model_name +
                             " cannot cut or break single bonds, and " +
                             (model.pre_existing_cracks ?
                                std::string("Peridynamics/Pre-existing cracks "
                                            "cut") :
                                "Fracture/Criterion = " + fracture.criterion +
                                  " breaks") +
                             " them",
                           "no pre-existing cracks and Fracture/Criterion = "
                           "none, or another Peridynamics/Model");
      }
    const bool nonlinear_model = plugins.model && !plugins.model->linear();
    plugins.criterion =
      Fracture::create_criterion<dim>(fracture.criterion, file);
    if (plugins.criterion)
      plugins.criterion->initialize(fracture, file);
    check_plugins<dim>(
      *plugins.driver,
      plugins.criterion.get(),
      make_run_traits(file,
                      dim,
                      plugins.model_name,
                      nonlinear_model,
                      density,
                      resolve_linear_solver(linear_solver,
                                            plugins.model.get(),
                                            *plugins.driver),
                      driver_settings.type,
                      plugins.model &&
                        plugins.model->layout().smooth_degradation,
                      plugins.model && plugins.model->layout().tangent_rows()),
      fracture);
    return plugins;
  }

#define INSTANTIATE(dim)                                                          \
  template RunPlugins<dim>   make_plugins<dim>(const std::string &,               \
                                             const Drivers::Settings &,         \
                                             const Fracture::Settings &,        \
                                             const ModelChoice &,               \
                                             dealii::ParameterHandler *,        \
                                             double,                            \
                                             const Solvers::Settings &);        \
  template void              check_plugins<dim>(const Drivers::Interface &,       \
                                   const Fracture::Criterion<dim> *, \
                                   const Drivers::RunTraits &,       \
                                   const Fracture::Settings &);      \
  template Solvers::Settings resolve_linear_solver<dim>(                          \
    const Solvers::Settings &,                                                    \
    const PDModels::Interface<dim> *,                                             \
    const Drivers::Interface &);
  PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
} // namespace pdfem
