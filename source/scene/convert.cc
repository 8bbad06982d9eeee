// SPDX-License-Identifier: LGPL-2.1-or-later
// pdfem-convert: a PDLSM-FEM command file (.in + .lis) as a native scene
// (.prm + gmsh .msh), written from the very set-up `pdfem model.in` runs.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/drivers/interface.h>
#include <pdfem/io/parameters.h>
#include <pdfem/io/pdlsm_fem_input.h>
#include <pdfem/scene/convert.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

#include "scene_internal.h"

namespace pdfem
{
  namespace Scene
  {
    namespace
    {
      namespace fs = std::filesystem;
      using dealii::numbers::invalid_unsigned_int;
      using internal::Setup;

      /// A double that reads back bit for bit.
      std::string
      exact(const double v)
      {
        std::ostringstream s;
        s << std::setprecision(17) << v;
        return s.str();
      }

      /// Peridynamics/Weight factor of a parameter file that was read (the
      /// pdlsm model's own parameter).
      double
      weight_factor(const Parameters::Scene &prm)
      {
        prm.handler->enter_subsection("Peridynamics");
        const double a = prm.handler->get_double("Weight factor");
        prm.handler->leave_subsection();
        return a;
      }

      std::string
      join(const std::vector<std::string> &items, const std::string &sep)
      {
        std::string s;
        for (const auto &i : items)
          s += (s.empty() ? "" : sep) + i;
        return s;
      }

      /// Physical tags of the mesh file (tags are per dimension in gmsh).
      constexpr unsigned int pd_tag = 1, fe_tag = 2, first_traction_tag = 10;

      /// Nodes that are a vertex of some element.
      std::vector<bool>
      used_nodes(const IO::PDLSMFEMModel &model)
      {
        std::vector<bool> used(model.nodes.size(), false);
        for (const auto &e : model.elements)
          for (const unsigned int v : e.vertices)
            used[v] = true;
        return used;
      }

      /// The .lis mesh as gmsh 2.2 ASCII: nodes and elements in the file's
      /// order (so that the vertex numbering is the one `pdfem model.in`
      /// uses), then the node sets and the natural-set faces.
      void
      write_msh(const IO::PDLSMFEMModel &model, const std::string &file)
      {
        const int          dim       = model.dim;
        const bool         no_fail   = !model.no_fail_nodes.empty();
        const auto         used      = used_nodes(model);
        const unsigned int no_fail_t = model.essential.size() + 1;
        bool               any_pd = false, any_fe = false;
        for (const auto &e : model.elements)
          (e.type == 1 ? any_pd : any_fe) = true;

        std::ofstream out(file);
        if (!out)
          throw InputError(file, "", "cannot write the mesh file");
        out << std::setprecision(17);
        out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
        std::vector<std::string> names;
        for (std::size_t s = 0; s < model.essential.size(); ++s)
          names.push_back("0 " + std::to_string(s + 1) + " \"ebc" +
                          std::to_string(s) + "\"");
        if (no_fail)
          names.push_back("0 " + std::to_string(no_fail_t) + " \"nofail\"");
        for (std::size_t s = 0; s < model.natural.size(); ++s)
          names.push_back(std::to_string(dim - 1) + " " +
                          std::to_string(first_traction_tag + s) + " \"nbc" +
                          std::to_string(s) + "\"");
        if (any_pd)
          names.push_back(std::to_string(dim) + " " + std::to_string(pd_tag) +
                          " \"pd\"");
        if (any_fe)
          names.push_back(std::to_string(dim) + " " + std::to_string(fe_tag) +
                          " \"fe\"");
        out << "$PhysicalNames\n" << names.size() << "\n";
        for (const auto &n : names)
          out << n << "\n";
        out << "$EndPhysicalNames\n";

        out << "$Nodes\n" << model.nodes.size() << "\n";
        for (std::size_t k = 0; k < model.nodes.size(); ++k)
          out << k + 1 << " " << model.nodes[k][0] << " " << model.nodes[k][1]
              << " " << (dim == 3 ? model.nodes[k][2] : 0.) << "\n";
        out << "$EndNodes\n";

        std::vector<std::string> elements;
        const auto               add = [&](const unsigned int               type,
                             const unsigned int               tag,
                             const std::vector<unsigned int> &nodes) {
          std::string line = std::to_string(type) + " 2 " +
                             std::to_string(tag) + " " + std::to_string(tag);
          for (const unsigned int v : nodes)
            line += " " + std::to_string(v + 1);
          elements.push_back(line);
        };
        // Node sets: one point element per listed node (type 15).
        for (std::size_t s = 0; s < model.essential.size(); ++s)
          for (const unsigned int v : model.essential[s].nodes)
            add(15, s + 1, {v});
        for (const unsigned int v : model.no_fail_nodes)
          if (used[v]) // a node of no element has no bonds
            add(15, no_fail_t, {v});
        // Natural sets: lines (2D), quadrilaterals or triangles (3D).
        for (std::size_t s = 0; s < model.natural.size(); ++s)
          for (const auto &face : model.natural[s].faces)
            add(dim == 2 ? 1 : (face.size() == 4 ? 3 : 2),
                first_traction_tag + s,
                face);
        // Cells, in the file's order; gmsh's quadrilateral and hexahedron
        // orders are PDLSM-FEM's (counter-clockwise).
        for (const auto &e : model.elements)
          {
            const std::size_t n = e.vertices.size();
            const unsigned    type =
              dim == 2 ? (n == 4 ? 3 : 2) : (n == 8 ? 5 : 4);
            add(type, e.type == 1 ? pd_tag : fe_tag, e.vertices);
          }
        out << "$Elements\n" << elements.size() << "\n";
        for (std::size_t i = 0; i < elements.size(); ++i)
          out << i + 1 << " " << elements[i] << "\n";
        out << "$EndElements\n";
        if (!out)
          throw InputError(file, "", "cannot write the mesh file");
      }

