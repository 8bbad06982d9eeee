// SPDX-License-Identifier: LGPL-2.1-or-later
// The PD model "pdlsm": the collocated PDLSM operator of PDLSM-FEM (the
// strong form L_k = div sigma at every PD node plus the boundary term).
#include <pdfem/base/config.h>
#include <pdfem/pd/families.h>
#include <pdfem/pd_models/interface.h>
#include <pdfem/pd_models/pdlsm.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>


namespace pdfem
{
  namespace PDModels
  {
    using namespace dealii;

    namespace
    {
      /// y = b x for a symmetric tensor stored as deal.II's raw entries
      /// (2D: 00, 11, 01; 3D: 00, 11, 22, 01, 02, 12).
      template <int dim>
      inline void
      symmetric_product(const double *b, const double *x, double *y)
      {
        if constexpr (dim == 2)
          {
            y[0] = b[0] * x[0] + b[2] * x[1];
            y[1] = b[2] * x[0] + b[1] * x[1];
          }
        else
          {
            y[0] = b[0] * x[0] + b[3] * x[1] + b[4] * x[2];
            y[1] = b[3] * x[0] + b[1] * x[1] + b[5] * x[2];
            y[2] = b[4] * x[0] + b[5] * x[1] + b[2] * x[2];
          }
      }

    } // namespace

    /**
     * The collocated PDLSM model (Liu & Xin, EFM 2021, eqs. 26-27; the
     * PDLSM-FEM manual eqs. 11-22; specs/004 §1.2-1.3), row k of the
     * coupled system's PD term:
     *
     *   F_k = -V_k^pd L_k + sigma_k s_k,
     *   L_k = sum_m G_m (u_m - u_k),   sigma_k = C : sym(sum_m (u_m - u_k)
     *   (x) a_m),
     *
     * with the PDLSM weights a_m, b_m of PDModels::PDLSM and G_m =
     * (lambda + mu) b_m + mu tr(b_m) I. The weights belong to the whole
     * initial family (bond states enter only the sums, as in PDLSM-FEM);
     * with free crack faces a family that lost bonds is refitted over its
     * intact ones. Linear in u; the tangent is not symmetric.
     */
    template <int dim>
    class PDLSMCollocation : public Interface<dim>
    {
    public:
      explicit PDLSMCollocation(const double weight_factor = 0.33)
        : weight_factor(weight_factor)
      {}

      void
      parse_parameters(ParameterHandler &prm, const std::string &file) override
      {
        weight_factor = parse_weight_factor(prm, file);
      }

      void
      initialize(const Region<dim> &region) override;

      void
      bonds_changed(const std::vector<std::size_t> &changed,
                    bool                            free_surfaces) override;

      bool
      linear() const override
      {
        return true;
      }

      bool
      symmetric() const override
      {
        return false;
      }

      void
      forces(std::size_t            begin,
             std::size_t            end,
             const NodalField<dim> &u,
             double                *f) const override;

      void
      tangent_row(std::size_t                  o,
                  const NodalField<dim>       &u,
                  std::vector<Tensor<2, dim>> &blocks) const override;

      Tensor<2, dim>
      displacement_gradient(std::size_t            o,
                            const NodalField<dim> &u) const override;

    private:
      /// Fit the weights of family @p o over its bonds (its intact ones
      /// alone with @p intact_only) in the work space @p ws; false if it
      /// cannot carry the fit (its weights are left as they are). Writes
      /// family o's bonds only.
      bool
      fit(std::size_t o, bool intact_only, FitWorkspace<dim> &ws);

      double                      weight_factor;
      std::unique_ptr<PDLSM<dim>> pdlsm;
      /// Per bond: the gradient weight a_m and -V_k G_m (zero once the
      /// bond is broken, so that the kernel needs no state tests).
      std::vector<Tensor<1, dim>>          weight_a;
      std::vector<SymmetricTensor<2, dim>> bond_block;
      /// fit()'s work space for bonds_changed(), kept from family to
      /// family (initialize() fits on the threads, with one each).
      FitWorkspace<dim> workspace;
    };

    template <int dim>
    bool
    PDLSMCollocation<dim>::fit(const std::size_t  o,
                               const bool         intact_only,
                               FitWorkspace<dim> &ws)
    {
      ws.gather(this->region, o, intact_only);
      const auto        &xi = ws.xi, &volume = ws.volume;
      const auto        &bond = ws.bond;
      auto              &a = ws.a, &b = ws.b;
      const unsigned int k = this->region.families->owners[o];
      if (!pdlsm->compute_weights(xi, volume, (*this->region.horizon)[k], a, b))
        return false;
      const double V = (*this->region.pd_volume)[k];
      for (std::size_t i = 0; i < bond.size(); ++i)
        {
          weight_a[bond[i]]   = a[i];
          bond_block[bond[i]] = -V * symmetrize(pdlsm->divergence_block(b[i]));
        }
      return true;
    }

    template <int dim>
    void
    PDLSMCollocation<dim>::initialize(const Region<dim> &r)
    {
      this->region = r;
      pdlsm = std::make_unique<PDLSM<dim>>(r.lambda, r.mu, weight_factor);
      const PD::Families &f = *r.families;
      weight_a.assign(f.n_bonds(), Tensor<1, dim>());
      bond_block.assign(f.n_bonds(), SymmetricTensor<2, dim>());
      // Every family must carry the second-order fit over its whole
      // initial family: if one cannot, the horizon is too small for the
      // mesh (or the weight too narrow).
      fit_every_family<dim>(
        r,
        [&](const std::size_t o, FitWorkspace<dim> &ws) {
          return fit(o, false, ws);
        },
        "second-order PDLSM fit",
        weight_factor,
        "a larger Horizon factor or Weight factor (m >= 3 with a >= 0.25 is "
        "safe on quads and hexes)");
    }

