// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FFT_DIRECT_OPERATOR_H
#define PDFEM_FFT_DIRECT_OPERATOR_H

#include <pdfem/fft/operator.h>

namespace pdfem
{
  namespace FFT
  {
    /**
     * The operators of Operator<dim> by the direct neighbour sum on the same
     * grid: for each node, a loop over the bonds of the discrete horizon
     * (horizon_offsets(); the offsets, their flat index steps and the
     * kernel factors alpha omega / |xi|^2 or omega are computed once), with
     * the periodic wrap only for the nodes within a horizon of the box's
     * faces. The reference for FftOperator (tests) and its competitor
     * (doc/benchmarks/fft.md). Work O(N M), M bonds per node; memory O(M)
     * besides the mask fields.
     *
     * Each bond is evaluated in the form of the model's force law (specs/002
     * eqs. 17, 21, 36), not in the expanded convolution form, so that the
     * comparison checks the expansion.
     */
    template <int dim>
    class DirectOperator : public Operator<dim>
    {
    public:
      /// @p threads threads share the nodes (rows); results do not depend
      /// on their number.
      DirectOperator(const Grid<dim> &grid,
                     const Material  &material,
                     unsigned int     threads = 1);

      void
      set_masks(const std::vector<double> &body,
                const std::vector<double> &integrity) override;

      void
      apply(const std::vector<double> &u, std::vector<double> &force) override;

      void
      dilatation(const std::vector<double> &u,
                 std::vector<double>       &theta) override;

      void
      energy_density(const std::vector<double> &u,
                     std::vector<double>       &W) override;

      void
      damage(std::vector<double> &d,
             DamageNormalisation  normalisation) override;

      const std::vector<double> &
      weighted_volume() const override;

      double
      bytes_per_node() const override;

      /// The number of bonds of the discrete horizon.
      std::size_t
      n_bonds_per_node() const;

    private:
      /// Calls row(node, wrapped, neighbour) for every node of the grid on
      /// the threads, wrapped telling whether the node is within a horizon
      /// of a face.
      template <typename Row>
      void
      for_each_node(const Row &row) const;

      /// Fills packed: value(node, out) writes the S values of a node.
      template <typename F>
      void
      pack(unsigned int S, const F &value);

      /// The index of the node with grid indices @p i in the padded grid.
      std::size_t
      padded_node(const std::array<unsigned int, dim> &i) const;

      /// The neighbour of @p node across bond @p b.
      std::size_t
      neighbour(std::size_t                          node,
                const std::array<unsigned int, dim> &i,
                bool                                 wrapped,
                unsigned int                         b) const;

      unsigned int                         threads;
      std::vector<Offset<dim>>             offsets;
      std::vector<long long>               step; ///< flat index step of a bond
      std::vector<double>                  factor; ///< per-bond kernel factor
      std::vector<std::array<double, dim>> xis;    ///< xi of each bond
      std::array<unsigned int, dim>        reach{};
      std::array<std::size_t, dim>         strides{};
      /// wrap[d][i + p + reach[d]] = (i + p) mod n[d]
      std::array<std::vector<unsigned int>, dim> wrap;
      std::vector<double>                        beta, body;
      std::vector<double>                        m, theta_work;
      /// The nodal values apply() reads (u, beta, ...: S per node) on the
      /// grid padded by reach[d] on both sides of every direction, with
      /// the periodic images in the padding.
      std::vector<double> packed;
      /// A bond's step in packed (S times its padded flat offset).
      std::vector<long long> bond_step;
    };
  } // namespace FFT
} // namespace pdfem

#endif
