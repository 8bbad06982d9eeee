// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "pdlsm energy": the energy form of the PDLSM operator, with
// the integration-constraint correction of its gradient weights and a
// stabilisation that vanishes on linear fields (issue 16, doc/theory.md
// §12). A family-element model: family k's energy acts on all its nodes.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/parameter_tools.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/pdlsm.h>
#include <pdfem/pd_models/pdlsm_energy.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <cmath>

namespace pdfem
{
  namespace PDModels
  {
    using namespace dealii;

    namespace
    {
      void
      declare_energy_form(ParameterHandler &prm)
      {
        declare_weight_factor(prm);
        prm.enter_subsection("Energy form");
        prm.declare_entry(
          "Gradient fit",
          "linear",
          Patterns::Selection("linear|quadratic"),
          "pdlsm energy: the least-squares fit the gradient weights come "
          "from: linear (first order; the stable time step of FE) or "
          "quadratic (PDLSM's second-order fit; more accurate on smooth "
          "fields, about half the stable time step on irregular meshes).");
        prm.declare_entry(
          "Stabilisation",
          "1",
          Patterns::Double(),
          "pdlsm energy: the modulus of the bond penalty on the non-affine "
          "part of each bond, eta - grad u xi, as a multiple of the shear "
          "modulus mu; >= 0 (0 leaves zero-energy modes).");
        prm.declare_entry(
          "Broken bonds",
          "condense",
          Patterns::Selection("condense|refit"),
          "pdlsm energy: what a family does when bonds break during a run. "
          "condense: its energy becomes its minimum over the lost members' "
          "displacements (a Schur complement; breaking can only release "
          "energy). refit: its gradient weights are fitted again over the "
          "intact bonds (the energy may rise at a break). Bonds cut by a "
          "pre-existing crack are always refitted.");
        prm.declare_entry(
          "Integration correction",
          "true",
          Patterns::Bool(),
          "pdlsm energy: correct the gradient weights so that sum_k V_k "
          "g_kj = s_j (the integration constraint; the patch test holds). "
          "false: the plain least-squares weights.");
        prm.leave_subsection();
      }
    } // namespace

    template <int dim>
    void
    PDLSMEnergy<dim>::parse_parameters(ParameterHandler  &prm,
                                       const std::string &file)
    {
      weight_factor = parse_weight_factor(prm, file);
      prm.enter_subsection("Energy form");
      quadratic_fit   = prm.get("Gradient fit") == "quadratic";
      stabilisation   = prm.get_double("Stabilisation");
      correct         = prm.get_bool("Integration correction");
      condense_broken = prm.get("Broken bonds") == "condense";
      prm.leave_subsection();
      if (!(stabilisation >= 0.) || !std::isfinite(stabilisation))
        throw InputError(file,
                         "Peridynamics/Energy form/Stabilisation",
                         number(stabilisation) + " is not allowed",
                         "a number >= 0 (a multiple of the shear modulus)");
    }

    template <int dim>
    Layout
    PDLSMEnergy<dim>::layout() const
    {
      Layout l;
      l.family_elements  = true;
      l.free_crack_faces = false; // cut families are refitted either way
      return l;
    }

