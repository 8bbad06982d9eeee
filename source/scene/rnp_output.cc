// SPDX-License-Identifier: LGPL-2.1-or-later
#include "rnp_output.h"

#include <pdfem/base/config.h>

#include <fstream>
#include <iomanip>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      template <int dim>
      void
      write_rnp_vtu(const std::string                &out_dir,
                    const dealii::Triangulation<dim> &tria,
                    const std::vector<int>           &node_of,
                    const std::vector<double>        &u,
                    const std::vector<double>        &damage,
                    const std::vector<std::uint8_t>  &pd_node,
                    const double                      load_factor)
      {
        const unsigned int              n_nodes = damage.size();
        std::vector<dealii::Point<dim>> x(n_nodes);
        for (unsigned int v = 0; v < node_of.size(); ++v)
          if (node_of[v] >= 0)
            x[node_of[v]] = tria.get_vertices()[v];
        std::ofstream out(out_dir + "/solution-00001.vtu");
        out << std::setprecision(12);
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
               "version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
            << n_nodes << "\" NumberOfCells=\"" << tria.n_active_cells()
            << "\">\n<Points>\n<DataArray type=\"Float64\" "
               "NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &p : x)
          {
            for (unsigned int d = 0; d < 3; ++d)
              out << (d < dim ? p[d] : 0.) << " ";
            out << "\n";
          }
        out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" "
               "Name=\"connectivity\" format=\"ascii\">\n";
        std::vector<unsigned int> offsets, types;
        unsigned int              offset = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            const unsigned int nv = cell->n_vertices();
            // deal.II numbers quadrilaterals and hexahedra lexicographically,
            // VTK counter-clockwise; simplices agree.
            static const unsigned int quad[] = {0, 1, 3, 2};
            static const unsigned int hex[]  = {0, 1, 3, 2, 4, 5, 7, 6};
            const bool hyper = cell->reference_cell().is_hyper_cube();
            for (unsigned int k = 0; k < nv; ++k)
              {
                const unsigned int v =
                  hyper ? (dim == 2 ? quad[k] : hex[k]) : k;
                out << node_of[cell->vertex_index(v)] << " ";
              }
            out << "\n";
            offset += nv;
            offsets.push_back(offset);
            types.push_back(hyper ? (dim == 2 ? 9 : 12) : (dim == 2 ? 5 : 10));
          }
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
               "format=\"ascii\">\n";
        for (const unsigned int o : offsets)
          out << o << "\n";
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" "
               "format=\"ascii\">\n";
        for (const unsigned int t : types)
          out << t << "\n";
        out << "</DataArray>\n</Cells>\n<PointData Vectors=\"displacement\" "
               "Scalars=\"damage\">\n<DataArray type=\"Float64\" "
               "Name=\"displacement\" NumberOfComponents=\"3\" "
               "format=\"ascii\">\n";
        for (unsigned int i = 0; i < n_nodes; ++i)
          {
            for (unsigned int d = 0; d < 3; ++d)
              out << (d < dim ? u[dim * i + d] : 0.) << " ";
            out << "\n";
          }
        out << "</DataArray>\n<DataArray type=\"Float64\" Name=\"damage\" "
               "format=\"ascii\">\n";
        for (const double d : damage)
          out << d << "\n";
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"region\" "
               "format=\"ascii\">\n";
        for (const std::uint8_t p : pd_node)
          out << (p ? 1 : 2) << "\n";
        out << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n"
               "</VTKFile>\n";

        std::ofstream pvd(out_dir + "/solution.pvd");
        pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
               "version=\"0.1\">\n<Collection>\n<DataSet timestep=\""
            << load_factor
            << "\" group=\"\" part=\"0\" file=\"solution-00001.vtu\"/>\n"
               "</Collection>\n</VTKFile>\n";
      }

#define INSTANTIATE(dim)                                               \
  template void write_rnp_vtu<dim>(const std::string &,                \
                                   const dealii::Triangulation<dim> &, \
                                   const std::vector<int> &,           \
                                   const std::vector<double> &,        \
                                   const std::vector<double> &,        \
                                   const std::vector<std::uint8_t> &,  \
                                   double);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