      /// The .prm text of a set-up, and the checks that it says the same.
      template <int dim>
      class PrmWriter
      {
      public:
        PrmWriter(const IO::PDLSMFEMModel &model,
                  const Setup<dim>        &setup,
                  const std::string       &msh_name)
          : model(model)
          , setup(setup)
          , msh_name(msh_name)
        {}

        std::string
        text() const
        {
          const auto        &s  = setup.settings;
          const auto        &d  = setup.driver;
          const auto        &f  = setup.fracture;
          const auto        &ls = s.linear_solver;
          std::ostringstream o;
          const auto         set = [&](const std::string &entry,
                               const std::string &value,
                               const std::string &comment = "") {
            o << "  set " << entry << " = " << value;
            if (!comment.empty())
              o << "  # " << comment;
            o << "\n";
          };
          const auto flag = [](const bool b) {
            return std::string(b ? "true" : "false");
          };
          const auto component = [](const unsigned int c) {
            return c == dim ? std::string("normal") : std::string(1, "xyz"[c]);
          };

          o << "# " << setup.name << ".prm: written by pdfem-convert "
            << PDFEM_VERSION << " from the PDLSM-FEM command file\n# "
            << model.command_file << " and its mesh file " << model.mesh_file
            << ".\n# Runs what `pdfem "
            << fs::path(model.command_file).filename().string()
            << "` runs (user guide, section 2b).\n";
          for (const auto &note : setup.notes)
            o << "# note: " << note << "\n";
          o << "\nset Dimension = " << dim << "\n\n";

          bool any_pd = false;
          for (const auto &e : model.elements)
            any_pd = any_pd || e.type == 1;
          o << "subsection Mesh\n";
          set("Input file", msh_name, "regions pd, fe; node sets ebc<i>");
          set("Global refinements", "0");
          set("Mesh size factor", "1");
          set("PD regions", any_pd ? "pd" : "none");
          o << "end\n\nsubsection Material\n";
          set("Young's modulus", exact(s.material.youngs_modulus));
          set("Poisson's ratio", exact(s.material.poissons_ratio));
          set("Density", exact(s.material.density));
          set("Plane model",
              s.material.plane_stress || dim == 3 ? "plane stress" :
                                                    "plane strain");
          set("Thickness", exact(s.material.thickness));
          o << "end\n\nsubsection Peridynamics\n";
          set("Model", "pdlsm");
          set("Horizon factor", exact(s.horizon_factor));
          set("Weight factor", exact(s.weight_factor));
          set("Family members",
              s.fe_nodes_in_families ? "all nodes" : "pd nodes");
          std::vector<std::string> cracks;
          for (const auto &c : model.cracks)
            {
              std::vector<std::string> points;
              for (const auto &p : c)
                {
                  std::string q = "(";
                  for (int k = 0; k < dim; ++k)
                    q += (k ? ", " : "") + exact(p[k]);
                  points.push_back(q + ")");
                }
              cracks.push_back(join(points, " -- "));
            }
          set("Pre-existing cracks", join(cracks, "; "));
          o << "end\n\nsubsection Boundary conditions\n";
          std::vector<std::string> items;
          for (const auto &bc : s.dirichlet)
            items.push_back(bc.name + ": " + component(bc.component) + " = " +
                            bc.expression);
          set("Dirichlet", join(items, "; "));
          items.clear();
          for (const auto &bc : s.traction)
            items.push_back(bc.name + ": " + component(bc.component) + " = " +
                            bc.expression);
          set("Traction", join(items, "; "));
          set("Body force", join(s.body_force, "; "));
          items.clear();
          for (const unsigned int g : setup.reaction_group)
            items.push_back(s.dirichlet.at(g).name);
          set("Reaction group", join(items, ", "));
          o << "end\n\nsubsection Linear solver\n";
          set("Type", ls.type);
          set("Direct solver", ls.direct_solver);
          set("Preconditioner", ls.preconditioner);
          set("Tolerance", exact(ls.tolerance));
          set("Max iterations", std::to_string(ls.max_iterations));
          set("GMRES restart", std::to_string(ls.restart));
          o << "end\n\nsubsection Driver\n";
          set("Type", d.type);
          set("Load steps", std::to_string(d.load_steps));
          set("Load increment", exact(d.load_increment));
          set("Initial load", exact(d.initial_load));
          set("Jump to critical load", flag(d.jump_to_critical_load));
          set("Hold load while cracks grow", flag(d.hold_load_while_growing));
          set("Residual tolerance", exact(d.residual_tolerance));
          set("Max iterations", std::to_string(d.max_iterations));
          if (Drivers::create(d.type, model.command_file)->dynamic())
            {
              set("Time step",
                  d.time_step > 0. ? exact(d.time_step) : std::string("auto"));
              set("End time", exact(d.end_time));
              set("Time step safety factor", exact(d.safety_factor));
              set("Eigenvalue iterations",
                  std::to_string(d.eigenvalue_iterations));
              set("Newmark beta", exact(d.newmark_beta));
              set("Newmark gamma", exact(d.newmark_gamma));
              set("HHT alpha", exact(d.hht_alpha));
              set("Mass", d.mass);
              set("Reuse factorization", flag(d.reuse_factorization));
              set("Initial velocity", join(d.initial_velocity, "; "));
              set("Energy tolerance", exact(d.energy_tolerance));
              set("History interval", std::to_string(d.history_interval));
            }
          o << "end\n\nsubsection Fracture\n";
          set("Criterion", f.criterion);
          set("Fracture toughness", exact(f.toughness));
          set("Tensile strength", exact(f.tensile_strength));
          set("Domain inner radius", exact(f.domain_inner_radius));
          set("Domain outer radius", exact(f.domain_outer_radius));
          set("Growth length", exact(f.growth_length));
          set("Absolute growth length",
              exact(f.growth_length_absolute),
              "d_cf x sqrt(smallest element area)");
          set("Top K", std::to_string(f.top_k));
          set("Critical stretch", exact(f.critical_stretch));
          set("Fracture energy", exact(f.fracture_energy));
          set("Adaptive margin", exact(f.adaptive_margin));
          set("No-fail nodes", model.no_fail_nodes.empty() ? "" : "nofail");
          set("Crack tips",
              setup.tip_at_end.empty() ? "inside" : "second point");
          o << "end\n\nsubsection Output\n";
          set("Write vtu", flag(setup.write_vtu));
          set("Write every", std::to_string(setup.write_every));
          set("Write nodes csv", flag(setup.write_nodes_csv));
          set("Print timings", flag(setup.print_timings));
          o << "end\n";
          return o.str();
        }

