// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_FIELD_OUTPUT_H
#define PDFEM_IO_FIELD_OUTPUT_H

#include <pdfem/coupling/coupled_system.h>

#include <string>
#include <utility>
#include <vector>

namespace pdfem
{
  namespace IO
  {
    /**
     * Field output of a run: `solution-NNNNN.pvtu` (one `.vtu` piece per
     * rank) with displacement, stress components, principal stresses, von
     * Mises stress, damage and node kind at the nodes, and PD region, material
     * id and rank per cell; `solution.pvd` lists every output with its time
     * and is rewritten after each.
     */
    template <int dim>
    class FieldOutput
    {
    public:
      FieldOutput(const std::string &directory, bool plane_strain, double nu);

      void
      write(const Coupling::CoupledSystem<dim> &system,
            const Coupling::NodalResults<dim>  &results,
            double                              time);

      /// nodes.csv: every node (sorted by coordinates) with displacement
      /// and stress; written by rank 0, independent of the number of ranks.
      static void
      write_nodes_csv(const std::string                 &file,
                      const Coupling::NodalResults<dim> &results);

    private:
      std::string                                 directory;
      bool                                        plane_strain;
      double                                      nu;
      unsigned int                                counter = 0;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace IO
} // namespace pdfem

#endif
