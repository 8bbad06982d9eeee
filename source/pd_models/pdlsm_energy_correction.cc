// SPDX-License-Identifier: LGPL-2.1-or-later
// "pdlsm energy": the integration-constraint correction of the gradient
// weights (doc/theory.md §12.2), solved by CG over the replicated nodes,
// preconditioned by a sparse factorisation of the regularised operator.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/group_by_key.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/pdlsm_energy.h>

#include <deal.II/base/mpi.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pdfem
{
  namespace PDModels
  {
    using namespace dealii;

    namespace
    {
      /**
       * The weighted linear-fit residual operator of one family, P = W (I -
       * Phi G^-1 Phi^T W), with Phi = [1, (x_a - x_k) / delta] and W the
       * normalised weights w_a (owner: its volume; members: omega V). P is
       * symmetric positive semi-definite and P Phi = 0.
       */
      template <int dim>
      struct FamilyProjector
      {
        std::vector<unsigned int>       nodes;
        std::vector<double>             w;
        std::vector<Tensor<1, dim + 1>> phi;
        FullMatrix<double>              G_inv{dim + 1, dim + 1};

        /// y_a += scale (P v)_a (one component; v, y indexed by node).
        void
        apply(const double *v, double *y, const double scale) const
        {
          Tensor<1, dim + 1> t; // Phi^T W v
          for (std::size_t a = 0; a < nodes.size(); ++a)
            t += w[a] * v[nodes[a]] * phi[a];
          Tensor<1, dim + 1> q; // G^-1 t
          for (unsigned int i = 0; i < dim + 1; ++i)
            for (unsigned int j = 0; j < dim + 1; ++j)
              q[i] += G_inv(i, j) * t[j];
          for (std::size_t a = 0; a < nodes.size(); ++a)
            y[nodes[a]] += scale * w[a] * (v[nodes[a]] - phi[a] * q);
        }

        /// (P)_ab.
        double
        entry(const std::size_t a, const std::size_t b) const
        {
          double q = 0.;
          for (unsigned int i = 0; i < dim + 1; ++i)
            for (unsigned int j = 0; j < dim + 1; ++j)
              q += phi[a][i] * G_inv(i, j) * phi[b][j];
          return (a == b ? w[a] : 0.) - w[a] * w[b] * q;
        }
      };

      /// MPI's type of T (the pieces gathered below).
      template <typename T>
      MPI_Datatype
      mpi_type();
      template <>
      MPI_Datatype
      mpi_type<unsigned int>()
      {
        return MPI_UNSIGNED;
      }
      template <>
      MPI_Datatype
      mpi_type<double>()
      {
        return MPI_DOUBLE;
      }

      /// The pieces of @p local of every rank, in rank order, on rank 0
      /// (empty elsewhere): MPI_Gatherv of the raw values (deal.II's gather
      /// serialises and compresses them: 1.1 of the 5.3 s of set-up on the
      /// 3D energy-form growth run of doc/benchmarks/scaling.md).
      template <typename T>
      std::vector<T>
      gather(std::vector<T> &&local, const MPI_Comm &comm)
      {
        const unsigned int ranks = Utilities::MPI::n_mpi_processes(comm);
        if (ranks == 1)
          return std::move(local);
        // MPI counts and offsets are int.
        AssertThrow(local.size() < std::numeric_limits<int>::max() / ranks,
                    ExcMessage("the integration correction's operator has "
                               "too many entries to gather on one rank"));
        const int        size = local.size();
        std::vector<int> sizes(ranks), offsets(ranks, 0);
        MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, comm);
        for (unsigned int r = 1; r < ranks; ++r)
          offsets[r] = offsets[r - 1] + sizes[r - 1];
        const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
        std::vector<T> all(root ? offsets.back() + sizes.back() : 0);
        MPI_Gatherv(local.data(),
                    size,
                    mpi_type<T>(),
                    all.data(),
                    sizes.data(),
                    offsets.data(),
                    mpi_type<T>(),
                    0,
                    comm);
        return all;
      }

      /// Rows of a sparse matrix: rows[i] has row_length[i] entries, the
      /// next ones of column and value (columns increasing).
      struct SparseRows
      {
        std::vector<unsigned int> rows, row_length, column;
        std::vector<double>       value;
      };

      /// One row of a sparse matrix summed densely: add() entries in any
      /// order, then append_to() writes them (columns increasing) and
      /// clears the row.
      class DenseRow
      {
      public:
        explicit DenseRow(const std::size_t n)
          : value(n, 0.)
          , used(n, 0)
        {}

        void
        add(const unsigned int column, const double v)
        {
          if (!used[column])
            {
              used[column] = 1;
              columns.push_back(column);
            }
          value[column] += v;
        }

        /// As row @p j of @p out; @p sorted: the columns were added in
        /// increasing order.
        void
        append_to(const unsigned int j, SparseRows &out, const bool sorted)
        {
          if (!sorted)
            std::sort(columns.begin(), columns.end());
          out.rows.push_back(j);
          out.row_length.push_back(columns.size());
          for (const unsigned int m : columns)
            {
              out.column.push_back(m);
              out.value.push_back(value[m]);
              value[m] = 0.;
              used[m]  = 0;
            }
          columns.clear();
        }

      private:
        std::vector<double>       value;
        std::vector<std::uint8_t> used;
        std::vector<unsigned int> columns;
      };

      /**
       * sum_k volume[k] P_k over the projectors @p P, row by row over the
       * nodes they reach (of @p n; increasing), P_ab = [a = b] w_a - w_b
       * (w_a G^-1 phi_a) . phi_b, summed into one dense row at a time: on the
       * 3D energy-form growth run this took 0.2 s where inserting every
       * family's block into an Epetra matrix took 2.9 s (its pattern 0.9 s, the
       * additions 2.1 s).
       */
      template <int dim>
      SparseRows
      sum_of_projectors(const std::vector<FamilyProjector<dim>> &P,
                        const std::vector<double>               &volume,
                        const unsigned int                       n)
      {
        // The (family, node in it) pairs of each node.
        using Pair = std::pair<unsigned int, unsigned int>;
        const auto [start, in_family] =
          group_by_key<Pair>(n, [&](const auto &emit) {
            for (std::size_t i = 0; i < P.size(); ++i)
              for (std::size_t a = 0; a < P[i].nodes.size(); ++a)
                emit(P[i].nodes[a], Pair(i, a));
          });
        SparseRows out;
        DenseRow   row(n);
        for (unsigned int j = 0; j < n; ++j)
          {
            if (start[j] == start[j + 1])
              continue;
            for (std::size_t e = start[j]; e < start[j + 1]; ++e)
              {
                const auto [i, a]    = in_family[e];
                const auto        &p = P[i];
                Tensor<1, dim + 1> psi; // V w_a G^-1 phi_a
                for (unsigned int r = 0; r < dim + 1; ++r)
                  for (unsigned int c = 0; c < dim + 1; ++c)
                    psi[r] += p.G_inv(r, c) * p.phi[a][c];
                psi *= volume[i] * p.w[a];
                for (std::size_t b = 0; b < p.nodes.size(); ++b)
                  row.add(p.nodes[b], -p.w[b] * (psi * p.phi[b]));
                row.add(j, volume[i] * p.w[a]);
              }
            row.append_to(j, out, false);
          }
        return out;
      }

      /**
       * The rows of every rank's @p local, summed on rank 0 (@p root) in
       * rank order, with eps diag(A) = 1e-8 @p diag added to the diagonal,
       * or 1 where @p diag is 0 (the nodes no family reaches): all n rows
       * there, none elsewhere.
       */
      SparseRows
      summed_on_root(SparseRows               &&local,
                     const std::vector<double> &diag,
                     const bool                 root,
                     const MPI_Comm            &comm)
      {
        const std::size_t               n = diag.size();
        const std::vector<unsigned int> rows =
                                          gather(std::move(local.rows), comm),
                                        lengths =
                                          gather(std::move(local.row_length),
                                                 comm),
                                        columns =
                                          gather(std::move(local.column), comm);
        const std::vector<double> values = gather(std::move(local.value), comm);
        SparseRows                sum;
        if (!root)
          return sum;
        // The pieces of each row (their first entries), in rank order.
        std::vector<std::size_t> first(rows.size());
        for (std::size_t r = 0, e = 0; r < rows.size(); ++r)
          {
            first[r] = e;
            e += lengths[r];
          }
        const auto [start, piece] =
          group_by_key<std::size_t>(n, [&](const auto &emit) {
            for (std::size_t r = 0; r < rows.size(); ++r)
              emit(rows[r], r);
          });
        sum.column.reserve(columns.size() + n);
        sum.value.reserve(columns.size() + n);
        DenseRow row(n);
        for (unsigned int j = 0; j < n; ++j)
          {
            for (std::size_t q = start[j]; q < start[j + 1]; ++q)
              for (std::size_t e = first[piece[q]];
                   e < first[piece[q]] + lengths[piece[q]];
                   ++e)
                row.add(columns[e], values[e]);
            row.add(j, diag[j] > 0. ? 1e-8 * diag[j] : 1.);
            // One piece comes sorted, with its diagonal.
            row.append_to(j, sum, start[j + 1] - start[j] <= 1);
          }
        return sum;
      }

      /**
       * The preconditioner of the correction's CG: A + eps diag(A), A =
       * sum_k V_k P_k assembled over the ranks (rows split evenly) and
       * factorised once by MUMPS; identity rows for inactive nodes. A is
       * singular (linear fields over each connected part), the
       * regularisation eps = 1e-8 makes it definite and leaves the
       * preconditioned spectrum in [lambda / (lambda + eps d), 1]: CG
       * needs 4-12 iterations where Jacobi needed hundreds to thousands
       * and stagnated on fine meshes (residual 1e-3 at 26 000 nodes). ML's
       * AMG instead stalled at 4e-6 after 260 iterations (centre-crack
       * strip, 12 462 nodes, m = 4), where the factorisation takes 6.7 s
       * (doc/theory.md §12.2).
       *
       * A is assembled in parallel, then gathered and factorised by MUMPS
       * on rank 0 alone, which also applies the factors (the right-hand
       * sides are replicated anyway) and broadcasts the result. MUMPS on
       * two ranks, even with its communicator cut to one process (Amesos'
       * MaxProcs = 1) or a fixed ordering, changed the factors in the last
       * digits from one run to the next, and with them every result of the
       * energy form: a 2-rank run restarted from a checkpoint differed from
       * the run left alone by 1e-14 relative. Centralised on one process,
       * as on one rank, it repeats itself.
       */
      template <int dim>
      class FactorisedOperator
      {
      public:
        FactorisedOperator(const std::vector<FamilyProjector<dim>> &P,
                           const std::vector<double>               &volume,
                           const std::vector<double>               &diag,
                           const MPI_Comm                          &comm)
          : n(diag.size())
          , root(Utilities::MPI::this_mpi_process(comm) == 0)
          , control(1, 0)
          , solver(
              control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Mumps"))
        {
          // Every rank's rows of its families' sum, gathered on rank 0 and
          // summed there in rank order (rows a node's families on several
          // ranks share); eps diag(A) on the diagonal, identity rows for
          // the nodes no family reaches.
          const SparseRows A =
            summed_on_root(sum_of_projectors(P, volume, n), diag, root, comm);
          const auto &[rows, row_length, column, value] = A;

          std::string error;
          if (root)
            try
              {
                const IndexSet                    all = complete_index_set(n);
                TrilinosWrappers::SparsityPattern serial(all, MPI_COMM_SELF);
                std::vector<types::global_dof_index> columns;
                std::size_t                          e = 0;
                for (unsigned int j = 0; j < n; ++j)
                  {
                    columns.assign(column.begin() + e,
                                   column.begin() + e + row_length[j]);
                    serial.add_entries(j, columns.begin(), columns.end(), true);
                    e += row_length[j];
                  }
                serial.compress();
                matrix.reinit(serial);
                e = 0;
                for (unsigned int j = 0; j < n; ++j)
                  {
                    columns.assign(column.begin() + e,
                                   column.begin() + e + row_length[j]);
                    matrix.set(j,
                               row_length[j],
                               columns.data(),
                               value.data() + e,
                               false);
                    e += row_length[j];
                  }
                matrix.compress(VectorOperation::insert);
                b.reinit(all, MPI_COMM_SELF);
                x.reinit(all, MPI_COMM_SELF);
                solver.initialize(matrix);
              }
            catch (const std::exception &e)
              {
                error = ParameterTools::clean_dealii_message(e.what());
              }
          error = Utilities::MPI::broadcast(comm, error, 0);
          if (!error.empty())
            throw RunFailure(
              "singular matrix",
              "the integration-constraint correction (Peridynamics/Model = "
              "pdlsm energy) could not factorise its operator: " +
                error.substr(0, 200));
        }

        /// z = (A + eps diag A)^-1 r for each of the @p components columns
        /// (replicated vectors, length components x n; collective: rank 0
        /// solves, every rank receives z).
        void
        apply(const std::vector<double> &r,
              std::vector<double>       &z,
              const unsigned int         components,
              const MPI_Comm            &comm)
        {
          if (root)
            for (unsigned int c = 0; c < components; ++c)
              {
                for (std::size_t j = 0; j < n; ++j)
                  b[j] = r[c * n + j];
                solver.solve(x, b);
                for (std::size_t j = 0; j < n; ++j)
                  z[c * n + j] = x[j];
              }
          MPI_Bcast(z.data(), components * n, MPI_DOUBLE, 0, comm);
        }

      private:
        /// A's size (nodes).
        const std::size_t n;
        const bool        root;
        /// A on rank 0 (MPI_COMM_SELF), its factors and vectors.
        TrilinosWrappers::SparseMatrix matrix;
        SolverControl                  control;
        TrilinosWrappers::SolverDirect solver;
        TrilinosWrappers::MPI::Vector  b, x;
      };
    } // namespace

    template <int dim>
    void
    PDLSMEnergy<dim>::solve_integration_constraint()
    {
      const PD::Families &f      = *this->region.families;
      const auto         &x      = *this->region.position;
      const auto         &V      = *this->region.pd_volume;
      const auto         &volume = *this->region.volume;
      const auto         &s      = *this->region.boundary_area;
      const unsigned int  n      = x.size();

      // The projectors of the fitted families this rank owns.
      std::vector<FamilyProjector<dim>> P;
      std::vector<std::size_t>          family;
      for (std::size_t o = 0; o < f.owners.size(); ++o)
        {
          if (!fitted[o])
            continue;
          const unsigned int   k     = f.owners[o];
          const double         delta = (*this->region.horizon)[k];
          FamilyProjector<dim> p;
          p.nodes.push_back(k);
          p.w.push_back(volume[k]);
          p.phi.push_back(Tensor<1, dim + 1>());
          p.phi.back()[0] = 1.;
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (f.intact[j])
              {
                const unsigned int   m = f.members[j];
                const Tensor<1, dim> r = (x[m] - x[k]) / delta;
                p.nodes.push_back(m);
                p.w.push_back(bond_weight[j]);
                Tensor<1, dim + 1> phi;
                phi[0] = 1.;
                for (unsigned int d = 0; d < dim; ++d)
                  phi[d + 1] = r[d];
                p.phi.push_back(phi);
              }
          double sum = 0.;
          for (const double w : p.w)
            sum += w;
          FullMatrix<double> G(dim + 1, dim + 1);
          for (std::size_t a = 0; a < p.nodes.size(); ++a)
            {
              p.w[a] /= sum;
              for (unsigned int i = 0; i < dim + 1; ++i)
                for (unsigned int j = 0; j < dim + 1; ++j)
                  G(i, j) += p.w[a] * p.phi[a][i] * p.phi[a][j];
            }
          p.G_inv.invert(G);
          P.push_back(std::move(p));
          family.push_back(o);
        }

      // A c = r, one column per component: A = sum_k V_k P_k, r_j = s_j -
      // sum_k V_k g_kj (the plain weights), both summed over the ranks.
      std::vector<double> rhs(dim * n, 0.), diag(n, 0.), family_volume;
      for (std::size_t i = 0; i < P.size(); ++i)
        {
          const std::size_t o  = family[i];
          const double      Vk = V[f.owners[o]];
          family_volume.push_back(Vk);
          for (std::size_t a = 0; a < P[i].nodes.size(); ++a)
            diag[P[i].nodes[a]] += Vk * P[i].entry(a, a);
          for (unsigned int c = 0; c < dim; ++c)
            rhs[c * n + f.owners[o]] -= Vk * owner_weight[o][c];
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            for (unsigned int c = 0; c < dim; ++c)
              rhs[c * n + f.members[j]] -= Vk * weight[j][c];
        }
      Utilities::MPI::sum(rhs, this->region.comm, rhs);
      Utilities::MPI::sum(diag, this->region.comm, diag);
      std::vector<std::uint8_t> active(n, 0);
      for (unsigned int j = 0; j < n; ++j)
        if (diag[j] > 0.)
          {
            active[j] = 1;
            for (unsigned int c = 0; c < dim; ++c)
              rhs[c * n + j] += s[j][c];
          }

      // Remove the part of r in A's null space (the linear fields over the
      // active nodes: r is orthogonal to it up to round-off when the
      // region is connected) with Gram-Schmidt on 1, x_1, .., x_dim.
      {
        std::vector<std::vector<double>> basis;
        for (unsigned int i = 0; i < dim + 1; ++i)
          {
            std::vector<double> q(n, 0.);
            for (unsigned int j = 0; j < n; ++j)
              if (active[j])
                q[j] = i == 0 ? 1. : x[j][i - 1];
            for (const auto &e : basis)
              {
                double dot = 0.;
                for (unsigned int j = 0; j < n; ++j)
                  dot += q[j] * e[j];
                for (unsigned int j = 0; j < n; ++j)
                  q[j] -= dot * e[j];
              }
            double norm = 0.;
            for (const double v : q)
              norm += v * v;
            if (norm > 0.)
              {
                for (double &v : q)
                  v /= std::sqrt(norm);
                basis.push_back(std::move(q));
              }
          }
        for (unsigned int c = 0; c < dim; ++c)
          for (const auto &e : basis)
            {
              double dot = 0.;
              for (unsigned int j = 0; j < n; ++j)
                dot += rhs[c * n + j] * e[j];
              for (unsigned int j = 0; j < n; ++j)
                rhs[c * n + j] -= dot * e[j];
            }
      }

      const auto product = [&](const std::vector<double> &v,
                               std::vector<double>       &y) {
        std::fill(y.begin(), y.end(), 0.);
        for (std::size_t i = 0; i < P.size(); ++i)
          for (unsigned int c = 0; c < dim; ++c)
            P[i].apply(v.data() + c * n,
                       y.data() + c * n,
                       V[f.owners[family[i]]]);
        Utilities::MPI::sum(y, this->region.comm, y);
      };
      const auto dot = [&](const std::vector<double> &a,
                           const std::vector<double> &b) {
        double sum = 0.;
        for (std::size_t i = 0; i < a.size(); ++i)
          sum += a[i] * b[i];
        return sum;
      };

      // Preconditioned CG from c = 0; stops at a residual of 1e-13 of |s|
      // (the patch test needs about 1e-12) or when 20 iterations bring no
      // new best (round-off, or a right-hand side not in A's range).
      FactorisedOperator<dim> preconditioner(P,
                                             family_volume,
                                             diag,
                                             this->region.comm);
      std::vector<double>     c(dim * n, 0.), c_best = c;
      std::vector<double>     r(dim * n), z(dim * n), p(dim * n), q(dim * n);
      product(c, q);
      for (std::size_t i = 0; i < r.size(); ++i)
        r[i] = rhs[i] - q[i];
      double s_norm = 0.;
      for (unsigned int j = 0; j < n; ++j)
        s_norm += s[j] * s[j];
      s_norm                    = std::sqrt(s_norm);
      const double tolerance    = 1e-13 * std::max(s_norm, 1e-300);
      const auto   precondition = [&] {
        preconditioner.apply(r, z, dim, this->region.comm);
        for (unsigned int c_ = 0; c_ < dim; ++c_)
          for (unsigned int j = 0; j < n; ++j)
            if (!active[j])
              z[c_ * n + j] = 0.;
      };
      precondition();
      p                             = z;
      double             rz         = dot(r, z);
      double             best       = std::sqrt(dot(r, r));
      unsigned int       since_best = 0, it = 0;
      const unsigned int max_iterations = 500;
      for (; it < max_iterations && best > tolerance && since_best < 20; ++it)
        {
          product(p, q);
          const double pq = dot(p, q);
          if (!(pq > 0.))
            break;
          const double alpha = rz / pq;
          for (std::size_t i = 0; i < r.size(); ++i)
            {
              c[i] += alpha * p[i];
              r[i] -= alpha * q[i];
            }
          const double norm = std::sqrt(dot(r, r));
          if (norm < best)
            {
              best       = norm;
              c_best     = c;
              since_best = 0;
            }
          else
            ++since_best;
          precondition();
          const double rz_new = dot(r, z);
          for (std::size_t i = 0; i < p.size(); ++i)
            p[i] = z[i] + rz_new / rz * p[i];
          rz = rz_new;
        }
      correction_iterations = it;
      c.swap(c_best);

      // The correction added to each owned family's weights, and the
      // constraint as it now holds: |sum_k V_k g_kj - s_j| relative to |s|.
      std::vector<double> Pc(dim * n, 0.), check(dim * n, 0.);
      for (std::size_t i = 0; i < P.size(); ++i)
        {
          const std::size_t o  = family[i];
          const double      Vk = V[f.owners[o]];
          for (unsigned int c_ = 0; c_ < dim; ++c_)
            {
              for (const unsigned int a : P[i].nodes)
                Pc[c_ * n + a] = 0.;
              P[i].apply(c.data() + c_ * n, Pc.data() + c_ * n, 1.);
            }
          // The projector's nodes are the owner and the intact members in
          // family order.
          std::size_t a              = 0;
          const auto  correct_weight = [&](Tensor<1, dim> &g) {
            const unsigned int node = P[i].nodes[a++];
            for (unsigned int c_ = 0; c_ < dim; ++c_)
              {
                g[c_] += Pc[c_ * n + node];
                check[c_ * n + node] += Vk * g[c_];
              }
          };
          correct_weight(owner_weight[o]);
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (f.intact[j])
              correct_weight(weight[j]);
        }
      Utilities::MPI::sum(check, this->region.comm, check);
      double error = 0.;
      for (unsigned int j = 0; j < n; ++j)
        if (active[j])
          for (unsigned int c_ = 0; c_ < dim; ++c_)
            error += std::pow(check[c_ * n + j] - s[j][c_], 2);
      constraint_residual = std::sqrt(error) / std::max(s_norm, 1e-300);
    }

#define INSTANTIATE(dim) \
  template void PDLSMEnergy<dim>::solve_integration_constraint();
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem
