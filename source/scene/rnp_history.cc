// SPDX-License-Identifier: LGPL-2.1-or-later
// The history columns of an RNP run (rnp_scene.cc).
#include <pdfem/base/config.h>
#include <pdfem/coupling/coupled_system.h>
#include <pdfem/io/history.h>

#include "scene_internal.h"

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using Coupling::component_names;

      template <int dim>
      std::vector<std::string>
      base_history_columns(const std::vector<std::string> &reaction_sets,
                           const bool                      reaction_group)
      {
        std::vector<std::string> columns = Summary::first_history_columns();
        for (const auto &set : reaction_sets)
          for (const auto &c : component_names<dim>())
            columns.push_back("reaction_" + IO::History::column_name(set) +
                              "_" + c);
        if (reaction_group)
          for (const auto &c : component_names<dim>())
            columns.push_back("reaction_RF_" + c);
        return columns;
      }

#define INSTANTIATE(dim)                                       \
  template std::vector<std::string> base_history_columns<dim>( \
    const std::vector<std::string> &, bool);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
