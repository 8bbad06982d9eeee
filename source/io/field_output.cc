// SPDX-License-Identifier: LGPL-2.1-or-later
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>
#include <pdfem/io/atomic_file.h>
#include <pdfem/io/field_output.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace pdfem
{
  namespace IO
  {
    using namespace dealii;

    using Coupling::stress_component;

    template <int dim>
    FieldOutput<dim>::FieldOutput(const std::string &directory,
                                  const bool         plane_strain,
                                  const double       nu)
      : directory(directory)
      , plane_strain(plane_strain)
      , nu(nu)
    {}

    template <int dim>
    FieldOutput<dim>::~FieldOutput()
    {
      // Not collective here: only wait for this rank's piece.
      if (pending.valid())
        {
          const std::string error = pending.get();
          if (!error.empty())
            std::cerr << "pdfem: field output failed: " << error << std::endl;
        }
    }

    template <int dim>
    void
    FieldOutput<dim>::finish()
    {
      const std::string error = pending.valid() ? pending.get() : "";
      if (Utilities::MPI::max(error.empty() ? 0 : 1, comm) > 0)
        throw RunFailure("io error",
                         error.empty() ? "another rank could not write its "
                                         "field file" :
                                         error);
    }

    // Three bytes give four characters. deal.II's encoder goes through
    // boost's iterator adaptors: 3 % of plateCrack FC1, on the thread beside
    // the solver.
    std::string
    internal::base64(const std::vector<unsigned char> &bytes)
    {
      static constexpr char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::string       out;
      const std::size_t n = bytes.size();
      out.reserve(4 * ((n + 2) / 3));
      std::size_t i = 0;
      for (; i + 2 < n; i += 3)
        {
          const std::uint32_t v =
            (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
          out += alphabet[(v >> 18) & 63];
          out += alphabet[(v >> 12) & 63];
          out += alphabet[(v >> 6) & 63];
          out += alphabet[v & 63];
        }
      if (i < n)
        {
          const bool          two = i + 1 < n;
          const std::uint32_t v =
            (bytes[i] << 16) | (two ? bytes[i + 1] << 8 : 0);
          out += alphabet[(v >> 18) & 63];
          out += alphabet[(v >> 12) & 63];
          out += two ? alphabet[(v >> 6) & 63] : '=';
          out += '=';
        }
      return out;
    }

    namespace
    {
      /// One named array of a VTU piece: Float32 values, @p components per
      /// point or cell.
      struct Array
      {
        std::string        name;
        unsigned int       components = 1;
        std::vector<float> values;
      };

      /// The piece of one rank, everything a VTU file holds.
      struct Piece
      {
        std::vector<float>        points; // 3 per point
        std::vector<std::int32_t> connectivity, offsets;
        std::vector<std::uint8_t> types;
        std::vector<Array>        point_data, cell_data;
      };

      /// Base64 of a 64-bit byte count followed by the bytes (VTK XML
      /// "binary" inline format, header_type UInt64, uncompressed).
      template <typename T>
      std::string
      encode(const std::vector<T> &data)
      {
        const std::uint64_t        n = data.size() * sizeof(T);
        std::vector<unsigned char> bytes(sizeof(n) + n);
        std::memcpy(bytes.data(), &n, sizeof(n));
        if (n > 0)
          std::memcpy(bytes.data() + sizeof(n), data.data(), n);
        return internal::base64(bytes);
      }

      void
      write_array(std::ostream      &out,
                  const std::string &type,
                  const std::string &name,
                  unsigned int       components,
                  const std::string &encoded)
      {
        out << "        <DataArray type=\"" << type << "\"";
        if (!name.empty())
          out << " Name=\"" << name << "\"";
        if (components > 1)
          out << " NumberOfComponents=\"" << components << "\"";
        out << " format=\"binary\">\n" << encoded << "\n        </DataArray>\n";
      }

      void
      write_piece(std::ostream &out, const Piece &piece)
      {
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
               "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
               "  <UnstructuredGrid>\n"
            << "    <Piece NumberOfPoints=\"" << piece.points.size() / 3
            << "\" NumberOfCells=\"" << piece.types.size() << "\">\n"
            << "      <PointData>\n";
        for (const Array &a : piece.point_data)
          write_array(out, "Float32", a.name, a.components, encode(a.values));
        out << "      </PointData>\n      <CellData>\n";
        for (const Array &a : piece.cell_data)
          write_array(out, "Float32", a.name, a.components, encode(a.values));
        out << "      </CellData>\n      <Points>\n";
        write_array(out, "Float32", "", 3, encode(piece.points));
        out << "      </Points>\n      <Cells>\n";
        write_array(
          out, "Int32", "connectivity", 1, encode(piece.connectivity));
        write_array(out, "Int32", "offsets", 1, encode(piece.offsets));
        write_array(out, "UInt8", "types", 1, encode(piece.types));
        out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
               "</VTKFile>\n";
      }

      void
      write_record(std::ostream                   &out,
                   const Piece                    &piece,
                   const std::vector<std::string> &sources)
      {
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
               "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
               "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
        for (const Array &a : piece.point_data)
          out << "      <PDataArray type=\"Float32\" Name=\"" << a.name
              << "\" NumberOfComponents=\"" << a.components << "\"/>\n";
        out << "    </PPointData>\n    <PCellData>\n";
        for (const Array &a : piece.cell_data)
          out << "      <PDataArray type=\"Float32\" Name=\"" << a.name
              << "\"/>\n";
        out << "    </PCellData>\n    <PPoints>\n      <PDataArray "
               "type=\"Float32\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
        for (const std::string &source : sources)
          out << "    <Piece Source=\"" << source << "\"/>\n";
        out << "  </PUnstructuredGrid>\n</VTKFile>\n";
      }

      /// VTK's vertex order and cell type for a deal.II cell.
      template <int dim>
      std::pair<std::vector<unsigned int>, std::uint8_t>
      vtk_cell(const ReferenceCell &reference)
      {
        if (reference == ReferenceCells::Quadrilateral)
          return {{0, 1, 3, 2}, 9};
        if (reference == ReferenceCells::Hexahedron)
          return {{0, 1, 3, 2, 4, 5, 7, 6}, 12};
        if (reference == ReferenceCells::Triangle)
          return {{0, 1, 2}, 5};
        if (reference == ReferenceCells::Tetrahedron)
          return {{0, 1, 2, 3}, 10};
        if (reference == ReferenceCells::Wedge)
          return {{0, 1, 2, 3, 4, 5}, 13};
        return {{0, 1, 2, 3, 4}, 14}; // pyramid
      }

      /// The .pvd time of a record at @p time after one at @p previous:
      /// @p time, or just after @p previous when it is not later (ParaView
      /// would show records of equal times as parts of one state).
      double
      after_previous(const double previous, const double time)
      {
        if (time > previous)
          return time;
        const double scale = std::max(std::abs(previous), std::abs(time));
        return previous + (scale > 0. ? 1e-9 * scale : 1e-12);
      }
    } // namespace

    template <int dim>
    void
    FieldOutput<dim>::write(const Coupling::CoupledSystem<dim> &system,
                            const Coupling::NodalResults<dim>  &results,
                            const double                        time)
    {
      // The locally owned cells and the nodes they use, each node once
      // (one point per node: PD and FE share the mesh vertices).
      const DoFHandler<dim>    &node_dofs = system.node_dof_handler();
      const auto               &node_of   = system.node_of_scalar_dof();
      Piece                     piece;
      std::vector<int>          point_of(results.position.size(), -1);
      std::vector<unsigned int> point_node;
      std::vector<types::global_dof_index> scalar_local;
      Array region{"pd_region", 1, {}}, material{"material_id", 1, {}},
        rank{"rank", 1, {}}, cracked{"cracked", 1, {}};
      const std::vector<bool> cut = system.cracked_cells();
      for (const auto &cell : node_dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            scalar_local.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(scalar_local);
            const auto [order, type] = vtk_cell<dim>(cell->reference_cell());
            for (const unsigned int v : order)
              {
                const unsigned int k = node_of[scalar_local[v]];
                if (point_of[k] < 0)
                  {
                    point_of[k] = point_node.size();
                    point_node.push_back(k);
                  }
                piece.connectivity.push_back(point_of[k]);
              }
            piece.offsets.push_back(piece.connectivity.size());
            piece.types.push_back(type);
            region.values.push_back(
              system.cell_is_pd()[cell->active_cell_index()] ? 1.f : 0.f);
            material.values.push_back(cell->material_id());
            rank.values.push_back(cell->subdomain_id());
            cracked.values.push_back(cut[cell->active_cell_index()] ? 1.f :
                                                                      0.f);
          }
      piece.cell_data = {region, material, rank, cracked};

      const auto         names = Coupling::stress_component_names<dim>();
      const unsigned int n     = point_node.size();
      Array displacement{"displacement", 3, std::vector<float>(3 * n, 0.f)};
      std::vector<Array> stress;
      for (const auto &name : names)
        stress.push_back({"stress_" + name, 1, std::vector<float>(n)});
      Array sigma_zz{"stress_zz", 1, std::vector<float>(n)},
        s1{"max_principal_stress", 1, std::vector<float>(n)},
        s_min{"min_principal_stress", 1, std::vector<float>(n)},
        von_mises{"von_mises_stress", 1, std::vector<float>(n)},
        damage{"damage", 1, std::vector<float>(n)},
        kind{"node_kind", 1, std::vector<float>(n)};
      piece.points.assign(3 * n, 0.f);
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int             k     = point_node[i];
          const SymmetricTensor<2, dim> &sigma = results.stress[k];
          for (unsigned int d = 0; d < dim; ++d)
            {
              piece.points[3 * i + d]        = results.position[k][d];
              displacement.values[3 * i + d] = results.displacement[k][d];
            }
          for (unsigned int c = 0; c < names.size(); ++c)
            stress[c].values[i] = stress_component(sigma, c);
          const auto ev    = eigenvalues(sigma);
          s1.values[i]     = ev[0];
          s_min.values[i]  = ev[dim - 1];
          const double szz = dim == 2 && plane_strain ? nu * trace(sigma) : 0.;
          sigma_zz.values[i] = szz;
          // von Mises from the full 3x3 stress.
          SymmetricTensor<2, 3> s3;
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = a; b < dim; ++b)
              s3[a][b] = sigma[a][b];
          if (dim == 2)
            s3[2][2] = szz;
          von_mises.values[i] = std::sqrt(1.5) * deviator(s3).norm();
          damage.values[i]    = results.damage[k];
          kind.values[i]      = results.kind[k];
        }
      piece.point_data.push_back(std::move(displacement));
      for (auto &a : stress)
        piece.point_data.push_back(std::move(a));
      if (dim == 2 && plane_strain)
        piece.point_data.push_back(std::move(sigma_zz));
      for (Array *a : {&s1, &s_min, &von_mises, &damage, &kind})
        piece.point_data.push_back(std::move(*a));

      // solution_NNNNN.R.vtu per rank R, solution_NNNNN.pvtu by rank 0,
      // each written whole or not at all (a failure: RunFailure "io
      // error" on every rank, at this write or at finish()).
      comm                       = node_dofs.get_communicator();
      const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
      const std::string  base =
        "solution_" + Utilities::int_to_string(counter++, 5);
      std::vector<std::string> sources;
      for (unsigned int r = 0; r < Utilities::MPI::n_mpi_processes(comm); ++r)
        sources.push_back(base + "." + Utilities::int_to_string(r) + ".vtu");
      const std::string pvtu = base + ".pvtu";
      finish();
      records.emplace_back(records.empty() ?
                             time :
                             after_previous(records.back().first, time),
                           pvtu);
      std::string error;
      if (my_rank == 0)
        {
          error =
            write_atomically(directory + "/" + pvtu, [&](std::ostream &out) {
              write_record(out, piece, sources);
            });
          if (error.empty())
            error =
              write_atomically(directory + "/solution.pvd",
                               [&](std::ostream &out) {
                                 DataOutBase::write_pvd_record(out, records);
                               });
        }
      error = Utilities::MPI::broadcast(comm, error, 0);
      if (!error.empty())
        throw RunFailure("io error", error);
      pending =
        std::async(std::launch::async,
                   [piece = std::move(piece),
                    file  = directory + "/" + sources[my_rank]]() {
                     return write_atomically(file, [&](std::ostream &out) {
                       write_piece(out, piece);
                     });
                   });
    }

    template <int dim>
    std::string
    FieldOutput<dim>::write_nodes_csv(const std::string                 &file,
                                      const Coupling::NodalResults<dim> &r)
    {
      std::vector<unsigned int> order(r.position.size());
      std::iota(order.begin(), order.end(), 0u);
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) {
                  for (int d = dim - 1; d >= 0; --d)
                    if (r.position[a][d] != r.position[b][d])
                      return r.position[a][d] < r.position[b][d];
                  return a < b;
                });
      return write_atomically(file, [&](std::ostream &out) {
        const char *axis = "xyz";
        for (unsigned int d = 0; d < dim; ++d)
          out << (d ? "," : "") << axis[d];
        for (unsigned int d = 0; d < dim; ++d)
          out << ",u" << axis[d];
        const auto stress_names = Coupling::stress_component_names<dim>();
        for (const auto &n : stress_names)
          out << ",s" << n;
        out << ",damage,kind\n";
        out << std::setprecision(std::numeric_limits<double>::max_digits10);
        for (const unsigned int k : order)
          {
            for (unsigned int d = 0; d < dim; ++d)
              out << (d ? "," : "") << r.position[k][d];
            for (unsigned int d = 0; d < dim; ++d)
              out << "," << r.displacement[k][d];
            for (unsigned int c = 0; c < stress_names.size(); ++c)
              out << "," << stress_component(r.stress[k], c);
            out << "," << r.damage[k] << "," << int(r.kind[k]) << "\n";
          }
      });
    }

    template <int dim>
    void
    FieldOutput<dim>::save_state(StateArchive &state)
    {
      finish();
      std::vector<double> times;
      std::string         names;
      for (const auto &[time, name] : records)
        {
          times.push_back(time);
          names += name + "\n";
        }
      state.put("fields/counter", counter);
      state.put("fields/times", times);
      state.put("fields/names", names);
    }

    template <int dim>
    void
    FieldOutput<dim>::load_state(const StateArchive &state)
    {
      counter                 = state.get<unsigned int>("fields/counter");
      const auto        times = state.get_vector<double>("fields/times");
      const std::string names = state.get_text("fields/names");
      records.clear();
      std::size_t from = 0;
      for (const double time : times)
        {
          const std::size_t end = names.find('\n', from);
          if (end == std::string::npos)
            throw InputError(
              "",
              "--restart",
              "the checkpoint's list of field outputs is cut short");
          records.emplace_back(time, names.substr(from, end - from));
          from = end + 1;
        }
    }

#define INSTANTIATE(dim) template class FieldOutput<dim>;
    PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
  } // namespace IO
} // namespace pdfem
