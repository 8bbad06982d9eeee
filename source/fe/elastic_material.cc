// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/fe/elastic_material.h>

namespace pdfem
{
  namespace FE
  {
    double
    ElasticMaterial::lambda() const
    {
      const double E = youngs_modulus, nu = poissons_ratio;
      return plane_stress ? E * nu / (1. - nu * nu) :
                            E * nu / ((1. + nu) * (1. - 2. * nu));
    }

    double
    ElasticMaterial::mu() const
    {
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }
  } // namespace FE
} // namespace pdfem