    template <int dim>
    bool
    PDLSMEnergy<dim>::fit(const std::size_t o, FitWorkspace<dim> &ws)
    {
      // The least-squares gradient weights of family o over its intact
      // bonds: a_i (member i), g_k = -sum_i a_i (owner).
      ws.gather(this->region, o, true);
      const auto         &xi = ws.xi, &volume = ws.volume;
      const auto         &bond = ws.bond;
      auto               &a = ws.a, &b = ws.b;
      const PD::Families &f     = *this->region.families;
      const double        delta = (*this->region.horizon)[f.owners[o]];
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        {
          weight[j]      = Tensor<1, dim>();
          bond_weight[j] = 0.;
          in_fit[j]      = f.intact[j];
        }
      const double inv_a2 = 1. / (weight_factor * weight_factor);
      for (std::size_t i = 0; i < bond.size(); ++i)
        {
          const Tensor<1, dim> s = xi[i] / delta;
          bond_weight[bond[i]]   = std::exp(-(s * s) * inv_a2) * volume[i];
        }
      set_stabilisation_weights(o);
      owner_weight[o] = Tensor<1, dim>();
      bool fitted     = false;
      if (quadratic_fit)
        fitted = pdlsm->compute_weights(xi, volume, delta, a, b);
      else if (bond.size() >= dim)
        {
          // M = sum_i w_i s_i (x) s_i in s = xi / delta; a_i = M^-1 w_i s_i
          // / delta. Rejected when M is (nearly) singular: collinear (2D)
          // or coplanar (3D) bonds.
          SymmetricTensor<2, dim> M;
          for (std::size_t i = 0; i < bond.size(); ++i)
            {
              const Tensor<1, dim> s = xi[i] / delta;
              M += bond_weight[bond[i]] * symmetrize(outer_product(s, s));
            }
          const double scale = trace(M);
          if (scale > 0. && determinant(M) > 1e-10 * std::pow(scale, dim))
            {
              const SymmetricTensor<2, dim> M_inv = invert(M);
              a.resize(bond.size());
              for (std::size_t i = 0; i < bond.size(); ++i)
                a[i] = bond_weight[bond[i]] * (M_inv * (xi[i] / delta)) / delta;
              fitted = true;
            }
        }
      if (!fitted)
        return false;
      for (std::size_t i = 0; i < bond.size(); ++i)
        {
          weight[bond[i]] = a[i];
          owner_weight[o] -= a[i];
        }
      return true;
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::set_stabilisation_weights(const std::size_t o)
    {
      // beta_i = w_i / (|xi_i|^2 sum w) over the bonds in the fit.
      const PD::Families &f   = *this->region.families;
      const auto         &x   = *this->region.position;
      const unsigned int  k   = f.owners[o];
      double              sum = 0.;
      n_in_fit[o]             = 0;
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        {
          stabilisation_weight[j] = 0.;
          if (in_fit[j])
            {
              const Tensor<1, dim> bv = x[f.members[j]] - x[k];
              stabilisation_weight[j] = bond_weight[j] / (bv * bv);
              sum += bond_weight[j];
              ++n_in_fit[o];
            }
        }
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (in_fit[j])
          stabilisation_weight[j] /= sum;
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::initialize(const Region<dim> &r)
    {
      this->region = r;
      pdlsm = std::make_unique<PDLSM<dim>>(r.lambda, r.mu, weight_factor);
      const PD::Families &f = *r.families;
      weight.assign(f.n_bonds(), Tensor<1, dim>());
      bond_weight.assign(f.n_bonds(), 0.);
      in_fit.assign(f.n_bonds(), 0);
      stabilisation_weight.assign(f.n_bonds(), 0.);
      n_in_fit.assign(f.owners.size(), 0);
      owner_weight.assign(f.owners.size(), Tensor<1, dim>());
      fitted.assign(f.owners.size(), 0);
      condensed.clear();
      condensed.resize(f.owners.size());
      fit_every_family<dim>(
        r,
        [&](const std::size_t o, FitWorkspace<dim> &ws) {
          fitted[o] = fit(o, ws);
          return fitted[o] != 0;
        },
        std::string(quadratic_fit ? "quadratic" : "linear") + " gradient fit",
        weight_factor,
        "a larger Horizon factor or Weight factor");
      if (correct)
        solve_integration_constraint();
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::bonds_changed(const std::vector<std::size_t> &changed,
                                    const bool free_surfaces)
    {
      // Condensed: the energy loses the lost members' stiffness, and the
      // weights are refitted as well, for the strain the criteria and the
      // output read (displacement_gradient()).
      if (!condense_broken)
        reference_bonds_cut(changed, free_surfaces);
      else
        for (const std::size_t o : changed)
          {
            condense(o);
            fitted[o] = fit(o, workspace);
          }
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::reference_bonds_cut(
      const std::vector<std::size_t> &changed,
      bool /*free_surfaces*/)
    {
      // The energy of a family is that of its intact bonds: its weights
      // are fitted again over them, without the correction (either
      // crack-face choice). The correction of the other families stays
      // that of the uncut body: solved again over the cracked body, with
      // s_j = 0 on the crack faces, the constraint would make a uniform
      // stress across the crack an equilibrium state (K_I of the edge-
      // crack strip -65 %); with the crack faces' share of area in s_j
      // (a crack between node rows) it is not consistent (x (x) s misses
      // the gap's volume; -7.7 %). Refitted locally: +3.2 %
      // (doc/theory.md §12.3). A family left unable to carry the fit
      // stores no strain energy (its stabilisation bonds remain).
      for (const std::size_t o : changed)
        fitted[o] = fit(o, workspace);
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::family_weights(const std::size_t o,
                                     FamilyWeights    &family) const
    {
      // The family's nodes (owner, intact members), their gradient
      // weights, the bonds and the stabilisation weights, those of the
      // last fit: the intact ones, or, in condense() before the refit,
      // those before the break. Written through raw pointers: stores
      // through the vectors reload every array's address at every bond.
      const PD::Families &f               = *this->region.families;
      const auto         &x               = *this->region.position;
      const unsigned int  k               = f.owners[o];
      auto &[nodes, g, bond_vector, beta] = family;
      nodes.resize(1 + n_in_fit[o]);
      g.resize(1 + n_in_fit[o]);
      bond_vector.resize(n_in_fit[o]);
      beta.resize(n_in_fit[o]);
      unsigned int         *node_out = nodes.data();
      Tensor<1, dim>       *g_out = g.data(), *xi_out = bond_vector.data();
      double               *beta_out = beta.data();
      const unsigned int   *members  = f.members.data();
      const std::uint8_t   *fit      = in_fit.data();
      const Tensor<1, dim> *w        = weight.data();
      const double         *sw       = stabilisation_weight.data();
      const Point<dim>      x_k      = x[k];
      *node_out++                    = k;
      *g_out++                       = owner_weight[o];
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (fit[j])
          {
            const unsigned int m = members[j];
            *node_out++          = m;
            *g_out++             = w[j];
            *xi_out++            = x[m] - x_k;
            *beta_out++          = sw[j];
          }
    }

    template <int dim>
    typename PDLSMEnergy<dim>::FamilyWeights
    PDLSMEnergy<dim>::family_weights(const std::size_t o) const
    {
      FamilyWeights family;
      family_weights(o, family);
      return family;
    }

    namespace
    {
      /// H = sum_a u_a (x) g_a over a family's nodes, u_a = u_of(a).
      template <int dim, typename U>
      Tensor<2, dim>
      family_gradient(const std::vector<Tensor<1, dim>> &g, const U &u_of)
      {
        Tensor<2, dim> H;
        for (std::size_t a = 0; a < g.size(); ++a)
          H += outer_product(u_of(a), g[a]);
        return H;
      }

      /**
       * @p A (symmetric, n x n) := its pseudo-inverse V diag(1/lambda) V^T
       * over the eigenvalues |lambda| > 1e-12 max |lambda| (LAPACK syevr,
       * then one BLAS product).
       */
      void
      pseudo_inverse(std::vector<double> &A, const std::size_t size)
      {
        const types::blas_int n = size, zero = 0;
        types::blas_int       found = 0, info = 0, lwork = -1, liwork = -1;
        const double          none = 0.;
        std::vector<double>   lambda(size), V(size * size), work(1);
        std::vector<types::blas_int> support(2 * size), iwork(1);
        const auto                   eigen = [&]() {
          syevr("V",
                "A",
                "U",
                &n,
                A.data(),
                &n,
                &none,
                &none,
                &zero,
                &zero,
                &none,
                &found,
                lambda.data(),
                V.data(),
                &n,
                support.data(),
                work.data(),
                &lwork,
                iwork.data(),
                &liwork,
                &info);
        };
        eigen(); // the workspace query
        lwork  = static_cast<types::blas_int>(work[0]);
        liwork = iwork[0];
        work.resize(lwork);
        iwork.resize(liwork);
        eigen();
        AssertThrow(info == 0,
                    dealii::ExcMessage("LAPACK syevr failed with info " +
                                       std::to_string(info)));
        double largest = 0.;
        for (const double l : lambda)
          largest = std::max(largest, std::abs(l));
        // W = V diag(1/lambda) over the kept eigenvalues, A = W V^T.
        std::vector<double> W(V);
        for (std::size_t j = 0; j < size; ++j)
          {
            const double l     = lambda[j];
            const double scale = std::abs(l) > 1e-12 * largest ? 1. / l : 0.;
            for (std::size_t i = 0; i < size; ++i)
              W[j * size + i] *= scale;
          }
        const double one = 1., nothing = 0.;
        gemm("N",
             "T",
             &n,
             &n,
             &n,
             &one,
             W.data(),
             &n,
             V.data(),
             &n,
             &nothing,
             A.data(),
             &n);
      }
    } // namespace

    template <int dim>
    void
    PDLSMEnergy<dim>::weights_forces(const FamilyWeights               &w,
                                     const std::vector<Tensor<1, dim>> &u,
                                     const double                       V,
                                     std::vector<Tensor<1, dim>>       &f) const
    {
      // f_a = V_k sigma_k g_a (strain energy) + G_s V_k sum_i beta_i C_ia
      // z_i (stabilisation), z_i = u_mi - u_k - H xi_i, H = sum_a u_a (x)
      // g_a, C_ia = [a = m_i] - [a = k] - g_a . xi_i; that is
      //   f_a = A g_a + G beta_i z_i [a = m_i] - G [a = k] sum_i beta_i z_i,
      //   A = V sigma - G Q,  Q = sum_i beta_i z_i (x) xi_i = R - H M,
      // with R = sum_i beta_i (u_mi - u_k) (x) xi_i and M = sum_i beta_i
      // xi_i (x) xi_i gathered beside H: two passes over the bonds, the
      // second one writing the forces.
      const auto &[nodes, g, xi, beta] = w;
      const std::size_t n              = nodes.size();
      const bool        stabilised     = stabilisation > 0.;
      Tensor<2, dim>    H              = outer_product(u[0], g[0]), R, M;
      for (std::size_t i = 0; i + 1 < n; ++i)
        {
          H += outer_product(u[i + 1], g[i + 1]);
          if (stabilised)
            {
              R += outer_product(beta[i] * (u[i + 1] - u[0]), xi[i]);
              M += outer_product(beta[i] * xi[i], xi[i]);
            }
        }
      const double   G = stabilisation * this->region.mu * V;
      Tensor<2, dim> A = V * Tensor<2, dim>(pdlsm->stress(H));
      if (stabilised)
        A -= G * (R - H * M);
      f.resize(n);
      Tensor<1, dim> z_sum; // sum_i beta_i z_i
      for (std::size_t i = 0; i + 1 < n; ++i)
        {
          f[i + 1] = A * g[i + 1];
          if (stabilised)
            {
              const Tensor<1, dim> z = beta[i] * (u[i + 1] - u[0] - H * xi[i]);
              f[i + 1] += G * z;
              z_sum += z;
            }
        }
      f[0] = A * g[0] - G * z_sum;
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::family_forces(const std::size_t            o,
                                    const NodalField<dim>       &u,
                                    std::vector<Tensor<1, dim>> &f) const
    {
      const CondensedFamily *c = condensed[o].get();
      if (c == nullptr)
        {
          // The family's weights and displacements gathered into vectors
          // the thread reuses: weights_forces() then runs on them from the
          // cache. A new FamilyWeights per family and product (four
          // allocations) took a third of the samples of the energy-form
          // run of doc/benchmarks/fracture.md §6
          // (doc/changes/20261126_energy_form_products.md).
          thread_local FamilyWeights               w;
          thread_local std::vector<Tensor<1, dim>> u_local;
          family_weights(o, w);
          u_local.resize(w.nodes.size());
          for (std::size_t a = 0; a < w.nodes.size(); ++a)
            u_local[a] = u[w.nodes[a]];
          weights_forces(w, u_local, (*this->region.pd_volume)[w.nodes[0]], f);
          return;
        }
      // Condensed: y = K [u_r; 0], u_L = -K_LL^+ y_L, f = (K [u_r; u_L])_r.
      const FamilyWeights        &w = c->original;
      std::vector<Tensor<1, dim>> u0(w.nodes.size()), y;
      for (const std::size_t a : c->kept)
        u0[a] = u[w.nodes[a]];
      const auto        forces = [&]() { weights_forces(w, u0, c->volume, y); };
      const std::size_t m      = dim * c->lost.size();
      if (m > 0)
        {
          // u_L = -K_LL^+ y_L on contiguous y_L: the product's inner loop
          // then streams one row of K_LL^+ (indexing y through the lost
          // list in it took half of the condensed families' time).
          forces();
          thread_local std::vector<double> y_lost;
          y_lost.resize(m);
          for (std::size_t q = 0; q < m; ++q)
            y_lost[q] = y[c->lost[q / dim]][q % dim];
          const double *P = c->lost_inverse.data();
          for (std::size_t r = 0; r < m; ++r)
            {
              double s = 0.;
              for (std::size_t q = 0; q < m; ++q)
                s += P[r * m + q] * y_lost[q];
              u0[c->lost[r / dim]][r % dim] = -s;
            }
        }
      forces();
      f.resize(c->kept.size());
      for (std::size_t a = 0; a < c->kept.size(); ++a)
        f[a] = y[c->kept[a]];
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::family_tangent(const std::size_t o,
                                     const NodalField<dim> &,
                                     std::vector<Tensor<2, dim>> &K) const
    {
      if (const CondensedFamily *c = condensed[o].get())
        {
          condensed_tangent(*c, K);
          return;
        }
      weights_tangent(
        family_weights(o),
        (*this->region.pd_volume)[(*this->region.families).owners[o]],
        K);
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::weights_tangent(const FamilyWeights            &weights,
                                      const double                    V,
                                      std::vector<Tensor<2, dim>>    &K,
                                      const std::vector<std::size_t> *rows,
                                      const std::vector<std::size_t> *columns,
                                      const bool diagonal) const
    {
      // Strain energy: K_ab(i, j) = V (lambda g_a,i g_b,j + mu (delta_ij
      // g_a . g_b + g_a,j g_b,i)). Stabilisation: G_s V (C^T beta C)_ab I
      // with C^T beta C = S_E - p_a . g_b - p_b . g_a + g_a . M g_b,
      // S_E the bond graph's part, p_a = sum_i beta_i E_ia xi_i and M =
      // sum_i beta_i xi_i (x) xi_i: O(n^2) instead of O(n^3), O(n) for
      // the diagonal blocks alone.
      const auto &[nodes, g, bond_vector, beta] = weights;
      const std::size_t n                       = nodes.size();
      const double      lambda = this->region.lambda, mu = this->region.mu;
      const bool        stabilised = stabilisation > 0.;
      const double      G          = stabilisation * this->region.mu * V;
      std::vector<Tensor<1, dim>> p(stabilised ? n : 0);
      Tensor<2, dim>              M;
      double                      beta_sum = 0.;
      for (std::size_t i = 0; stabilised && i + 1 < n; ++i)
        {
          p[i + 1] = beta[i] * bond_vector[i];
          p[0] -= p[i + 1];
          M += beta[i] * outer_product(bond_vector[i], bond_vector[i]);
          beta_sum += beta[i];
        }
      const auto block = [&](const std::size_t a, const std::size_t b) {
        Tensor<2, dim> B;
        const double   gg = g[a] * g[b];
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            B[i][j] = V * (lambda * g[a][i] * g[b][j] +
                           mu * ((i == j ? gg : 0.) + g[a][j] * g[b][i]));
        if (!stabilised)
          return B;
        double s = -(p[a] * g[b]) - (p[b] * g[a]) + g[a] * (M * g[b]);
        if (a == b)
          s += a == 0 ? beta_sum : beta[a - 1];
        else if (a == 0)
          s -= beta[b - 1];
        else if (b == 0)
          s -= beta[a - 1];
        for (unsigned int i = 0; i < dim; ++i)
          B[i][i] += G * s;
        return B;
      };
      const std::size_t n_rows    = rows ? rows->size() : n;
      const std::size_t n_columns = columns ? columns->size() : n;
      const auto        row       = [&](const std::size_t i) {
        return rows ? (*rows)[i] : i;
      };
      const auto column = [&](const std::size_t j) {
        return columns ? (*columns)[j] : j;
      };
      if (diagonal)
        {
          K.resize(n_rows);
          for (std::size_t i = 0; i < n_rows; ++i)
            K[i] = block(row(i), row(i));
          return;
        }
      K.resize(n_rows * n_columns);
      for (std::size_t i = 0; i < n_rows; ++i)
        for (std::size_t j = 0; j < n_columns; ++j)
          K[i * n_columns + j] = block(row(i), column(j));
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::family_diagonal_blocks(
      const std::size_t o,
      const NodalField<dim> & /*u*/,
      std::vector<Tensor<2, dim>> &D) const
    {
      if (const CondensedFamily *c = condensed[o].get())
        {
          condensed_tangent(*c, D, true);
          return;
        }
      weights_tangent(
        family_weights(o),
        (*this->region.pd_volume)[(*this->region.families).owners[o]],
        D,
        nullptr,
        nullptr,
        true);
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::condense(const std::size_t o)
    {
      // The first time: the energy of the weights of the last fit, all
      // its nodes kept.
      const PD::Families &f = *this->region.families;
      if (!condensed[o])
        {
          auto c      = std::make_unique<CondensedFamily>();
          c->original = family_weights(o);
          c->volume   = (*this->region.pd_volume)[f.owners[o]];
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (in_fit[j])
              c->original_bonds.push_back(j);
          for (std::size_t a = 0; a < c->original.nodes.size(); ++a)
            c->kept.push_back(a);
          condensed[o] = std::move(c);
        }
      CondensedFamily         &c = *condensed[o];
      std::vector<std::size_t> kept{0};
      for (std::size_t i = 1; i < c.kept.size(); ++i)
        {
          const std::size_t a = c.kept[i];
          (f.intact[c.original_bonds[a - 1]] ? kept : c.lost).push_back(a);
        }
      if (kept.size() == c.kept.size())
        return;
      c.kept.swap(kept);

      // K_LL^+ over all the lost members. K_LL is symmetric positive
      // semi-definite, and definite with the stabilisation: there its
      // inverse comes from a Cholesky factorisation (LAPACK potrf, potri:
      // m^3 flops). Without it, or where potrf finds K_LL not numerically
      // definite (a family that lost nearly all its members), the
      // pseudo-inverse V diag(1/lambda) V^T over the eigenvalues above
      // 1e-12 of the largest (syevr and one product; the SVD it replaces
      // extracted its pseudo-inverse by m matrix-vector products). The 3D
      // growth run of doc/changes/20261126_energy_form_condensation.md:
      // criterion 9.6-12.1 -> 4.0-4.4 s.
      std::vector<Tensor<2, dim>> K;
      weights_tangent(c.original, c.volume, K, &c.lost, &c.lost);
      const std::size_t    nl = c.lost.size(), m = dim * nl;
      std::vector<double> &inverse = c.lost_inverse;
      inverse.resize(m * m);
      for (std::size_t r = 0; r < m; ++r)
        for (std::size_t q = 0; q < m; ++q)
          inverse[r * m + q] = K[(r / dim) * nl + q / dim][r % dim][q % dim];
      // K_LL is symmetric: its row-major storage is its column-major one.
      const types::blas_int n    = m;
      types::blas_int       info = 1;
      if (stabilisation > 0.)
        {
          std::vector<double> factor(inverse);
          potrf("U", &n, factor.data(), &n, &info);
          if (info == 0)
            potri("U", &n, factor.data(), &n, &info);
          if (info == 0)
            {
              // potri wrote the upper triangle (column major).
              for (std::size_t q = 0; q < m; ++q)
                for (std::size_t r = 0; r <= q; ++r)
                  inverse[r * m + q] = inverse[q * m + r] = factor[q * m + r];
              return;
            }
        }
      pseudo_inverse(inverse, m);
    }

    template <int dim>
    void
    PDLSMEnergy<dim>::condensed_tangent(const CondensedFamily       &c,
                                        std::vector<Tensor<2, dim>> &K,
                                        const bool diagonal) const
    {
      // K' = K_rr - K_rL K_LL^+ K_Lr, the correction by BLAS products;
      // only the blocks it needs (the diagonal: K_aa - K_La^T X_a).
      const std::size_t nr = c.kept.size(), m = dim * c.lost.size();
      weights_tangent(c.original, c.volume, K, &c.kept, &c.kept, diagonal);
      if (m == 0)
        return;
      std::vector<Tensor<2, dim>> blocks;
      weights_tangent(c.original, c.volume, blocks, &c.lost, &c.kept);
      FullMatrix<double> K_Lr(m, dim * nr), P(m, m), X(m, dim * nr);
      for (std::size_t r = 0; r < m; ++r)
        {
          for (std::size_t q = 0; q < m; ++q)
            P(r, q) = c.lost_inverse[r * m + q];
          for (std::size_t b = 0; b < nr; ++b)
            for (unsigned int j = 0; j < dim; ++j)
              K_Lr(r, dim * b + j) = blocks[(r / dim) * nr + b][r % dim][j];
        }
      P.mmult(X, K_Lr);
      if (diagonal)
        {
          for (std::size_t a = 0; a < nr; ++a)
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                for (std::size_t r = 0; r < m; ++r)
                  K[a][i][j] -= K_Lr(r, dim * a + i) * X(r, dim * a + j);
          return;
        }
      FullMatrix<double> correction(dim * nr, dim * nr);
      K_Lr.Tmmult(correction, X);
      for (std::size_t a = 0; a < nr; ++a)
        for (std::size_t b = 0; b < nr; ++b)
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              K[a * nr + b][i][j] -= correction(dim * a + i, dim * b + j);
    }

    template <int dim>
    Tensor<2, dim>
    PDLSMEnergy<dim>::displacement_gradient(const std::size_t      o,
                                            const NodalField<dim> &u) const
    {
      const auto [nodes, g, bond_vector, beta] = family_weights(o);
      return family_gradient(g,
                             [&](const std::size_t a) { return u[nodes[a]]; });
    }

    template <int dim>
    std::vector<std::pair<std::string, double>>
    PDLSMEnergy<dim>::constants() const
    {
      return {{"stabilisation modulus", stabilisation * this->region.mu},
              {"integration constraint residual", constraint_residual},
              {"integration correction iterations",
               double(correction_iterations)}};
    }

#define INSTANTIATE(dim) template class PDLSMEnergy<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::PDLSMEnergy,
  "pdlsm energy",
  "peridynamic least squares in energy form: the forces are the gradient of "
  "sum_k V_k W(strain_k) with corrected gradient weights and a bond "
  "stabilisation; linear, symmetric, conservative",
  pdfem::PDModels::declare_energy_form)
