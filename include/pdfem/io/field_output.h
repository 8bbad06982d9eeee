// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_FIELD_OUTPUT_H
#define PDFEM_IO_FIELD_OUTPUT_H

#include <pdfem/coupling/coupled_system.h>

#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pdfem
{
  class StateArchive;

  namespace IO
  {
    namespace internal
    {
      /// Base64 (RFC 4648, with '=' padding) of @p bytes, for the VTU
      /// writer's inline binary arrays.
      std::string
      base64(const std::vector<unsigned char> &bytes);
    } // namespace internal

    /**
     * Field output of a run: `solution_NNNNN.pvtu` (one `.vtu` piece per
     * rank) with displacement, stress components, principal stresses, von
     * Mises stress, damage and node kind at the nodes, and PD region, material
     * id, rank and "cracked" (a crack runs through it) per cell;
     * `solution.pvd` lists every output with its time (the physical time of
     * a dynamic run, the load factor of a static one) and is rewritten after
     * each. ParaView takes records with equal times as parts of one state,
     * so a record whose time does not exceed the one before it (growth
     * steps at a held load) is listed 1e-9 (relative) after it.
     *
     * The files are written directly (uncompressed binary VTU, one point
     * per node, Float32), not through deal.II's DataOut: building DataOut's
     * patches alone took 40-50 ms per output on the 7 140-node plateCrack
     * plate, the whole output here about 3 ms. Each rank encodes and writes
     * its piece on a background thread while the run goes on; the next
     * write() or finish() waits for it.
     */
    template <int dim>
    class FieldOutput
    {
    public:
      FieldOutput(const std::string &directory, bool plane_strain, double nu);
      /// Waits for the last piece (an error there is printed, not thrown;
      /// call finish() to learn it).
      ~FieldOutput();

      /// Write the fields at @p time (the time or load factor of the
      /// step; see the class description for equal times).
      void
      write(const Coupling::CoupledSystem<dim> &system,
            const Coupling::NodalResults<dim>  &results,
            double                              time);

      /// Wait until every rank's piece is on disk. Collective: a piece that
      /// could not be written on any rank throws RunFailure "io error".
      void
      finish();
      /// finish(), then put the outputs written so far (counter, the
      /// solution.pvd list) into a checkpoint. Collective.
      void
      save_state(StateArchive &state);
      /// Take them back on restart: later outputs continue the numbering
      /// and solution.pvd lists the earlier ones.
      void
      load_state(const StateArchive &state);

      /// nodes.csv: every node (sorted by coordinates) with displacement
      /// and stress, independent of the number of ranks. Written whole or
      /// not at all (write_atomically()); returns why it failed, or "".
      static std::string
      write_nodes_csv(const std::string                 &file,
                      const Coupling::NodalResults<dim> &results);

    private:
      std::string                                 directory;
      bool                                        plane_strain;
      double                                      nu;
      unsigned int                                counter = 0;
      std::vector<std::pair<double, std::string>> records;
      /// The piece being written in the background (its error, or "").
      std::future<std::string> pending;
      /// The communicator of the last write() (finish() agrees over it).
      MPI_Comm comm = MPI_COMM_SELF;
    };
  } // namespace IO
} // namespace pdfem

#endif
