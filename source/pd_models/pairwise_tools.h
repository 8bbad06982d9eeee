// SPDX-License-Identifier: LGPL-2.1-or-later
// What the pairwise bond models (rnp, bond based) share: the volumes their
// bonds carry and the fitted displacement gradient of their output.
#ifndef PDFEM_PD_MODELS_PAIRWISE_TOOLS_H
#define PDFEM_PD_MODELS_PAIRWISE_TOOLS_H

#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <cmath>
#include <vector>

namespace pdfem
{
  namespace PDModels
  {
    /// `Nodal volumes` and `Dirichlet layer`, the lattice a pairwise
    /// model's subsection of @p prm describes (read by the model).
    inline void
    declare_lattice_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii;
      prm.declare_entry("Nodal volumes",
                        "cells",
                        Patterns::Selection("cells|uniform"),
                        "cells: each node's share of its cells (the body's "
                        "volume); uniform: h^dim for every node (a lattice "
                        "of spacing h, the largest cell size).");
      prm.declare_entry("Dirichlet layer",
                        "1",
                        Patterns::Double(0.),
                        "Prescribed displacements act on every node within "
                        "this many horizons of the named boundary (the "
                        "nonlocal boundary layer); 0: the boundary's nodes "
                        "only.");
    }

    /// `Traction layer` (a model that reads it into
    /// Layout::traction_layer declares it).
    inline void
    declare_traction_layer_parameter(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Traction layer",
                        "0",
                        dealii::Patterns::Double(0.),
                        "Tractions on the PD cells' boundary faces act as a "
                        "body force t / l on every node within this many "
                        "horizons of the boundary (the embedded constraints "
                        "of the FFT method; l the layer's volume over the "
                        "boundary's area); 0: on the boundary faces.");
    }

    /// The layout of a pairwise bond model: one horizon, bonds acting on
    /// both ends, prescribed values within @p dirichlet_layer horizons of
    /// their boundary, nodal body forces, crack faces its own.
    inline Layout
    pairwise_layout(const double dirichlet_layer)
    {
      Layout l;
      l.uniform_horizon  = true;
      l.pairwise         = true;
      l.dirichlet_layer  = dirichlet_layer;
      l.nodal_body_force = true;
      l.free_crack_faces = false;
      return l;
    }

    /**
     * Per node of @p r: the volume its bonds carry (@p bond_volume) and its
     * PD share w_k = V_k^pd / V_k (@p pd_share). Bond volumes are the PD
     * cells' shares V_k^pd, every cell's share V_k with FE nodes in the
     * families (an interface node stands for material on both sides), or
     * h^dim for every member (@p uniform: a lattice of spacing h); 0 for
     * nodes that are no family members.
     */
    template <int dim>
    void
    pairwise_bond_volumes(const Region<dim>   &r,
                          const bool           uniform,
                          std::vector<double> &bond_volume,
                          std::vector<double> &pd_share)
    {
      const auto        &V_all = *r.volume;
      const auto        &V_pd  = *r.pd_volume;
      const unsigned int n     = V_all.size();
      bond_volume.assign(n, 0.);
      pd_share.assign(n, 0.);
      for (unsigned int k = 0; k < n; ++k)
        {
          pd_share[k]       = V_all[k] > 0. ? V_pd[k] / V_all[k] : 0.;
          const bool member = V_pd[k] > 0. || r.fe_nodes_in_families;
          bond_volume[k] =
            !member ? 0. :
            uniform ? std::pow(r.spacing, dim) :
                      (r.fe_nodes_in_families ? V_all[k] : V_pd[k]);
        }
    }

    /**
     * A linear fit of the intact bonds' deformation at owner @p o:
     * grad u = (sum w eta (x) xi) (sum w xi (x) xi)^-1 with
     * w = V_m weight(j) / |xi|^2 (j the bond's index in the families); 0
     * where the bonds span no full dimension. Output only: a bond model
     * has no gradient of its own.
     */
    template <int dim, typename Weight>
    dealii::Tensor<2, dim>
    fitted_gradient(const Region<dim>     &r,
                    const std::size_t      o,
                    const NodalField<dim> &u,
                    const Weight          &weight)
    {
      using dealii::Tensor;
      const PD::Families  &f  = *r.families;
      const auto          &x  = *r.position;
      const auto          &V  = *r.volume;
      const unsigned int   k  = f.owners[o];
      const Tensor<1, dim> uk = u[k];
      Tensor<2, dim>       A, B;
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (f.intact[j])
          {
            const unsigned int   m  = f.members[j];
            const Tensor<1, dim> xi = x[m] - x[k];
            const double         w  = V[m] * weight(j) / (xi * xi);
            A += w * outer_product(u[m] - uk, xi);
            B += w * outer_product(xi, xi);
          }
      if (std::abs(determinant(B)) <= 1e-12 * std::pow(trace(B), dim))
        return Tensor<2, dim>();
      return A * invert(B);
    }
  } // namespace PDModels
} // namespace pdfem

#endif
