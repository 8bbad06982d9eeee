// SPDX-License-Identifier: LGPL-2.1-or-later
// CoupledSystem: the rigid motions that the prescribed displacements leave
// free (a floating body, found before any solve).
#include <pdfem/base/config.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "coupled_system_impl.h"

namespace pdfem
{
  namespace Coupling
  {
    using namespace dealii;

    namespace
    {
      /// The rigid motions of a body around @p c with size @p L: the
      /// translations, then the rotations e_r x (x - c) / L.
      template <int dim>
      std::vector<Tensor<1, dim>>
      rigid_motions(const Point<dim> &x, const Point<dim> &c, const double L)
      {
        std::vector<Tensor<1, dim>> m(dim * (dim + 1) / 2);
        for (unsigned int d = 0; d < dim; ++d)
          m[d][d] = 1.;
        const Tensor<1, dim> r = (x - c) / L;
        if constexpr (dim == 2)
          m[2] = Tensor<1, 2>({-r[1], r[0]});
        else
          for (unsigned int a = 0; a < 3; ++a)
            {
              Tensor<1, 3> e;
              e[a]     = 1.;
              m[3 + a] = cross_product_3d(e, r);
            }
        return m;
      }

      const char *motion_names[2][6] = {{"translation x",
                                         "translation y",
                                         "rotation about z"},
                                        {"translation x",
                                         "translation y",
                                         "translation z",
                                         "rotation about x",
                                         "rotation about y",
                                         "rotation about z"}};
    } // namespace

    template <int dim>
    std::vector<std::string>
    CoupledSystem<dim>::unheld_rigid_motions() const
    {
      const Impl                     &s     = *impl;
      const std::vector<unsigned int> label = s.piece_labels();
      constexpr unsigned int          n     = dim * (dim + 1) / 2;

      // Each piece's box (centre and size), then the Gram matrix of the
      // rigid motions over its prescribed DoFs (replicated: every rank
      // knows every node and which DoFs are prescribed).
      struct Piece
      {
        unsigned int n_nodes = 0;
        Point<dim>   lo, hi;
        double       gram[n][n] = {};
      };
      std::map<unsigned int, Piece> pieces;
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        {
          Piece &p = pieces[label[k]];
          for (unsigned int d = 0; d < dim; ++d)
            {
              p.lo[d] =
                p.n_nodes == 0 ? s.x[k][d] : std::min(p.lo[d], s.x[k][d]);
              p.hi[d] =
                p.n_nodes == 0 ? s.x[k][d] : std::max(p.hi[d], s.x[k][d]);
            }
          ++p.n_nodes;
        }
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        {
          Piece     &p = pieces[label[k]];
          const auto m =
            rigid_motions<dim>(s.x[k],
                               0.5 * (p.lo + p.hi),
                               std::max(p.lo.distance(p.hi), 1e-300));
          for (unsigned int c = 0; c < dim; ++c)
            if (s.dof_fixed[s.node_dof[k][c]])
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  p.gram[i][j] += m[i][c] * m[j][c];
        }

      std::vector<std::string> unheld;
      for (const auto &[first, p] : pieces)
        {
          if (p.n_nodes < 2)
            continue; // a node without cells and bonds is held (decoupled)
          std::vector<std::string> free;
          for (unsigned int i = 0; i < n; ++i)
            if (p.gram[i][i] == 0.)
              free.push_back(motion_names[dim - 2][i]);
          if (free.empty())
            {
              // Each motion is touched; is a combination of them free?
              LAPACKFullMatrix<double> G(n, n);
              double                   largest = 0.;
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    G(i, j) = p.gram[i][j];
                    largest = std::max(largest, std::abs(p.gram[i][j]));
                  }
              G.compute_eigenvalues();
              double smallest = largest;
              for (unsigned int i = 0; i < n; ++i)
                smallest = std::min(smallest, G.eigenvalue(i).real());
              if (smallest <= 1e-12 * largest)
                free.push_back(dim == 2 ? "a rotation about the held point" :
                                          "a rotation about the held line");
            }
          if (free.empty())
            continue;
          const auto point = [](const Point<dim> &q) {
            std::ostringstream out;
            for (unsigned int d = 0; d < dim; ++d)
              out << (d ? ", " : "(") << q[d];
            return out.str() + ")";
          };
          std::ostringstream line;
          line << (pieces.size() == 1 ? "the body" : "a piece of the body")
               << " (" << p.n_nodes << " nodes, " << point(p.lo) << " to "
               << point(p.hi) << ") can move freely: ";
          for (std::size_t i = 0; i < free.size(); ++i)
            line << (i ? ", " : "") << free[i];
          line << " not held by any prescribed displacement";
          unheld.push_back(line.str());
        }
      return unheld;
    }

    template <int dim>
    std::string
    CoupledSystem<dim>::unheld_component() const
    {
      const Impl &s = *impl;
      const int   c = s.model ? s.model->layout().stiffless_component : -1;
      if (c < 0)
        return "";
      unsigned int n_free = 0, first = 0;
      for (unsigned int k = 0; k < s.n_nodes; ++k)
        if (s.is_pd[k] && !s.is_fe[k] && !s.dof_fixed[s.node_dof[k][c]])
          first = n_free++ == 0 ? k : first;
      if (n_free == 0)
        return "";
      std::ostringstream line;
      line << n_free << " PD node(s), the first at (";
      for (unsigned int d = 0; d < dim; ++d)
        line << (d ? ", " : "") << s.x[first][d];
      line << "), can move freely in "
           << "xyz"[c]
           << ": the PD model gives them no stiffness in that direction and "
              "no prescribed displacement holds it";
      return line.str();
    }

    template <int dim>
    ForceBalance<dim>
    CoupledSystem<dim>::force_balance() const
    {
      const Impl       &s = *impl;
      ForceBalance<dim> balance;
      double            applied = 0., reacted = 0.;
      // Raw arrays at owned-local indices (a global-index lookup per DoF
      // was 3 % of an explicit run that writes this every step).
      const double *fi = s.f_int.begin();
      const double *fe = s.f_ext.begin();
      for (const unsigned int k : s.owned_nodes)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const auto   i     = s.owned_lid[k][c];
            const double f_int = fi[i], f_ext = fe[i];
            balance.internal_resultant[c] += f_int;
            balance.external_resultant[c] += f_ext;
            applied += std::abs(f_ext);
          }
      for (const unsigned int lid : s.held_lid)
        reacted += std::abs(fi[lid] - fe[lid]);
      balance.internal_resultant =
        Utilities::MPI::sum(balance.internal_resultant, s.comm);
      balance.external_resultant =
        Utilities::MPI::sum(balance.external_resultant, s.comm);
      applied      = Utilities::MPI::sum(applied, s.comm);
      reacted      = Utilities::MPI::sum(reacted, s.comm);
      balance.load = 0.5 * (applied > 0. ? applied : reacted);
      return balance;
    }

#define INSTANTIATE(dim)                                                       \
  template std::vector<std::string> CoupledSystem<dim>::unheld_rigid_motions() \
    const;                                                                     \
  template std::string       CoupledSystem<dim>::unheld_component() const;     \
  template ForceBalance<dim> CoupledSystem<dim>::force_balance() const;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
