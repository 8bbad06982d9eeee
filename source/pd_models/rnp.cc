// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/pd_models/rnp.h>

#include <cmath>

namespace pdfem
{
  namespace PDModels
  {
    using dealii::Tensor;

    RNPPotential::RNPPotential(const double C, const double beta)
      : C(C)
      , beta(beta)
    {}

    double
    RNPPotential::g(const double r) const
    {
      return C * -std::expm1(-beta * r * r);
    }

    double
    RNPPotential::dg(const double r) const
    {
      return 2. * C * beta * r * std::exp(-beta * r * r);
    }

    double
    RNPPotential::d2g(const double r) const
    {
      return 2. * C * beta * (1. - 2. * beta * r * r) * std::exp(-beta * r * r);
    }

    double
    RNPPotential::d3g(const double r) const
    {
      return 4. * C * beta * beta * r * (2. * beta * r * r - 3.) *
             std::exp(-beta * r * r);
    }

    double
    RNPPotential::r_c() const
    {
      return 1. / std::sqrt(2. * beta);
    }

    double
    rnp_moment(const RNPInfluence influence, const int dim)
    {
      const double d = dim;
      return influence == RNPInfluence::constant ? 1. / (d + 1.) :
                                                   1. / ((d + 1.) * (d + 2.));
    }

    double
    unit_ball_volume(const int dim)
    {
      switch (dim)
        {
          case 0:
            return 1.;
          case 1:
            return 2.;
          case 2:
            return M_PI;
          default:
            return 4. * M_PI / 3.;
        }
    }

    double
    rnp_poissons_ratio(const int dim, const bool plane_strain)
    {
      if (dim == 1)
        return 0.;
      return (dim == 3 || plane_strain) ? 0.25 : 1. / 3.;
    }

    double
    rnp_c_beta(const double       E,
               const RNPInfluence influence,
               const int          dim,
               const bool         plane_strain)
    {
      const double M = rnp_moment(influence, dim);
      if (dim == 1)
        return E / (2. * M); // E = 2 C beta M_1
      // lambda = mu = 2 C beta M_d / (d + 2); E = 2 mu (1 + nu) with the
      // nu of rnp_poissons_ratio (2D plane stress: E = 8 mu / 3).
      const double nu = rnp_poissons_ratio(dim, plane_strain);
      const double mu = E / (2. * (1. + nu));
      return mu * (dim + 2.) / (2. * M);
    }

    double
    rnp_c_from_fracture_energy(const double       G_c,
                               const RNPInfluence influence,
                               const int          dim)
    {
      return G_c * unit_ball_volume(dim) /
             (2. * unit_ball_volume(dim - 1) * rnp_moment(influence, dim));
    }

    template <int dim>
    RNP<dim>::RNP(const RNPSettings &settings)
      : s(settings)
      , g(settings.C, settings.beta)
      , c(2. / (std::pow(settings.horizon, dim + 1) * unit_ball_volume(dim)))
    {}

    template <int dim>
    double
    RNP<dim>::strain(const Tensor<1, dim> &xi, const Tensor<1, dim> &eta)
    {
      return (eta * xi) / xi.norm_square();
    }

    template <int dim>
    double
    RNP<dim>::r(const Tensor<1, dim> &xi, const Tensor<1, dim> &eta)
    {
      return std::sqrt(xi.norm()) * strain(xi, eta);
    }

    template <int dim>
    double
    RNP<dim>::influence(const double length) const
    {
      const double rho = length / s.horizon;
      if (rho > 1. + 1e-10)
        return 0.;
      return s.influence == RNPInfluence::constant ? 1. :
                                                     std::max(0., 1. - rho);
    }

    template <int dim>
    Tensor<1, dim>
    RNP<dim>::force(const Tensor<1, dim> &xi, const Tensor<1, dim> &eta) const
    {
      const double length = xi.norm();
      const double phi    = s.scaling == RNPForceScaling::paper ?
                              1. / std::sqrt(length) :
                              1. / length;
      const double rr     = std::sqrt(length) * (eta * xi) / (length * length);
      return (c * influence(length) * phi * g.dg(rr) / length) * xi;
    }

    template <int dim>
    Tensor<2, dim>
    RNP<dim>::stiffness(const Tensor<1, dim> &xi,
                        const Tensor<1, dim> &eta) const
    {
      const double length = xi.norm();
      const double sqrt_l = std::sqrt(length);
      const double phi =
        s.scaling == RNPForceScaling::paper ? 1. / sqrt_l : 1. / length;
      const double rr = sqrt_l * (eta * xi) / (length * length);
      const double a  = c * influence(length) * phi * sqrt_l * g.d2g(rr) /
                       (length * length * length);
      Tensor<2, dim> A;
      for (unsigned int p = 0; p < dim; ++p)
        for (unsigned int q = 0; q < dim; ++q)
          A[p][q] = a * xi[p] * xi[q];
      return A;
    }

    template <int dim>
    double
    RNP<dim>::damage(const Tensor<1, dim> &xi, const Tensor<1, dim> &eta) const
    {
      return std::abs(r(xi, eta)) / g.r_c();
    }

    template class RNP<1>;
#define INSTANTIATE(dim) template class RNP<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace PDModels
} // namespace pdfem
