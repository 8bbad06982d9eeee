// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FFT_GRID_H
#define PDFEM_FFT_GRID_H

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace pdfem
{
  /**
   * Peridynamic operators on a uniform periodic grid, evaluated as sums of
   * a(x) [b * c](x) with FFTs (the fast convolution-based method, FCBM, of
   * Jafarzadeh et al. 2022; specs/002) or by the direct neighbour sum, for
   * comparison. Bounded bodies of any shape are embedded in the periodic
   * box with masks (the embedded-constraint method, specs/002 §2.5).
   */
  namespace FFT
  {
    /**
     * A uniform periodic grid (the box T of specs/002 §2.2): n[k] nodes of
     * spacing[k] in direction k, the node (i_0, ..., i_{dim-1}) at
     * x = (i_0 spacing[0], ...). Nodes are numbered with the last index
     * fastest (FFTW's row-major order), node = (i_0 n_1 + i_1) n_2 + i_2.
     * Every node carries the same volume (area in 2D) Delta V = prod
     * spacing[k] (the midpoint quadrature of specs/002 §2.3).
     *
     * Nodal fields are std::vector<double>: a scalar field holds N values,
     * a vector field dim N values, component c of node k at c N + k. An
     * operator distributed over MPI ranks (FftOperator with several ranks)
     * takes and returns the fields of its rank's Slab only, in the same
     * layout with N the slab's node count.
     */
    template <int dim>
    struct Grid
    {
      std::array<unsigned int, dim> n{};
      std::array<double, dim>       spacing{};

      /// N = prod n[k].
      std::size_t
      n_nodes() const;

      /// Delta V = prod spacing[k].
      double
      node_volume() const;

      /// The node with grid indices @p i.
      std::size_t
      node(const std::array<unsigned int, dim> &i) const;

      /// The grid indices of @p node.
      std::array<unsigned int, dim>
      indices(std::size_t node) const;

      /// The position of @p node.
      std::array<double, dim>
      position(std::size_t node) const;
    };

    /**
     * The part of a Grid one MPI rank holds: the whole planes i_0 =
     * first_plane, ..., first_plane + n_planes - 1 of the slowest index
     * (FFTW's MPI layout). Nodes are numbered with i_0 slowest, so the slab
     * is the contiguous range [begin, end) of box nodes: box node begin + k
     * is the rank's local node k. A rank may hold no plane (more ranks than
     * planes): then begin = end.
     */
    struct Slab
    {
      unsigned int first_plane = 0;
      unsigned int n_planes    = 0;
      std::size_t  begin       = 0;
      std::size_t  end         = 0;

      /// end - begin.
      std::size_t
      n_nodes() const
      {
        return end - begin;
      }

      /// Whether box node @p node is in the slab.
      bool
      contains(const std::size_t node) const
      {
        return begin <= node && node < end;
      }
    };

    /// The PD models the operators evaluate.
    enum class Model
    {
      /// Linearised bond-based model, f = C(xi) eta with
      /// C = alpha omega xi (x) xi / |xi|^2 (specs/002 eq. 17).
      linear_bond_based,
      /// The rotation-invariant nonlinear bond-based model
      /// f = alpha omega / (2 |xi|^2) (2 xi.eta + eta.eta)(xi + eta)
      /// (specs/002 eqs. 19, 21).
      nonlinear_bond_based,
      /// The linearised linear peridynamic solid, state based (specs/002
      /// §1.4, eqs. 33-36).
      lps
    };

    /// "linear bond based", "nonlinear bond based", "lps".
    std::string
    model_name(Model model);

    /**
     * A model with its constants. The influence function omega(r) is called
     * for 0 < r <= horizon only (omega = 0 beyond the horizon and at xi = 0,
     * specs/002 §2.3); default 1 / r.
     */
    struct Material
    {
      Model  model   = Model::linear_bond_based;
      double horizon = 0.;
      /// Bond-based models: alpha in C = alpha omega xi (x) xi / |xi|^2
      /// (specs/002 §1.2: 2D plane stress alpha = 9 E / (pi delta^3), 3D
      /// alpha = 12 E / (pi delta^4) for omega = 1 / r).
      double micromodulus = 0.;
      /// LPS: the bulk modulus kappa (in 2D the planar bulk modulus kappa':
      /// kappa + mu / 3 in plane strain, E / (2 (1 - nu)) in plane stress)
      /// and the shear modulus mu.
      double bulk_modulus  = 0.;
      double shear_modulus = 0.;
      /// omega(r); empty: 1 / r.
      std::function<double(double)> influence;

      /// omega(r) for 0 < r <= horizon.
      double
      omega(double r) const;
    };

    /**
     * One bond of the discrete horizon: the grid offset p (xi = p .
     * spacing, 0 < |xi| <= horizon) and |xi|.
     */
    template <int dim>
    struct Offset
    {
      std::array<int, dim>    p{};
      std::array<double, dim> xi{};
      double                  length = 0.;
    };

    /**
     * The bonds of the discrete horizon of @p grid: every offset with
     * 0 < |xi| <= horizon (1 + 1e-10), the relative slack keeping offsets
     * at exactly m spacings for integer m = horizon / spacing. Throws
     * InputError unless 2 max|p_k| < n[k] in every direction, i.e. unless
     * a bond reaches each node at most once in the periodic box.
     */
    template <int dim>
    std::vector<Offset<dim>>
    horizon_offsets(const Grid<dim> &grid, double horizon);

    /**
     * Checks the grid and the material (positive sizes, horizon at least
     * one spacing, constants of the model set) and throws InputError
     * naming the bad value.
     */
    template <int dim>
    void
    check_input(const Grid<dim> &grid, const Material &material);
  } // namespace FFT
} // namespace pdfem

#endif