    template <int dim>
    void
    PDLSMCollocation<dim>::bonds_changed(
      const std::vector<std::size_t> &changed,
      const bool                      free_surfaces)
    {
      // With free crack faces a family that lost bonds is fitted over its
      // intact bonds alone (one-sided, as at an outer boundary); one too
      // small for the fit keeps the weights it has.
      const PD::Families &f = *this->region.families;
      for (const std::size_t o : changed)
        {
          if (free_surfaces)
            fit(o, true, workspace);
          for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
            if (!f.intact[j])
              bond_block[j] = SymmetricTensor<2, dim>();
        }
    }

    template <int dim>
    void
    PDLSMCollocation<dim>::forces(const std::size_t      begin,
                                  const std::size_t      end,
                                  const NodalField<dim> &u,
                                  double                *f_out) const
    {
      // Row k: sum_m -V_k G_m du_m + sigma_k s_k, with -V_k G_m from
      // bond_block (zero for broken bonds: no state tests) and sigma_k =
      // C : sym(sum_m du_m (x) a_m) over the intact bonds (boundary nodes
      // only, so the boundary term needs the gradient once per node). Raw
      // arrays; each owner's sums run in the same order on any number of
      // threads, so the result is the same bit for bit.
      static_assert(sizeof(SymmetricTensor<2, dim>) ==
                      SymmetricTensor<2, dim>::n_independent_components *
                        sizeof(double),
                    "bond_block must be a packed array of doubles");
      const PD::Families    &fam = *this->region.families;
      const auto            &s_k = *this->region.boundary_area;
      const double          *xv  = u.values;
      const auto            *lid = u.local_index;
      constexpr unsigned int nb =
        SymmetricTensor<2, dim>::n_independent_components;
      const double *blocks =
        bond_block.empty() ? nullptr : &bond_block[0].access_raw_entry(0);
      for (std::size_t o = begin; o < end; ++o)
        {
          const unsigned int k = fam.owners[o];
          double             xk[dim], dx[dim], gdx[dim], sum[dim] = {};
          for (unsigned int c = 0; c < dim; ++c)
            xk[c] = xv[lid[k][c]];
          const Tensor<1, dim> s        = s_k[k];
          const bool           boundary = s.norm_square() > 0.;
          Tensor<2, dim>       grad_u;
          for (std::size_t j = fam.offsets[o]; j < fam.offsets[o + 1]; ++j)
            {
              const auto &lm = lid[fam.members[j]];
              for (unsigned int c = 0; c < dim; ++c)
                dx[c] = xv[lm[c]] - xk[c];
              symmetric_product<dim>(blocks + nb * j, dx, gdx);
              for (unsigned int c = 0; c < dim; ++c)
                sum[c] += gdx[c];
              if (boundary && fam.intact[j])
                for (unsigned int c = 0; c < dim; ++c)
                  for (unsigned int d = 0; d < dim; ++d)
                    grad_u[c][d] += dx[c] * weight_a[j][d];
            }
          if (boundary)
            {
              const Tensor<1, dim> t = pdlsm->stress(grad_u) * s;
              for (unsigned int c = 0; c < dim; ++c)
                sum[c] += t[c];
            }
          for (unsigned int c = 0; c < dim; ++c)
            f_out[dim * o + c] = sum[c];
        }
    }

    template <int dim>
    void
    PDLSMCollocation<dim>::tangent_row(
      const std::size_t o,
      const NodalField<dim> &,
      std::vector<Tensor<2, dim>> &blocks) const
    {
      const PD::Families  &f = *this->region.families;
      const Tensor<1, dim> s = (*this->region.boundary_area)[f.owners[o]];
      const bool           boundary = s.norm_square() > 0.;
      blocks.assign(1, Tensor<2, dim>());
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (f.intact[j])
          {
            Tensor<2, dim> B = bond_block[j];
            if (boundary)
              B += pdlsm->traction_block(s, weight_a[j]);
            blocks.push_back(B);
            blocks[0] -= B;
          }
    }

    template <int dim>
    Tensor<2, dim>
    PDLSMCollocation<dim>::displacement_gradient(const std::size_t      o,
                                                 const NodalField<dim> &u) const
    {
      // grad u = sum_m (u_m - u_k) (x) a_m over the intact bonds.
      const PD::Families &f = *this->region.families;
      const unsigned int  k = f.owners[o];
      Tensor<2, dim>      grad_u;
      for (std::size_t j = f.offsets[o]; j < f.offsets[o + 1]; ++j)
        if (f.intact[j])
          {
            const unsigned int m = f.members[j];
            for (unsigned int c = 0; c < dim; ++c)
              {
                const double du = u(m, c) - u(k, c);
                for (unsigned int d = 0; d < dim; ++d)
                  grad_u[c][d] += du * weight_a[j][d];
              }
          }
      return grad_u;
    }

    template <int dim>
    std::unique_ptr<Interface<dim>>
    make_pdlsm(const double weight_factor)
    {
      return std::make_unique<PDLSMCollocation<dim>>(weight_factor);
    }

#define INSTANTIATE(dim) \
  template std::unique_ptr<Interface<dim>> make_pdlsm<dim>(double);
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem

PDFEM_REGISTER_PD_MODEL(
  pdfem::PDModels::PDLSMCollocation,
  "pdlsm",
  "peridynamic least squares (second-order Taylor fit), collocated at the "
  "nodes as in PDLSM-FEM; linear, non-symmetric",
  pdfem::PDModels::declare_weight_factor)
