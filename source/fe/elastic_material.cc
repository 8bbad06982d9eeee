// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/fe/elastic_material.h>

#include <deal.II/fe/fe_values.h>

namespace pdfem
{
  namespace FE
  {
    double
    ElasticMaterial::lambda() const
    {
      const double E = youngs_modulus, nu = poissons_ratio;
      return plane_stress ? E * nu / (1. - nu * nu) :
                            E * nu / ((1. + nu) * (1. - 2. * nu));
    }

    double
    ElasticMaterial::mu() const
    {
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }

    template <int dim>
    void
    cell_stiffness(const dealii::FEValues<dim, dim> &fv,
                   const ElasticMaterial            &material,
                   std::vector<double>              &K)
    {
      // The vector elements are primitive: phi_i = N_i e_{c_i}, so with
      // g = grad N: div phi_i = g_i[c_i] and
      // 2 eps_i : eps_j = g_i . g_j delta_{c_i c_j} + g_i[c_j] g_j[c_i].
      const double                                  lambda  = material.lambda();
      const double                                  mu      = material.mu();
      const auto                                   &fe_cell = fv.get_fe();
      const unsigned int                            n       = fv.dofs_per_cell;
      static thread_local std::vector<unsigned int> comp;
      comp.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        comp[i] = fe_cell.system_to_component_index(i).first;
      K.assign(n * n, 0.);
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
        {
          const double JxW = fv.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            {
              const dealii::Tensor<1, dim> gi = fv.shape_grad(i, q) * JxW;
              for (unsigned int j = i; j < n; ++j)
                {
                  const dealii::Tensor<1, dim> &gj = fv.shape_grad(j, q);
                  double v = lambda * gi[comp[i]] * gj[comp[j]] +
                             mu * gi[comp[j]] * gj[comp[i]];
                  if (comp[i] == comp[j])
                    v += mu * (gi * gj);
                  K[i * n + j] += v;
                }
            }
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < i; ++j)
          K[i * n + j] = K[j * n + i];
    }

#define INSTANTIATE(dim)                                                \
  template void cell_stiffness<dim>(const dealii::FEValues<dim, dim> &, \
                                    const ElasticMaterial &,            \
                                    std::vector<double> &);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace FE
} // namespace pdfem
