// SPDX-License-Identifier: LGPL-2.1-or-later
// The `nodes csv` postprocessor.
#include <pdfem/base/exceptions.h>
#include <pdfem/io/field_output.h>
#include <pdfem/simulator/postprocess.h>

#include <deal.II/base/mpi.h>

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
          // Written whole or not at all; a failure ends the run with
          // "io error" on every rank.
          std::string error;
          if (this->is_root())
            error = IO::FieldOutput<dim>::write_nodes_csv(
              this->get_output_directory() + "/nodes.csv",
              this->get_nodal_results());
          error =
            dealii::Utilities::MPI::broadcast(this->get_mpi_communicator(),
                                              error,
                                              0);
          if (!error.empty())
            throw RunFailure("io error", error);
        }
      };
    } // namespace

    PDFEM_REGISTER_POSTPROCESSOR(NodesCsv,
                                 "nodes csv",
                                 "nodes.csv: every node's position, "
                                 "displacement and stress at the end.")
  } // namespace Postprocess
} // namespace pdfem
