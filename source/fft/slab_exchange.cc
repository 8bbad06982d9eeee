// SPDX-License-Identifier: LGPL-2.1-or-later
// FFT::SlabExchange: the values of a rank's points to the slabs that hold
// them and back.
#include <pdfem/fft/slab_exchange.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace pdfem
{
  namespace FFT
  {
    namespace
    {
      int
      n_ranks(MPI_Comm comm)
      {
        int n = 1;
        MPI_Comm_size(comm, &n);
        return n;
      }

      /// Offsets of @p counts (exclusive prefix sums).
      std::vector<int>
      offsets_of(const std::vector<int> &counts)
      {
        std::vector<int> offsets(counts.size(), 0);
        for (std::size_t r = 1; r < counts.size(); ++r)
          offsets[r] = offsets[r - 1] + counts[r - 1];
        return offsets;
      }
    } // namespace

    SlabExchange::SlabExchange(const std::vector<std::size_t> &points,
                               const Slab                     &slab,
                               MPI_Comm                        communicator)
      : comm(communicator)
      , serial(n_ranks(communicator) == 1)
      , n_local_points(points.size())
      , n_slab_nodes(slab.n_nodes())
    {
      if (serial)
        {
          // The slab is the whole box: each point is its own slab node.
          receive_node.resize(points.size());
          for (std::size_t p = 0; p < points.size(); ++p)
            {
              if (!slab.contains(points[p]))
                throw std::logic_error("SlabExchange: a point off the box");
              receive_node[p] = points[p] - slab.begin;
            }
          return;
        }
      const int n = n_ranks(comm);
      // The slabs tile the box: the nonempty ones in rank order, each a
      // range [begin, end) of box nodes (an empty slab may report any
      // position, so it is left out of the search).
      const std::uint64_t        range[2] = {slab.begin, slab.end};
      std::vector<std::uint64_t> all(2 * n);
      MPI_Allgather(range, 2, MPI_UINT64_T, all.data(), 2, MPI_UINT64_T, comm);
      std::vector<std::uint64_t> starts; // of the nonempty slabs
      std::vector<int>           owner;  // their ranks
      for (int r = 0; r < n; ++r)
        if (all[2 * r + 1] > all[2 * r])
          {
            starts.push_back(all[2 * r]);
            owner.push_back(r);
          }
      std::vector<int> rank_of(points.size());
      send_count.assign(n, 0);
      for (std::size_t p = 0; p < points.size(); ++p)
        {
          const auto i =
            std::upper_bound(starts.begin(), starts.end(), points[p]) -
            starts.begin() - 1;
          if (i < 0 || points[p] >= all[2 * owner[i] + 1])
            throw std::logic_error("SlabExchange: a point off the box");
          rank_of[p] = owner[i];
          ++send_count[owner[i]];
        }
      send_offset = offsets_of(send_count);
      send_order.resize(points.size());
      std::vector<int> next = send_offset;
      for (std::size_t p = 0; p < points.size(); ++p)
        send_order[next[rank_of[p]]++] = p;

      receive_count.assign(n, 0);
      MPI_Alltoall(
        send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, comm);
      receive_offset = offsets_of(receive_count);
      std::vector<std::uint64_t> sent(points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
        sent[i] = points[send_order[i]];
      std::vector<std::uint64_t> received(receive_offset.back() +
                                          receive_count.back());
      MPI_Alltoallv(sent.data(),
                    send_count.data(),
                    send_offset.data(),
                    MPI_UINT64_T,
                    received.data(),
                    receive_count.data(),
                    receive_offset.data(),
                    MPI_UINT64_T,
                    comm);
      receive_node.resize(received.size());
      for (std::size_t i = 0; i < received.size(); ++i)
        {
          if (!slab.contains(received[i]))
            throw std::logic_error("SlabExchange: the slabs do not tile");
          receive_node[i] = received[i] - slab.begin;
        }
    }

    void
    SlabExchange::exchange(const unsigned int n_components,
                           const bool         forward) const
    {
      const int        n = int(send_count.size());
      std::vector<int> sc(n), so(n), rc(n), ro(n);
      for (int r = 0; r < n; ++r)
        {
          sc[r] = int(n_components) * send_count[r];
          so[r] = int(n_components) * send_offset[r];
          rc[r] = int(n_components) * receive_count[r];
          ro[r] = int(n_components) * receive_offset[r];
        }
      if (forward)
        MPI_Alltoallv(send_buffer.data(),
                      sc.data(),
                      so.data(),
                      MPI_DOUBLE,
                      receive_buffer.data(),
                      rc.data(),
                      ro.data(),
                      MPI_DOUBLE,
                      comm);
      else
        MPI_Alltoallv(receive_buffer.data(),
                      rc.data(),
                      ro.data(),
                      MPI_DOUBLE,
                      send_buffer.data(),
                      sc.data(),
                      so.data(),
                      MPI_DOUBLE,
                      comm);
    }

    void
    SlabExchange::push(const double        *values,
                       const unsigned int   n_components,
                       std::vector<double> &slab_field) const
    {
      slab_field.resize(n_components * n_slab_nodes, 0.);
      const std::size_t N = n_slab_nodes;
      if (serial)
        {
          for (std::size_t p = 0; p < n_local_points; ++p)
            for (unsigned int c = 0; c < n_components; ++c)
              slab_field[c * N + receive_node[p]] =
                values[n_components * p + c];
          return;
        }
      send_buffer.resize(n_components * n_local_points);
      receive_buffer.resize(n_components * receive_node.size());
      for (std::size_t i = 0; i < send_order.size(); ++i)
        for (unsigned int c = 0; c < n_components; ++c)
          send_buffer[n_components * i + c] =
            values[n_components * send_order[i] + c];
      exchange(n_components, true);
      for (std::size_t i = 0; i < receive_node.size(); ++i)
        for (unsigned int c = 0; c < n_components; ++c)
          slab_field[c * N + receive_node[i]] =
            receive_buffer[n_components * i + c];
    }

    void
    SlabExchange::pull(const std::vector<double> &slab_field,
                       const unsigned int         n_components,
                       double                    *values) const
    {
      const std::size_t N = n_slab_nodes;
      if (serial)
        {
          for (std::size_t p = 0; p < n_local_points; ++p)
            for (unsigned int c = 0; c < n_components; ++c)
              values[n_components * p + c] =
                slab_field[c * N + receive_node[p]];
          return;
        }
      send_buffer.resize(n_components * n_local_points);
      receive_buffer.resize(n_components * receive_node.size());
      for (std::size_t i = 0; i < receive_node.size(); ++i)
        for (unsigned int c = 0; c < n_components; ++c)
          receive_buffer[n_components * i + c] =
            slab_field[c * N + receive_node[i]];
      exchange(n_components, false);
      for (std::size_t i = 0; i < send_order.size(); ++i)
        for (unsigned int c = 0; c < n_components; ++c)
          values[n_components * send_order[i] + c] =
            send_buffer[n_components * i + c];
    }
  } // namespace FFT
} // namespace pdfem
