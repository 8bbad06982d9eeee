// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FRACTURE_CRITERION_H
#define PDFEM_FRACTURE_CRITERION_H

#include <pdfem/base/config.h>
#include <pdfem/base/plugins.h>
#include <pdfem/fracture/crack_growth.h>
#include <pdfem/fracture/settings.h>

#include <memory>
#include <string>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    class JsonWriter;
  }

  namespace Fracture
  {
    /** What a criterion may check of the rest of a run before it starts. */
    struct CriterionTraits
    {
      std::string file; // for messages
      /// The driver integrates in time.
      bool dynamic_driver = false;
      /// The driver's name, for messages.
      std::string driver_name;
    };

    /**
     * A crack criterion plugin (specs/004 §3): after each converged state
     * it decides which bonds break and where cracks grow. Register one with
     * PDFEM_REGISTER_CRITERION at the end of its `.cc` file; it is then a
     * choice of `Fracture/Criterion`. The crack state it works on (paths,
     * tips, the interaction integral) is a CrackGrowth; bonds break through
     * the coupled system (CoupledSystem::break_bonds(),
     * CoupledSystem::break_bonds_if()).
     *
     * The criterion also says what it adds to the outputs: history.csv
     * columns, a progress fragment and members of summary.json's "final".
     */
    template <int dim>
    class Criterion
    {
    public:
      virtual ~Criterion() = default;

      /// Take the parsed `subsection Fracture` and validate what this
      /// criterion needs (InputError naming @p file and the parameter).
      virtual void
      initialize(const Settings &settings, const std::string &file);

      /// Throw InputError if the criterion cannot work in this run.
      virtual void
      check(const CriterionTraits &traits) const;

      /// Does the criterion follow crack tips (2D ends, 3D front points)?
      virtual bool
      tracks_tips() const
      {
        return false;
      }

      /**
       * Evaluate on @p results; where @p allow_growth, break bonds in
       * @p system and record the growth in @p cracks. Collective.
       */
      virtual Assessment
      evaluate(CrackGrowth<dim>                  &cracks,
               Coupling::CoupledSystem<dim>      &system,
               const Coupling::NodalResults<dim> &results,
               bool                               allow_growth) = 0;

      /// history.csv columns after the reactions.
      virtual std::vector<std::string>
      history_columns(const CrackGrowth<dim> &cracks) const;

      /// Their values after @p assessment (appended to @p row).
      virtual void
      history_values(const CrackGrowth<dim> &cracks,
                     const Assessment       &assessment,
                     std::vector<double>    &row) const;

      /// A fragment of the progress line ("  K_eq/K_Ic 0.93").
      virtual std::string
      progress(const CrackGrowth<dim> &cracks,
               const Assessment       &assessment) const;

      /// Members of summary.json's "final" object.
      virtual void
      write_final(const CrackGrowth<dim> &cracks,
                  const Assessment       &assessment,
                  IO::JsonWriter         &json) const;

      /// The parameters.
      const Settings &
      settings() const
      {
        return parameters;
      }

    protected:
      Settings parameters;
    };

    /// The registry of criteria for dimension @p dim.
    template <int dim>
    Plugins::Registry<Criterion<dim>> &
    registry();

    /// Register @p Class<2> and @p Class<3> (a template on dim).
    template <template <int> class Class>
    bool
    register_criterion(const std::string &name, const std::string &description)
    {
      registry<2>().add(name, description, {}, []() {
        return std::unique_ptr<Criterion<2>>(new Class<2>());
      });
#if PDFEM_WITH_3D
      registry<3>().add(name, description, {}, []() {
        return std::unique_ptr<Criterion<3>>(new Class<3>());
      });
#endif
      return true;
    }

    /// The criterion @p name, or nullptr for "none" (InputError naming
    /// `Fracture/Criterion` if unknown).
    template <int dim>
    std::unique_ptr<Criterion<dim>>
    create_criterion(const std::string &name, const std::string &file);
  } // namespace Fracture
} // namespace pdfem

/**
 * Register the criterion class template @p classname (on dim) under
 * @p name (a `Fracture/Criterion` value) with a one-line @p description;
 * at namespace scope in its `.cc`.
 */
#define PDFEM_REGISTER_CRITERION(classname, name, description)              \
  namespace                                                                 \
  {                                                                         \
    const bool PDFEM_PLUGIN_CONCAT(pdfem_criterion_registered_, __LINE__) = \
      ::pdfem::Fracture::register_criterion<classname>(name, description);  \
  }

#endif
