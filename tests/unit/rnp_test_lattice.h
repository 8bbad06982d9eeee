// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the RNP unit tests (rnp_test.cc, rnp_solver_test.cc): the
// lattice of nodes they are made on.
#ifndef PDFEM_TESTS_UNIT_RNP_TEST_LATTICE_H
#define PDFEM_TESTS_UNIT_RNP_TEST_LATTICE_H

#include <deal.II/base/point.h>

#include <cmath>
#include <vector>

namespace pdfem
{
  namespace test
  {
    using dealii::Point;

    /// A lattice of n^dim nodes, spacing h, full volumes h^dim.
    template <int dim>
    void
    lattice(const unsigned int       n,
            const double             h,
            std::vector<Point<dim>> &x,
            std::vector<double>     &volume)
    {
      x.clear();
      unsigned int total = 1;
      for (unsigned int d = 0; d < dim; ++d)
        total *= n;
      for (unsigned int k = 0; k < total; ++k)
        {
          Point<dim>   p;
          unsigned int code = k;
          for (unsigned int d = 0; d < dim; ++d)
            {
              p[d] = h * (code % n);
              code /= n;
            }
          x.push_back(p);
        }
      volume.assign(x.size(), std::pow(h, dim));
    }
  } // namespace test
} // namespace pdfem

#endif
