// SPDX-License-Identifier: LGPL-2.1-or-later
// The uniform periodic grid of the FFT operators, the discrete horizon,
// the checks of the input and what the two operator forms share.
#include <pdfem/base/exceptions.h>
#include <pdfem/fft/grid.h>
#include <pdfem/fft/operator.h>

#include <cmath>

namespace pdfem
{
  namespace FFT
  {
    template <int dim>
    std::size_t
    Grid<dim>::n_nodes() const
    {
      std::size_t N = 1;
      for (unsigned int k = 0; k < dim; ++k)
        N *= n[k];
      return N;
    }

    template <int dim>
    double
    Grid<dim>::node_volume() const
    {
      double V = 1.;
      for (unsigned int k = 0; k < dim; ++k)
        V *= spacing[k];
      return V;
    }

    template <int dim>
    std::size_t
    Grid<dim>::node(const std::array<unsigned int, dim> &i) const
    {
      std::size_t k = 0;
      for (unsigned int d = 0; d < dim; ++d)
        k = k * n[d] + i[d];
      return k;
    }

    template <int dim>
    std::array<unsigned int, dim>
    Grid<dim>::indices(std::size_t node) const
    {
      std::array<unsigned int, dim> i;
      for (int d = dim - 1; d >= 0; --d)
        {
          i[d] = node % n[d];
          node /= n[d];
        }
      return i;
    }

    template <int dim>
    std::array<double, dim>
    Grid<dim>::position(const std::size_t node) const
    {
      const auto              i = indices(node);
      std::array<double, dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = i[d] * spacing[d];
      return x;
    }

    std::string
    model_name(const Model model)
    {
      switch (model)
        {
          case Model::linear_bond_based:
            return "linear bond based";
          case Model::nonlinear_bond_based:
            return "nonlinear bond based";
          case Model::lps:
            return "lps";
        }
      return "";
    }

    double
    Material::omega(const double r) const
    {
      return influence ? influence(r) : 1. / r;
    }

    template <int dim>
    std::vector<Offset<dim>>
    horizon_offsets(const Grid<dim> &grid, const double horizon)
    {
      std::array<int, dim> reach;
      for (unsigned int d = 0; d < dim; ++d)
        {
          reach[d] = static_cast<int>(
            std::floor(horizon * (1. + 1e-10) / grid.spacing[d]));
          if (2 * static_cast<long long>(reach[d]) >=
              static_cast<long long>(grid.n[d]))
            throw InputError("",
                             "horizon",
                             number(horizon) + " reaches " +
                               std::to_string(reach[d]) +
                               " spacings in direction " + std::to_string(d) +
                               " of a periodic grid of " +
                               std::to_string(grid.n[d]) + " nodes",
                             "2 horizon / spacing < nodes per direction");
        }
      const double             limit = horizon * horizon * (1. + 2e-10);
      std::vector<Offset<dim>> offsets;
      std::array<int, dim>     p;
      p.fill(0);
      p[0] = -reach[0];
      for (unsigned int d = 1; d < dim; ++d)
        p[d] = -reach[d];
      while (true)
        {
          Offset<dim> o;
          o.p         = p;
          double r2   = 0.;
          bool   zero = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              o.xi[d] = p[d] * grid.spacing[d];
              r2 += o.xi[d] * o.xi[d];
              zero = zero && p[d] == 0;
            }
          if (!zero && r2 <= limit)
            {
              o.length = std::sqrt(r2);
              offsets.push_back(o);
            }
          // next offset, last index fastest
          int d = dim - 1;
          while (d >= 0 && p[d] == reach[d])
            {
              p[d] = -reach[d];
              --d;
            }
          if (d < 0)
            break;
          ++p[d];
        }
      return offsets;
    }

    template <int dim>
    void
    check_input(const Grid<dim> &grid, const Material &material)
    {
      for (unsigned int d = 0; d < dim; ++d)
        {
          if (grid.n[d] < 2)
            throw InputError("",
                             "grid nodes",
                             std::to_string(grid.n[d]) + " in direction " +
                               std::to_string(d),
                             "at least 2");
          if (!(grid.spacing[d] > 0.))
            throw InputError("",
                             "grid spacing",
                             number(grid.spacing[d]),
                             "a positive number");
          if (!(material.horizon >= grid.spacing[d]))
            throw InputError("",
                             "horizon",
                             number(material.horizon) +
                               " is smaller than the spacing " +
                               number(grid.spacing[d]),
                             "horizon >= spacing");
        }
      if (material.model == Model::lps)
        {
          if (!(material.shear_modulus > 0.) || !(material.bulk_modulus > 0.))
            throw InputError("",
                             "LPS moduli",
                             "bulk " + number(material.bulk_modulus) +
                               ", shear " + number(material.shear_modulus),
                             "positive numbers");
        }
      else if (!(material.micromodulus > 0.))
        throw InputError("",
                         "micromodulus",
                         number(material.micromodulus),
                         "a positive number");
    }

    template <int dim>
    Operator<dim>::Operator(const Grid<dim> &grid, const Material &material)
      : grid_(grid)
      , material_(material)
    {
      check_input(grid, material);
    }

    template <int dim>
    const Grid<dim> &
    Operator<dim>::grid() const
    {
      return grid_;
    }

    template <int dim>
    const Material &
    Operator<dim>::material() const
    {
      return material_;
    }

    std::size_t
    update_integrity(const std::vector<double> &W,
                     const double               critical_energy_density,
                     std::vector<double>       &integrity)
    {
      if (integrity.size() != W.size())
        integrity.assign(W.size(), 1.);
      std::size_t failed = 0;
      for (std::size_t k = 0; k < W.size(); ++k)
        if (integrity[k] != 0. && W[k] > critical_energy_density)
          {
            integrity[k] = 0.;
            ++failed;
          }
      return failed;
    }

    double
    critical_energy_density(const double fracture_energy, const double horizon)
    {
      return fracture_energy / horizon;
    }

    template struct Grid<2>;
    template struct Grid<3>;
    template class Operator<2>;
    template class Operator<3>;
    template std::vector<Offset<2>>
    horizon_offsets(const Grid<2> &, double);
    template std::vector<Offset<3>>
    horizon_offsets(const Grid<3> &, double);
    template void
    check_input(const Grid<2> &, const Material &);
    template void
    check_input(const Grid<3> &, const Material &);
  } // namespace FFT
} // namespace pdfem
