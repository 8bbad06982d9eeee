// SPDX-License-Identifier: LGPL-2.1-or-later
// The `nodes csv` postprocessor.
#include <pdfem/io/field_output.h>
#include <pdfem/simulator/postprocess.h>

namespace pdfem
{
  namespace Postprocess
  {
    namespace
    {
      /**
       * nodes.csv at the end (Output/Write nodes csv): every node's
       * coordinates, displacement and stress, sorted by coordinates so that
       * it does not depend on the number of ranks.
       */
      template <int dim>
      class NodesCsv : public Interface<dim>
      {
      public:
        bool
        initialize() override
        {
          return this->get_setup().write_nodes_csv;
        }

        void
        finish() override
        {
          if (this->is_root())
            IO::FieldOutput<dim>::write_nodes_csv(this->get_output_directory() +
                                                    "/nodes.csv",
                                                  this->get_nodal_results());
        }
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(NodesCsv,
                                 "nodes csv",
                                 "nodes.csv: every node's position, "
                                 "displacement and stress at the end.")
  } // namespace Postprocess
} // namespace pdfem
