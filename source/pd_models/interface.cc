// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model family: its registries and the defaults of Interface.
#include <pdfem/base/config.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>

#include <stdexcept>
#include <string>

namespace pdfem
{
  namespace PDModels
  {
    template <int dim>
    Plugins::Registry<Interface<dim>> &
    registry()
    {
      static Plugins::Registry<Interface<dim>> models;
      return models;
    }

    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const std::string &name, const std::string &file)
    {
      return registry<dim>().create(name,
                                    file,
                                    "Peridynamics/Model",
                                    "PD model");
    }

    template <int dim>
    void
    Interface<dim>::parse_parameters(dealii::ParameterHandler &,
                                     const std::string &)
    {}

    template <int dim>
    Layout
    Interface<dim>::layout() const
    {
      return Layout();
    }

    template <int dim>
    double
    Interface<dim>::nodal_volume(const unsigned int k) const
    {
      return (*region.pd_volume)[k];
    }

    template <int dim>
    std::vector<std::pair<std::string, double>>
    Interface<dim>::constants() const
    {
      return {};
    }

    template <int dim>
    double
    Interface<dim>::damage(const std::size_t o, const NodalField<dim> &) const
    {
      const PD::Families &f     = *region.families;
      const std::size_t   first = f.offsets[o], last = f.offsets[o + 1];
      if (last == first)
        return 0.;
      std::size_t n_intact = 0;
      for (std::size_t j = first; j < last; ++j)
        n_intact += f.intact[j];
      return 1. - double(n_intact) / double(last - first);
    }

    namespace
    {
      [[noreturn]] void
      not_provided(const char *what, const char *layout)
      {
        throw std::logic_error(std::string("this PD model does not provide ") +
                               what + " (it is a " + layout + " model)");
      }
    } // namespace

    template <int dim>
    void
    Interface<dim>::forces(std::size_t,
                           std::size_t,
                           const NodalField<dim> &,
                           double *) const
    {
      not_provided("forces()", "family-element");
    }

    template <int dim>
    void
    Interface<dim>::tangent_row(std::size_t,
                                const NodalField<dim> &,
                                std::vector<dealii::Tensor<2, dim>> &) const
    {
      not_provided("tangent_row()", "family-element");
    }

    template <int dim>
    void
    Interface<dim>::tangent_products(std::size_t,
                                     std::size_t,
                                     const NodalField<dim> &,
                                     const NodalField<dim> &,
                                     double *) const
    {
      throw std::logic_error(
        "this PD model does not provide tangent_products() (its Layout "
        "says tangent_products = false)");
    }

    template <int dim>
    void
    Interface<dim>::family_forces(std::size_t,
                                  const NodalField<dim> &,
                                  std::vector<dealii::Tensor<1, dim>> &) const
    {
      not_provided("family_forces()", "row");
    }

    template <int dim>
    void
    Interface<dim>::family_tangent(std::size_t,
                                   const NodalField<dim> &,
                                   std::vector<dealii::Tensor<2, dim>> &) const
    {
      not_provided("family_tangent()", "row");
    }

    template <int dim>
    void
    Interface<dim>::family_diagonal_blocks(
      const std::size_t                    o,
      const NodalField<dim>               &u,
      std::vector<dealii::Tensor<2, dim>> &blocks) const
    {
      // The owner and the intact members: (1 + intact)^2 tangent blocks.
      const PD::Families &f = *region.families;
      std::size_t         n = 1;
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        n += f.intact[j] ? 1 : 0;
      std::vector<dealii::Tensor<2, dim>> tangent;
      family_tangent(o, u, tangent);
      AssertThrow(tangent.size() == n * n,
                  dealii::ExcMessage("a family-element PD model's tangent "
                                     "must have (1 + intact bonds)^2 blocks"));
      blocks.resize(n);
      for (std::size_t a = 0; a < n; ++a)
        blocks[a] = tangent[a * n + a];
    }

#define INSTANTIATE(dim)                                                       \
  template class Interface<dim>;                                               \
  template Plugins::Registry<Interface<dim>> &registry<dim>();                 \
  template std::unique_ptr<Interface<dim>>    create<dim>(const std::string &, \
                                                       const std::string &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem
