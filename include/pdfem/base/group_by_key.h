// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_BASE_GROUP_BY_KEY_H
#define PDFEM_BASE_GROUP_BY_KEY_H

#include <cstddef>
#include <utility>
#include <vector>

namespace pdfem
{
  /**
   * Items grouped by their key (< @p n), by counting sort: for_each(emit)
   * calls emit(key, item) for every item (it is called twice, to count and
   * to place); the items of key k are grouped[start[k] .. start[k + 1]], in
   * the order emitted. Returns {start, grouped}.
   */
  template <typename Item, typename ForEach>
  std::pair<std::vector<std::size_t>, std::vector<Item>>
  group_by_key(const std::size_t n, const ForEach &for_each)
  {
    std::vector<std::size_t> start(n + 1, 0);
    for_each([&](const std::size_t key, const Item &) { ++start[key + 1]; });
    for (std::size_t k = 0; k < n; ++k)
      start[k + 1] += start[k];
    std::vector<Item>        grouped(start[n]);
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for_each([&](const std::size_t key, const Item &item) {
      grouped[next[key]++] = item;
    });
    return {std::move(start), std::move(grouped)};
  }
} // namespace pdfem

#endif