        /// Read @p prm_file back and compare it with the set-up: what
        /// differs cannot be expressed (InputError naming the command file).
        void
        check(const std::string &prm_file) const
        {
          Parameters::Scene prm;
          try
            {
              prm.read(prm_file);
            }
          catch (const InputError &e)
            {
              throw InputError(model.command_file,
                               "",
                               "the scene cannot be expressed as a .prm: " +
                                 std::string(e.what()),
                               "an input that `pdfem` also accepts as .prm");
            }
          const auto              &s = setup.settings;
          const auto              &d = setup.driver;
          const auto              &f = setup.fracture;
          std::vector<std::string> differ;
          const auto expect = [&](const bool same, const std::string &what) {
            if (!same)
              differ.push_back(what);
          };
          expect(prm.dim == dim, "Dimension");
          expect(prm.material.youngs_modulus == s.material.youngs_modulus &&
                   prm.material.poissons_ratio == s.material.poissons_ratio &&
                   prm.material.density == s.material.density &&
                   prm.material.thickness == s.material.thickness,
                 "Material");
          expect(prm.peridynamics.horizon_factor == s.horizon_factor &&
                   weight_factor(prm) == s.weight_factor &&
                   prm.peridynamics.fe_nodes_in_families ==
                     s.fe_nodes_in_families &&
                   prm.peridynamics.cracks.size() == s.cracks.size(),
                 "Peridynamics");
          expect(prm.boundary_conditions.dirichlet.size() ==
                     s.dirichlet.size() &&
                   prm.boundary_conditions.traction.size() ==
                     s.traction.size() &&
                   prm.boundary_conditions.reaction_group.size() ==
                     setup.reaction_group.size(),
                 "Boundary conditions");
          expect(prm.linear_solver.type == s.linear_solver.type &&
                   prm.linear_solver.direct_solver ==
                     s.linear_solver.direct_solver &&
                   prm.linear_solver.preconditioner ==
                     s.linear_solver.preconditioner &&
                   prm.linear_solver.tolerance == s.linear_solver.tolerance &&
                   prm.linear_solver.max_iterations ==
                     s.linear_solver.max_iterations &&
                   prm.linear_solver.restart == s.linear_solver.restart,
                 "Linear solver");
          auto p = prm.driver; // the time stepping is parsed by its driver
          expect(p.type == d.type && p.load_steps == d.load_steps &&
                   p.load_increment == d.load_increment &&
                   p.initial_load == d.initial_load &&
                   p.jump_to_critical_load == d.jump_to_critical_load &&
                   p.hold_load_while_growing == d.hold_load_while_growing &&
                   p.residual_tolerance == d.residual_tolerance &&
                   p.max_iterations == d.max_iterations,
                 "Driver");
          const bool dynamic =
            Drivers::create(d.type, model.command_file)->dynamic();
          if (dynamic)
            p.check_time_stepping(prm_file, dim, true);
          if (dynamic)
            expect(p.time_step == d.time_step && p.end_time == d.end_time &&
                     p.safety_factor == d.safety_factor &&
                     p.newmark_beta == d.newmark_beta &&
                     p.newmark_gamma == d.newmark_gamma &&
                     p.hht_alpha == d.hht_alpha && p.mass == d.mass &&
                     p.reuse_factorization == d.reuse_factorization &&
                     p.history_interval == d.history_interval &&
                     p.energy_tolerance == d.energy_tolerance,
                   "Driver (dynamic)");
          const auto &q = prm.fracture;
          expect(q.criterion == f.criterion && q.toughness == f.toughness &&
                   q.tensile_strength == f.tensile_strength &&
                   q.domain_inner_radius == f.domain_inner_radius &&
                   q.domain_outer_radius == f.domain_outer_radius &&
                   q.growth_length == f.growth_length &&
                   q.growth_length_absolute == f.growth_length_absolute &&
                   q.top_k == f.top_k &&
                   q.adaptive_margin == f.adaptive_margin &&
                   q.critical_stretch == f.critical_stretch &&
                   q.fracture_energy == f.fracture_energy &&
                   q.tip_at_second_point == !setup.tip_at_end.empty(),
                 "Fracture");
          expect(prm.output.write_every == setup.write_every &&
                   prm.output.write_vtu == setup.write_vtu,
                 "Output");
          if (!differ.empty())
            throw InputError(model.command_file,
                             "",
                             "the .prm would differ from the run in " +
                               join(differ, ", ") + " (cannot be expressed)",
                             "report this: the converter lacks an entry");
        }

