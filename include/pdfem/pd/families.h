// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_PD_FAMILIES_H
#define PDFEM_PD_FAMILIES_H

#include <deal.II/base/point.h>

#include <cstdint>
#include <vector>

namespace pdfem
{
  namespace PD
  {
    /**
     * The families of a set of PD nodes, stored compressed (CSR): the members
     * of owner k are members[offsets[k] .. offsets[k+1]), sorted by node
     * index, the owner itself excluded. Each entry is one bond k -> m with its
     * state (1 intact, 0 broken); bonds break for good.
     *
     * Family rule for non-uniform horizons (Liu et al. 2021, eq. A.1):
     * m is in the family of k iff 0 < |x_m - x_k| <= delta_k or
     * |x_m - x_k| <= delta_m, so that families are symmetric wherever both
     * nodes are owners.
     */
    struct Families
    {
      /// Node index of each family owner.
      std::vector<unsigned int> owners;
      /// CSR offsets, owners.size() + 1 entries.
      std::vector<std::size_t> offsets;
      /// Node index of each member.
      std::vector<unsigned int> members;
      /// Bond state per member entry: 1 intact, 0 broken.
      std::vector<std::uint8_t> intact;

      std::size_t
      n_bonds() const
      {
        return members.size();
      }
      std::size_t
      n_broken() const;
    };

    /**
     * Find the families of @p owners among all nodes @p x with horizons
     * @p horizon; only nodes with @p may_be_member[j] != 0 become members.
     * A cell list with cells of the largest horizon: O(N) for uniform
     * horizons. The owners are searched in chunks on the threads of
     * ThreadTeam::shared() (so not from within one of its jobs), with the
     * same result on any number of threads.
     */
    template <int dim>
    Families
    find_families(const std::vector<dealii::Point<dim>> &x,
                  const std::vector<double>             &horizon,
                  const std::vector<unsigned int>       &owners,
                  const std::vector<std::uint8_t>       &may_be_member);

    /// The same by testing every pair: O(N^2), the reference for tests.
    template <int dim>
    Families
    find_families_brute_force(const std::vector<dealii::Point<dim>> &x,
                              const std::vector<double>             &horizon,
                              const std::vector<unsigned int>       &owners,
                              const std::vector<std::uint8_t> &may_be_member);
  } // namespace PD
} // namespace pdfem

#endif
