// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/pd/families.h>

#include <deal.II/base/index_set.h>

#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdfem
{
  namespace Coupling
  {
    using dealii::Point;
    using dealii::Tensor;

    namespace
    {
      template <int dim>
      Tensor<1, dim>
      node_vector(const std::vector<double> &u, const unsigned int i)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = u[dim * i + c];
        return v;
      }

      /// Every pair within @p horizon with at least one PD node (both PD
      /// unless @p fe_members): symmetric lists, CSR over all nodes.
      template <int dim>
      void
      find_pairs(const std::vector<Point<dim>>   &x,
                 const double                     horizon,
                 const std::vector<std::uint8_t> &pd,
                 const bool                       fe_members,
                 std::vector<std::size_t>        &offsets,
                 std::vector<unsigned int>       &members)
      {
        std::vector<std::vector<unsigned int>> lists(x.size());
        const std::vector<std::uint8_t>        may_be_member =
          fe_members ? std::vector<std::uint8_t>(x.size(), 1) : pd;
        if constexpr (dim == 1)
          {
            const double r2 = horizon * horizon * (1. + 1e-10);
            for (unsigned int i = 0; i < x.size(); ++i)
              if (pd[i])
                for (unsigned int j = 0; j < x.size(); ++j)
                  if (j != i && may_be_member[j] &&
                      x[i].distance_square(x[j]) <= r2)
                    lists[i].push_back(j);
          }
        else
          {
            std::vector<unsigned int> owners;
            for (unsigned int i = 0; i < x.size(); ++i)
              if (pd[i])
                owners.push_back(i);
            const PD::Families f = PD::find_families<dim>(
              x, std::vector<double>(x.size(), horizon), owners, may_be_member);
            for (std::size_t k = 0; k < owners.size(); ++k)
              lists[owners[k]].assign(f.members.begin() + f.offsets[k],
                                      f.members.begin() + f.offsets[k + 1]);
          }
        // a bond from a PD node to a non-PD node acts on both
        for (unsigned int i = 0; i < x.size(); ++i)
          if (pd[i])
            for (const unsigned int j : lists[i])
              if (!pd[j])
                lists[j].push_back(i);
        offsets.assign(1, 0);
        members.clear();
        for (auto &list : lists)
          {
            std::sort(list.begin(), list.end());
            members.insert(members.end(), list.begin(), list.end());
            offsets.push_back(members.size());
          }
      }
    } // namespace

    template <int dim>
    RNPSystem<dim>::RNPSystem(
      const std::vector<Point<dim>> &x_in,
      const std::vector<double>     &v_in,
      const PDModels::RNPSettings   &settings,
      const std::function<bool(const Point<dim> &, const Point<dim> &)> &cut,
      const Loads                     &loads_in,
      const RNPTangent                 tangent,
      const std::vector<std::uint8_t> &pd_node,
      const LinearElements            &elements,
      const bool                       fe_members,
      const std::vector<double>       &energy_weight)
      : x(x_in)
      , volume(v_in)
      , rnp(settings)
      , loads(loads_in)
      , method(tangent)
      , fe(elements)
    {
      // ---- bonds: every pair within the horizon not cut by a pre-crack
      std::vector<std::size_t>  all_offsets;
      std::vector<unsigned int> all_members;
      find_pairs<dim>(x,
                      settings.horizon,
                      pd_node.empty() ? std::vector<std::uint8_t>(x.size(), 1) :
                                        pd_node,
                      fe_members,
                      all_offsets,
                      all_members);
      offsets.assign(1, 0);
      double shortest = std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          for (std::size_t b = all_offsets[i]; b < all_offsets[i + 1]; ++b)
            {
              const unsigned int j = all_members[b];
              if (cut && cut(x[i], x[j]))
                {
                  n_cut += (j > i);
                  continue;
                }
              members.push_back(j);
              weight.push_back(energy_weight.empty() ?
                                 1. :
                                 0.5 * (energy_weight[i] + energy_weight[j]));
              shortest = std::min(shortest, x[i].distance(x[j]));
            }
          offsets.push_back(members.size());
        }
      fd_step = std::isfinite(shortest) ? 1e-6 * shortest : 1e-6;

      // ---- free DoFs in reverse Cuthill-McKee order of the nodes
      if (loads.constrained.empty())
        loads.constrained.assign(n_dofs(), 0);
      // A node without a bond or an element (cut free by pre-cracks) would
      // make K singular: it is held where it is (decoupled).
      {
        std::vector<std::uint8_t> in_element(x.size(), 0);
        for (const auto &dofs : fe.dofs)
          for (const unsigned int d : dofs)
            in_element[d / dim] = 1;
        for (unsigned int i = 0; i < x.size(); ++i)
          if (offsets[i + 1] == offsets[i] && !in_element[i])
            {
              ++n_decoupled;
              for (unsigned int c = 0; c < dim; ++c)
                loads.constrained[dim * i + c] = 1;
            }
      }
      std::vector<std::vector<unsigned int>> adjacency(x.size());
      for (unsigned int i = 0; i < x.size(); ++i)
        adjacency[i].assign(members.begin() + offsets[i],
                            members.begin() + offsets[i + 1]);
      for (const auto &dofs : fe.dofs)
        for (const unsigned int a : dofs)
          for (const unsigned int b : dofs)
            if (a / dim != b / dim)
              adjacency[a / dim].push_back(b / dim);
      for (auto &list : adjacency)
        {
          std::sort(list.begin(), list.end());
          list.erase(std::unique(list.begin(), list.end()), list.end());
        }
      const std::vector<unsigned int> order =
        Solvers::reverse_cuthill_mckee(adjacency);
      band_row.assign(n_dofs(), -1);
      long next = 0;
      for (const unsigned int i : order)
        for (unsigned int c = 0; c < dim; ++c)
          if (!loads.constrained[dim * i + c])
            band_row[dim * i + c] = next++;
      long bandwidth = dim - 1;
      for (unsigned int i = 0; i < x.size(); ++i)
        for (std::size_t b = offsets[i]; b < offsets[i + 1]; ++b)
          {
            const unsigned int j = members[b];
            for (unsigned int p = 0; p < dim; ++p)
              for (unsigned int q = 0; q < dim; ++q)
                {
                  const long ri = band_row[dim * i + p];
                  const long rj = band_row[dim * j + q];
                  if (ri >= 0 && rj >= 0)
                    bandwidth = std::max(bandwidth, std::abs(ri - rj));
                }
          }
      for (const auto &dofs : fe.dofs)
        for (const unsigned int a : dofs)
          for (const unsigned int b : dofs)
            if (band_row[a] >= 0 && band_row[b] >= 0)
              bandwidth =
                std::max(bandwidth, std::abs(band_row[a] - band_row[b]));
      K.reinit(next, bandwidth);
      f_int.assign(n_dofs(), 0.);
      f_ext.assign(n_dofs(), 0.);
      max_damage.assign(x.size(), 0.);
    }

    template <int dim>
    void
    RNPSystem<dim>::initialize_vector(Vector &v) const
    {
      v.reinit(dealii::complete_index_set(n_dofs()), MPI_COMM_SELF);
    }

    template <int dim>
    void
    RNPSystem<dim>::apply_dirichlet(Vector &u, const double t) const
    {
      std::vector<double> values(u.begin(), u.end());
      if (loads.prescribed)
        loads.prescribed(t, values);
      for (unsigned int d = 0; d < n_dofs(); ++d)
        if (loads.constrained[d])
          u[d] = values[d];
      u.compress(dealii::VectorOperation::insert);
    }

    template <int dim>
    void
    RNPSystem<dim>::node_force(const std::vector<double> &u,
                               const unsigned int         i,
                               double                    *f) const
    {
      Tensor<1, dim>       sum;
      const Tensor<1, dim> ui = node_vector<dim>(u, i);
      for (std::size_t b = offsets[i]; b < offsets[i + 1]; ++b)
        {
          const unsigned int j = members[b];
          sum += volume[j] * weight[b] *
                 rnp.force(x[j] - x[i], node_vector<dim>(u, j) - ui);
        }
      for (unsigned int c = 0; c < dim; ++c)
        f[c] = -volume[i] * sum[c];
    }

    template <int dim>
    void
    RNPSystem<dim>::internal_force(const std::vector<double> &u,
                                   std::vector<double>       &f) const
    {
      f.assign(n_dofs(), 0.);
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const Tensor<1, dim> ui = node_vector<dim>(u, i);
          for (std::size_t b = offsets[i]; b < offsets[i + 1]; ++b)
            {
              const unsigned int j = members[b];
              if (j < i)
                continue;
              const Tensor<1, dim> t =
                (volume[i] * volume[j] * weight[b]) *
                rnp.force(x[j] - x[i], node_vector<dim>(u, j) - ui);
              for (unsigned int c = 0; c < dim; ++c)
                {
                  f[dim * i + c] -= t[c];
                  f[dim * j + c] += t[c];
                }
            }
        }
      fe.add_product(u, f);
    }

    namespace
    {
      /// Visit every entry K(row, col) of the tangent: add(row, col, value)
      /// with the DoF indices; analytic (eqs. (33)-(34) corrected).
      template <int dim, class Add>
      void
      analytic_entries(const std::vector<Point<dim>>   &x,
                       const std::vector<double>       &volume,
                       const std::vector<std::size_t>  &offsets,
                       const std::vector<unsigned int> &members,
                       const std::vector<double>       &weight,
                       const PDModels::RNP<dim>        &rnp,
                       const std::vector<double>       &u,
                       Add                            &&add)
      {
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            const Tensor<1, dim> ui = node_vector<dim>(u, i);
            for (std::size_t b = offsets[i]; b < offsets[i + 1]; ++b)
              {
                const unsigned int j = members[b];
                if (j < i)
                  continue;
                const Tensor<2, dim> A =
                  (volume[i] * volume[j] * weight[b]) *
                  rnp.stiffness(x[j] - x[i], node_vector<dim>(u, j) - ui);
                for (unsigned int p = 0; p < dim; ++p)
                  for (unsigned int q = 0; q < dim; ++q)
                    {
                      add(dim * i + p, dim * i + q, A[p][q]);
                      add(dim * j + p, dim * j + q, A[p][q]);
                      add(dim * i + p, dim * j + q, -A[p][q]);
                      add(dim * j + p, dim * i + q, -A[p][q]);
                    }
              }
          }
      }
    } // namespace

    template <int dim>
    void
    RNPSystem<dim>::dense_tangent(const std::vector<double> &u,
                                  std::vector<double>       &matrix,
                                  const RNPTangent           how) const
    {
      const unsigned int n = n_dofs();
      matrix.assign(std::size_t(n) * n, 0.);
      for (std::size_t e = 0; e < fe.dofs.size(); ++e)
        for (std::size_t a = 0; a < fe.dofs[e].size(); ++a)
          for (std::size_t b = 0; b < fe.dofs[e].size(); ++b)
            matrix[std::size_t(fe.dofs[e][a]) * n + fe.dofs[e][b]] +=
              fe.matrices[e][a * fe.dofs[e].size() + b];
      if (how == RNPTangent::analytic)
        {
          analytic_entries<dim>(x,
                                volume,
                                offsets,
                                members,
                                weight,
                                rnp,
                                u,
                                [&](unsigned int r, unsigned int c, double v) {
                                  matrix[std::size_t(r) * n + c] += v;
                                });
          return;
        }
      // central differences, column by column, rows of the affected nodes
      std::vector<double> w = u;
      double              fp[dim], fm[dim];
      for (unsigned int k = 0; k < x.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const unsigned int col = dim * k + c;
            for (std::size_t b = offsets[k]; b <= offsets[k + 1]; ++b)
              {
                const unsigned int i = b < offsets[k + 1] ? members[b] : k;
                w[col]               = u[col] + fd_step;
                node_force(w, i, fp);
                w[col] = u[col] - fd_step;
                node_force(w, i, fm);
                w[col] = u[col];
                for (unsigned int p = 0; p < dim; ++p)
                  matrix[std::size_t(dim * i + p) * n + col] +=
                    (fp[p] - fm[p]) / (2. * fd_step);
              }
          }
    }

    template <int dim>
    void
    RNPSystem<dim>::tangent_product(const std::vector<double> &u,
                                    const std::vector<double> &v,
                                    std::vector<double>       &Kv) const
    {
      Kv.assign(n_dofs(), 0.);
      fe.add_product(v, Kv);
      analytic_entries<dim>(x,
                            volume,
                            offsets,
                            members,
                            weight,
                            rnp,
                            u,
                            [&](unsigned int r, unsigned int c, double a) {
                              Kv[r] += a * v[c];
                            });
    }

    template <int dim>
    void
    RNPSystem<dim>::assemble_tangent(const std::vector<double> &u,
                                     const RNPTangent           how)
    {
      K.clear_values();
      for (std::size_t e = 0; e < fe.dofs.size(); ++e)
        for (std::size_t a = 0; a < fe.dofs[e].size(); ++a)
          for (std::size_t b = 0; b < fe.dofs[e].size(); ++b)
            {
              const long br = band_row[fe.dofs[e][a]];
              const long bc = band_row[fe.dofs[e][b]];
              if (br >= 0 && bc >= 0 && bc <= br)
                K.add(br, bc, fe.matrices[e][a * fe.dofs[e].size() + b]);
            }
      if (how == RNPTangent::analytic)
        {
          analytic_entries<dim>(x,
                                volume,
                                offsets,
                                members,
                                weight,
                                rnp,
                                u,
                                [&](unsigned int r, unsigned int c, double v) {
                                  const long br = band_row[r];
                                  const long bc = band_row[c];
                                  if (br >= 0 && bc >= 0 && bc <= br)
                                    K.add(br, bc, v);
                                });
          return;
        }
      // Central differences of the nodal forces: perturb one DoF, recompute
      // the force of every node it acts on (the node and its family).
      std::vector<double> w = u;
      double              fp[dim], fm[dim];
      for (unsigned int k = 0; k < x.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const unsigned int col = dim * k + c;
            const long         bc  = band_row[col];
            if (bc < 0)
              continue;
            for (std::size_t b = offsets[k]; b <= offsets[k + 1]; ++b)
              {
                const unsigned int i = b < offsets[k + 1] ? members[b] : k;
                w[col]               = u[col] + fd_step;
                node_force(w, i, fp);
                w[col] = u[col] - fd_step;
                node_force(w, i, fm);
                w[col] = u[col];
                for (unsigned int p = 0; p < dim; ++p)
                  {
                    const long br = band_row[dim * i + p];
                    if (br >= 0 && bc <= br)
                      K.add(br, bc, (fp[p] - fm[p]) / (2. * fd_step));
                  }
              }
          }
    }

    template <int dim>
    double
    RNPSystem<dim>::residual(const Vector &u_in,
                             const double  t,
                             Vector       &r,
                             const bool    assemble)
    {
      const std::vector<double> u(u_in.begin(), u_in.end());
      internal_force(u, f_int);
      f_ext.assign(n_dofs(), 0.);
      if (loads.external_force)
        loads.external_force(t, f_ext);
      initialize_vector(r);
      double norm2 = 0., ext = 0., inner = 0.;
      for (unsigned int d = 0; d < n_dofs(); ++d)
        {
          inner = std::max(inner, std::abs(f_int[d]));
          if (loads.constrained[d])
            continue;
          ext            = std::max(ext, std::abs(f_ext[d]));
          const double v = f_ext[d] - f_int[d];
          r[d]           = v;
          norm2 += v * v;
        }
      r.compress(dealii::VectorOperation::insert);
      scale = std::max(ext, inner);
      if (assemble)
        assemble_tangent(u, method);
      return std::sqrt(norm2);
    }

    template <int dim>
    double
    RNPSystem<dim>::force_scale() const
    {
      return scale;
    }

    template <int dim>
    unsigned int
    RNPSystem<dim>::solve_linear(Vector &du, const Vector &r)
    {
      initialize_vector(du);
      if (!K.factorized() && !K.factorize())
        {
          du = std::numeric_limits<double>::quiet_NaN();
          return 0;
        }
      std::vector<double> b(K.size());
      for (unsigned int d = 0; d < n_dofs(); ++d)
        if (band_row[d] >= 0)
          b[band_row[d]] = r[d];
      K.solve(b);
      for (unsigned int d = 0; d < n_dofs(); ++d)
        if (band_row[d] >= 0)
          du[d] = b[band_row[d]];
      du.compress(dealii::VectorOperation::insert);
      return 1;
    }

    template <int dim>
    Drivers::StabilityReport
    RNPSystem<dim>::check_stability()
    {
      Drivers::StabilityReport report;
      if (!K.factorized())
        report.singular = !K.factorize();
      report.n_negative              = K.n_negative_pivots();
      report.smallest_relative_pivot = K.smallest_relative_pivot();
      return report;
    }

    template <int dim>
    std::vector<double>
    RNPSystem<dim>::damage(const std::vector<double> &u) const
    {
      std::vector<double> d(x.size(), 0.);
      for (unsigned int i = 0; i < x.size(); ++i)
        {
          const Tensor<1, dim> ui = node_vector<dim>(u, i);
          for (std::size_t b = offsets[i]; b < offsets[i + 1]; ++b)
            {
              const unsigned int j = members[b];
              d[i] =
                std::max(d[i],
                         rnp.damage(x[j] - x[i], node_vector<dim>(u, j) - ui));
            }
        }
      return d;
    }

    template <int dim>
    void
    RNPSystem<dim>::update_damage_history(const std::vector<double> &u)
    {
      const std::vector<double> d = damage(u);
      for (unsigned int i = 0; i < x.size(); ++i)
        max_damage[i] = std::max(max_damage[i], d[i]);
    }

    template class RNPSystem<1>;
#define INSTANTIATE(dim) template class RNPSystem<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace Coupling
} // namespace pdfem