      private:
        const IO::PDLSMFEMModel &model;
        const Setup<dim>        &setup;
        const std::string        msh_name;
      };

      template <int dim>
      Conversion
      convert(const IO::PDLSMFEMModel &model,
              const std::string       &output_dir,
              MPI_Comm                 comm)
      {
        // The set-up of `pdfem model.in`: every check and every choice of
        // the run (solver, tolerances, growth length...) in one place.
        RunOptions options;
        options.output_directory = output_dir.empty() ? "." : output_dir;
        Setup<dim> setup;
        internal::setup_from_pdlsm_fem<dim>(model, options, comm, setup);

        // What the run would refuse later (CoupledSystem): a node set with
        // a node of no element. Say it now, in the run's words.
        const auto used = used_nodes(model);
        for (std::size_t s = 0; s < model.essential.size(); ++s)
          for (const unsigned int v : model.essential[s].nodes)
            if (!used[v])
              throw InputError(model.command_file,
                               "ebc" + std::to_string(s),
                               "node " + std::to_string(v + 1) +
                                 " belongs to no element",
                               "nodes of the mesh's elements");

        // Node sets are matched to the mesh by their coordinates
        // (Mesh::read_node_sets): a node at the place of another vertex (a
        // seam) cannot be told apart in a .msh.
        std::map<std::array<double, dim>, unsigned int> node_at;
        std::vector<unsigned int>                       twin(model.nodes.size(),
                                       invalid_unsigned_int);
        for (unsigned int v = 0; v < model.nodes.size(); ++v)
          if (used[v])
            {
              std::array<double, dim> key;
              for (unsigned int d = 0; d < dim; ++d)
                key[d] = model.nodes[v][d];
              const auto [it, inserted] = node_at.emplace(key, v);
              if (!inserted)
                {
                  twin[v]          = it->second;
                  twin[it->second] = v;
                }
            }
        const auto check_set = [&](const std::vector<unsigned int> &nodes,
                                   const std::string               &set) {
          for (const unsigned int v : nodes)
            if (used[v] && twin[v] != invalid_unsigned_int)
              throw InputError(model.command_file,
                               set,
                               "cannot be expressed as a .prm: node " +
                                 std::to_string(v + 1) +
                                 " lies at the place of node " +
                                 std::to_string(twin[v] + 1) +
                                 ", and node sets are matched to the mesh by "
                                 "their coordinates",
                               "node sets without coincident nodes (or run "
                               "the .in file itself)");
        };
        for (std::size_t s = 0; s < model.essential.size(); ++s)
          check_set(model.essential[s].nodes, "ebc" + std::to_string(s));
        check_set(model.no_fail_nodes, "NO FAIL region");

        Conversion result;
        result.notes = setup.notes;
        const fs::path dir(output_dir.empty() ? "." : output_dir);
        result.msh_file = (dir / (setup.name + ".msh")).string();
        result.prm_file = (dir / (setup.name + ".prm")).string();
        const PrmWriter<dim> writer(model, setup, setup.name + ".msh");
        try
          {
            write_msh(model, result.msh_file);
            std::ofstream out(result.prm_file);
            out << writer.text();
            out.close();
            if (!out)
              throw InputError(result.prm_file, "", "cannot write the scene");
            writer.check(result.prm_file);
          }
        catch (const InputError &)
          {
            // Nothing half-written stays behind.
            std::error_code ec;
            fs::remove(result.prm_file, ec);
            fs::remove(result.msh_file, ec);
            throw;
          }
        return result;
      }
    } // namespace

    Conversion
    convert_pdlsm_fem(const std::string &command_file,
                      const std::string &output_dir,
                      MPI_Comm           comm)
    {
      const IO::PDLSMFEMModel model = IO::read_pdlsm_fem(command_file);
      if (model.dim == 2)
        return convert<2>(model, output_dir, comm);
#if PDFEM_WITH_3D
      return convert<3>(model, output_dir, comm);
#else
      throw InputError(command_file,
                       "3D",
                       "this pdfem was built without 3D",
                       "2D (rebuild with PDFEM_WITH_3D=ON)");
#endif
    }
  } // namespace Scene
} // namespace pdfem
