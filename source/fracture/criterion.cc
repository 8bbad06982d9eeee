// SPDX-License-Identifier: LGPL-2.1-or-later
// The crack criterion family: its registries and the defaults of Criterion.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/json_writer.h>
#include <pdfem/fracture/criterion.h>

namespace pdfem
{
  namespace Fracture
  {
    template <int dim>
    Plugins::Registry<Criterion<dim>> &
    registry()
    {
      static Plugins::Registry<Criterion<dim>> criteria;
      return criteria;
    }

    template <int dim>
    std::unique_ptr<Criterion<dim>>
    create_criterion(const std::string &name, const std::string &file)
    {
      if (name == "none")
        return nullptr;
      return registry<dim>().create(
        name, file, "Fracture/Criterion", "criterion", {"none"});
    }

    template <int dim>
    void
    Criterion<dim>::initialize(const Settings    &settings,
                               const std::string &file)
    {
      parameters = settings;
      if (!(parameters.growth_length > 0.))
        throw InputError(file,
                         "Fracture/Growth length",
                         number(parameters.growth_length) + " is not positive",
                         "> 0 element sizes");
    }

    template <int dim>
    void
    Criterion<dim>::check(const CriterionTraits &) const
    {}

    template <int dim>
    std::vector<std::string>
    Criterion<dim>::history_columns(const CrackGrowth<dim> &) const
    {
      return {};
    }

    template <int dim>
    void
    Criterion<dim>::history_values(const CrackGrowth<dim> &,
                                   const Assessment &,
                                   std::vector<double> &) const
    {}

    template <int dim>
    std::string
    Criterion<dim>::progress(const CrackGrowth<dim> &, const Assessment &) const
    {
      return "";
    }

    template <int dim>
    void
    Criterion<dim>::write_final(const CrackGrowth<dim> &,
                                const Assessment &,
                                IO::JsonWriter &) const
    {}

#define INSTANTIATE(dim)                                             \
  template class Criterion<dim>;                                     \
  template Plugins::Registry<Criterion<dim>> &registry<dim>();       \
  template std::unique_ptr<Criterion<dim>>    create_criterion<dim>( \
    const std::string &, const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Fracture
} // namespace pdfem
