// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_FFT_SLAB_EXCHANGE_H
#define PDFEM_FFT_SLAB_EXCHANGE_H

#include <pdfem/fft/grid.h>

#include <cstddef>
#include <vector>

#include <mpi.h>

namespace pdfem
{
  namespace FFT
  {
    /**
     * Moves nodal values between the box nodes a rank owns in a mesh
     * partition (its points, any box nodes, each owned by one rank) and the
     * slabs of an FftOperator distributed over the same ranks (Slab: the
     * ranks' contiguous ranges of box nodes). The plan, which rank's slab
     * holds each point and where, is made once (one MPI_Alltoall and one
     * MPI_Alltoallv); every push() or pull() is then one MPI_Alltoallv of
     * the values. With one rank both are copies.
     *
     * Point values are interleaved, n_components per point (value c of
     * point p at n_components p + c); slab fields are component-major, the
     * layout of the operator's fields (c N + k, N the slab's nodes).
     */
    class SlabExchange
    {
    public:
      /// The plan for the box nodes @p points of this rank, @p slab being
      /// this rank's slab (collective over @p comm).
      SlabExchange(const std::vector<std::size_t> &points,
                   const Slab                     &slab,
                   MPI_Comm                        comm);

      /// slab_field[c N + k] = the value of the point at box node begin + k;
      /// the slab's other nodes keep their values (collective).
      void
      push(const double        *values,
           unsigned int         n_components,
           std::vector<double> &slab_field) const;

      /// values[n_components p + c] = slab_field at point p's box node, from
      /// the rank whose slab holds it (collective).
      void
      pull(const std::vector<double> &slab_field,
           unsigned int               n_components,
           double                    *values) const;

      /// This rank's points.
      std::size_t
      n_points() const
      {
        return n_local_points;
      }

    private:
      MPI_Comm    comm;
      bool        serial;
      std::size_t n_local_points, n_slab_nodes;
      /// The points in the order they are sent (grouped by the slab's
      /// rank), and the slab nodes (local) of the values received, in the
      /// order they arrive.
      std::vector<std::size_t> send_order, receive_node;
      /// Points sent to and received from each rank, and their offsets.
      std::vector<int> send_count, send_offset, receive_count, receive_offset;
      /// The MPI buffers of push() and pull().
      mutable std::vector<double> send_buffer, receive_buffer;

      /// One MPI_Alltoallv of n_components values per point, in the
      /// direction to the slabs (forward) or back.
      void
      exchange(unsigned int n_components, bool forward) const;
    };
  } // namespace FFT
} // namespace pdfem

#endif
