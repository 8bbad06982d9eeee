// SPDX-License-Identifier: LGPL-2.1-or-later
// The run of a scene with Peridynamics/Model = rnp: every mesh vertex is an
// RNP node (specs/000), solved by the Newton driver with its stability check
// (or the static driver), history.csv and summary.json as for every scene.
#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>
#include <pdfem/coupling/rnp_system.h>
#include <pdfem/drivers/newton_driver.h>
#include <pdfem/drivers/static_driver.h>
#include <pdfem/io/history.h>
#include <pdfem/io/json_writer.h>
#include <pdfem/pd_models/rnp.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>

#include "rnp_output.h"
#include "scene_internal.h"
#include <sys/resource.h>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using namespace dealii;
      using Coupling::component_names;

      namespace
      {
        using clock = std::chrono::steady_clock;

        /// x, y, z, t expressions (z = 0 in 2D), as everywhere in pdfem.
        struct Expression
        {
          explicit Expression(const std::string &text)
            : f(1)
          {
            f.initialize("x,y,z,t",
                         text,
                         std::map<std::string, double>(),
                         true);
          }
          template <int dim>
          double
          operator()(const Point<dim> &p, const double t)
          {
            Point<3> q;
            for (unsigned int d = 0; d < dim; ++d)
              q[d] = p[d];
            f.set_time(t);
            return f.value(q);
          }
          FunctionParser<3> f;
        };

        template <int dim>
        Tensor<1, dim>
        outward_normal(const typename Triangulation<dim>::face_iterator &face,
                       const Point<dim> &cell_center)
        {
          Tensor<1, dim> n;
          if constexpr (dim == 2)
            {
              const Tensor<1, 2> t = face->vertex(1) - face->vertex(0);
              n[0]                 = t[1];
              n[1]                 = -t[0];
            }
          else
            {
              const Tensor<1, 3> a = face->vertex(1) - face->vertex(0);
              const Tensor<1, 3> b =
                face->vertex(face->n_vertices() - 1) - face->vertex(0);
              n = cross_product_3d(a, b);
            }
          n /= n.norm();
          if ((face->center() - cell_center) * n < 0.)
            n = -n;
          return n;
        }
      } // namespace

      template <int dim>
      int
      execute_rnp(Setup<dim>              &setup,
                  const Parameters::Scene &prm,
                  const RunOptions        &options,
                  MPI_Comm                 comm)
      {
        const auto &tria     = *setup.tria;
        const auto &settings = setup.settings;
        const auto &rp       = prm.rnp;
        const bool  plane_strain =
          dim == 2 &&
          prm.material.plane == Parameters::PlaneModel::plane_strain;

        // ---- input checks (before any work)
        if (Utilities::MPI::n_mpi_processes(comm) > 1)
          throw InputError(prm.file,
                           "Peridynamics/Model",
                           "rnp runs on one MPI rank",
                           "run without mpirun, or with -np 1");
        for (const auto &cell : tria.active_cell_iterators())
          if (!setup.cell_is_pd[cell->active_cell_index()] &&
              !cell->reference_cell().is_hyper_cube())
            throw InputError(prm.file,
                             "Mesh/PD regions",
                             "the FE cells around an RNP region must be "
                             "quadrilaterals or hexahedra",
                             "a quad/hex mesh for the FE region, or all PD");
        PDModels::RNPSettings model;
        model.influence = rp.influence == "linear" ?
                            PDModels::RNPInfluence::linear :
                            PDModels::RNPInfluence::constant;
        model.scaling   = rp.force_scaling == "prototype" ?
                            PDModels::RNPForceScaling::prototype :
                            PDModels::RNPForceScaling::paper;
        if (rp.calibration == "constants")
          {
            if (!(rp.C > 0.) || !(rp.beta > 0.))
              throw InputError(prm.file,
                               "Peridynamics/RNP/C, beta",
                               "C = " + number(rp.C) +
                                 ", beta = " + number(rp.beta) +
                                 ": both must be positive with Calibration "
                                 "= constants",
                               "C > 0 and beta > 0");
            model.C    = rp.C;
            model.beta = rp.beta;
          }
        else
          {
            const double nu = PDModels::rnp_poissons_ratio(dim, plane_strain);
            if (std::abs(prm.material.poissons_ratio - nu) > 1e-3)
              throw InputError(
                prm.file,
                "Material/Poisson's ratio",
                "nu = " + number(prm.material.poissons_ratio) +
                  " cannot be calibrated: a bond-based (RNP) "
                  "material has nu = " +
                  number(nu) +
                  (dim == 2 ?
                     (plane_strain ? " in plane strain" : " in plane stress") :
                     " in 3D"),
                number(nu) + " (or Peridynamics/RNP/Calibration = constants)");
            if (!(rp.fracture_energy > 0.))
              throw InputError(prm.file,
                               "Peridynamics/RNP/Fracture energy",
                               "G_c = " + number(rp.fracture_energy) +
                                 " is not positive",
                               "G_c > 0 with Calibration = moduli");
            const double c_beta = PDModels::rnp_c_beta(
              prm.material.youngs_modulus, model.influence, dim, plane_strain);
            model.C = PDModels::rnp_c_from_fracture_energy(rp.fracture_energy,
                                                           model.influence,
                                                           dim);
            model.beta = c_beta / model.C;
          }

        // ---- nodes: the used vertices; volumes; horizon
        auto                    start    = clock::now();
        const auto             &vertices = tria.get_vertices();
        std::vector<int>        node_of(vertices.size(), -1);
        std::vector<Point<dim>> x;
        for (unsigned int v = 0; v < vertices.size(); ++v)
          if (tria.get_used_vertices()[v])
            {
              node_of[v] = x.size();
              x.push_back(vertices[v]);
            }
        // Volumes: PD cells' shares; with FE nodes as family members, every
        // cell's share (an interface node stands for material on both sides).
        const bool          fe_members = prm.peridynamics.fe_nodes_in_families;
        std::vector<double> volume(x.size(), 0.);
        std::vector<std::uint8_t> pd_node(x.size(), 0);
        double                    h = 0.;
        for (const auto &cell : tria.active_cell_iterators())
          {
            const bool pd = setup.cell_is_pd[cell->active_cell_index()];
            if (pd)
              h = std::max(h, std::pow(cell->measure(), 1. / dim));
            for (const unsigned int v : cell->vertex_indices())
              {
                const int k = node_of[cell->vertex_index(v)];
                if (pd || fe_members)
                  volume[k] += cell->measure() / cell->n_vertices();
                if (pd)
                  pd_node[k] = 1;
              }
          }
        // Energy partition: the PD share of each node's volume (1 inside the
        // RNP region, 0 in the FE region, between at the interface).
        std::vector<double> energy_weight;
        if (rp.interface_energy == "partition")
          {
            std::vector<double> pd_share(x.size(), 0.), all(x.size(), 0.);
            for (const auto &cell : tria.active_cell_iterators())
              for (const unsigned int v : cell->vertex_indices())
                {
                  const int    k     = node_of[cell->vertex_index(v)];
                  const double share = cell->measure() / cell->n_vertices();
                  all[k] += share;
                  if (setup.cell_is_pd[cell->active_cell_index()])
                    pd_share[k] += share;
                }
            energy_weight.resize(x.size());
            for (unsigned int i = 0; i < x.size(); ++i)
              energy_weight[i] = all[i] > 0. ? pd_share[i] / all[i] : 0.;
          }
        if (rp.nodal_volumes == "uniform")
          for (unsigned int i = 0; i < x.size(); ++i)
            volume[i] = (pd_node[i] || fe_members) ? std::pow(h, dim) : 0.;

        // ---- the FE cells: Q1 stiffness matrices on the shared nodes
        typename Coupling::RNPSystem<dim>::LinearElements elements;
        {
          const FESystem<dim>              fe(FE_Q<dim>(1), dim);
          const QGauss<dim>                quadrature(2);
          FEValues<dim>                    values(fe,
                               quadrature,
                               update_gradients | update_JxW_values);
          const FEValuesExtractors::Vector displacement(0);
          const double                     lambda = settings.material.lambda();
          const double                     mu     = settings.material.mu();
          const unsigned int               n      = fe.n_dofs_per_cell();
          for (const auto &cell : tria.active_cell_iterators())
            if (!setup.cell_is_pd[cell->active_cell_index()])
              {
                values.reinit(cell);
                std::vector<double>       Ke(n * n, 0.);
                std::vector<unsigned int> dofs(n);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const auto ci = fe.system_to_component_index(i);
                    dofs[i] =
                      dim * node_of[cell->vertex_index(ci.second)] + ci.first;
                  }
                for (const unsigned int q : values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const auto ei =
                        values[displacement].symmetric_gradient(i, q);
                      const double di = trace(ei);
                      for (unsigned int j = 0; j < n; ++j)
                        {
                          const auto ej =
                            values[displacement].symmetric_gradient(j, q);
                          Ke[i * n + j] +=
                            (lambda * di * trace(ej) + 2. * mu * (ei * ej)) *
                            values.JxW(q);
                        }
                    }
                elements.dofs.push_back(dofs);
                elements.matrices.push_back(Ke);
              }
        }
        model.horizon          = prm.peridynamics.horizon_factor * h;
        const double thickness = dim == 2 ? prm.material.thickness : 1.;

        // ---- loads: Dirichlet layers, tractions, body force
        const unsigned int                       n_dofs = dim * x.size();
        typename Coupling::RNPSystem<dim>::Loads loads;
        loads.constrained.assign(n_dofs, 0);
        std::vector<std::string>               set_names;
        std::vector<std::vector<unsigned int>> set_nodes;
        struct Prescribed
        {
          unsigned int dof;
          unsigned int node;
          unsigned int expression;
        };
        std::vector<Prescribed>  prescribed;
        std::vector<std::string> expressions;
        const double             layer = rp.dirichlet_layer * model.horizon;
        for (const auto &bc : settings.dirichlet)
          {
            std::vector<unsigned int> nodes;
            if (bc.at_point)
              {
                // the nearest node, and every node within the layer
                unsigned int best = 0;
                for (unsigned int i = 1; i < x.size(); ++i)
                  if (x[i].distance(bc.point) < x[best].distance(bc.point))
                    best = i;
                nodes.push_back(best);
                const double r2 = layer * layer * (1. + 1e-10);
                for (unsigned int i = 0; i < x.size(); ++i)
                  if (i != best && pd_node[i] &&
                      x[i].distance_square(bc.point) <= r2)
                    nodes.push_back(i);
              }
            else
              {
                std::vector<Point<dim>> on_boundary;
                for (const auto &face : tria.active_face_iterators())
                  if (face->at_boundary() && std::count(bc.boundary_ids.begin(),
                                                        bc.boundary_ids.end(),
                                                        face->boundary_id()))
                    for (const unsigned int v : face->vertex_indices())
                      on_boundary.push_back(face->vertex(v));
                // PD nodes: the nonlocal layer; FE nodes: the boundary's own
                const double r2_fe = 1e-24 * h * h;
                const double r2    = layer * layer * (1. + 1e-10) + r2_fe;
                for (unsigned int i = 0; i < x.size(); ++i)
                  for (const auto &p : on_boundary)
                    if (x[i].distance_square(p) <= (pd_node[i] ? r2 : r2_fe))
                      {
                        nodes.push_back(i);
                        break;
                      }
              }
            const auto it =
              std::find(set_names.begin(), set_names.end(), bc.name);
            if (it == set_names.end())
              {
                set_names.push_back(bc.name);
                set_nodes.push_back(nodes);
              }
            else
              {
                auto &s = set_nodes[it - set_names.begin()];
                s.insert(s.end(), nodes.begin(), nodes.end());
              }
            expressions.push_back(bc.expression);
            for (const unsigned int i : nodes)
              {
                loads.constrained[dim * i + bc.component] = 1;
                prescribed.push_back({dim * i + bc.component,
                                      i,
                                      unsigned(expressions.size() - 1)});
              }
          }
        auto functions = std::make_shared<std::deque<Expression>>();
        for (const auto &e : expressions)
          functions->emplace_back(e);
        loads.prescribed = [prescribed, functions, x](double               t,
                                                      std::vector<double> &u) {
          for (const auto &p : prescribed)
            u[p.dof] = (*functions)[p.expression](x[p.node], t);
        };

        // tractions: each boundary face's force to its vertices
        struct NodalLoad
        {
          unsigned int   node;
          unsigned int   component; // dim: normal
          Tensor<1, dim> normal;
          double         weight; // area share [m^(dim-1)]
          unsigned int   expression;
        };
        auto nodal_loads = std::make_shared<std::vector<NodalLoad>>();
        auto traction_fn = std::make_shared<std::deque<Expression>>();
        for (const auto &bc : settings.traction)
          {
            traction_fn->emplace_back(bc.expression);
            for (const auto &cell : tria.active_cell_iterators())
              for (const unsigned int f : cell->face_indices())
                if (cell->at_boundary(f) &&
                    std::count(bc.boundary_ids.begin(),
                               bc.boundary_ids.end(),
                               cell->face(f)->boundary_id()))
                  {
                    const auto face = cell->face(f);
                    const auto n    = outward_normal<dim>(face, cell->center());
                    for (const unsigned int v : face->vertex_indices())
                      nodal_loads->push_back(
                        {unsigned(node_of[face->vertex_index(v)]),
                         bc.component,
                         n,
                         face->measure() / face->n_vertices(),
                         unsigned(traction_fn->size() - 1)});
                  }
          }
        auto body_fn        = std::make_shared<std::deque<Expression>>();
        bool has_body_force = false;
        for (const auto &e : settings.body_force)
          {
            body_fn->emplace_back(e);
            has_body_force = has_body_force || e != "0";
          }
        loads.external_force =
          [nodal_loads, traction_fn, body_fn, x, volume, has_body_force](
            double t, std::vector<double> &f) {
            std::fill(f.begin(), f.end(), 0.);
            for (const auto &l : *nodal_loads)
              {
                const double v = (*traction_fn)[l.expression](x[l.node], t);
                if (l.component == dim)
                  for (unsigned int c = 0; c < dim; ++c)
                    f[dim * l.node + c] += l.weight * v * l.normal[c];
                else
                  f[dim * l.node + l.component] += l.weight * v;
              }
            if (has_body_force)
              for (unsigned int i = 0; i < x.size(); ++i)
                for (unsigned int c = 0; c < dim && c < body_fn->size(); ++c)
                  f[dim * i + c] += volume[i] * (*body_fn)[c](x[i], t);
          };

        std::function<bool(const Point<dim> &, const Point<dim> &)> cut;
        if (!settings.cracks.empty())
          cut = [cracks = settings.cracks](const Point<dim> &a,
                                           const Point<dim> &b) {
            return Mesh::cut_by_any<dim>(cracks, a, b);
          };
        Coupling::RNPSystem<dim> system(
          x,
          volume,
          model,
          cut,
          loads,
          rp.tangent == "analytic" ? Coupling::RNPTangent::analytic :
                                     Coupling::RNPTangent::finite_difference,
          pd_node,
          elements,
          fe_members,
          energy_weight);
        // ---- patch test of the RNP-FE coupling (runs with FE cells): for
        // each unit strain mode eps, u = eps (x - x_c) prescribed on the
        // boundary (FE nodes on it, PD nodes within a horizon of it, so that
        // the PD surface effect is not counted), the rest solved in the
        // linear regime, without pre-cracks. An exact coupling reproduces
        // the affine field; the error is the ghost forces' doing
        // (theory.md §8.3).
        struct PatchTest
        {
          unsigned int modes = 0, held_nodes = 0;
          double       error = 0., ghost_force = 0.;
        } patch;
        if (!elements.dofs.empty())
          {
            std::vector<Point<dim>> on_boundary;
            for (const auto &face : tria.active_face_iterators())
              if (face->at_boundary())
                for (const unsigned int v : face->vertex_indices())
                  on_boundary.push_back(face->vertex(v));
            Point<dim> lo = x[0], hi = x[0];
            for (const auto &p : x)
              for (unsigned int c = 0; c < dim; ++c)
                {
                  lo[c] = std::min(lo[c], p[c]);
                  hi[c] = std::max(hi[c], p[c]);
                }
            const Point<dim>                         centre = 0.5 * (lo + hi);
            typename Coupling::RNPSystem<dim>::Loads patch_loads;
            patch_loads.constrained.assign(n_dofs, 0);
            const double r2_fe = 1e-24 * h * h;
            const double r2 =
              model.horizon * model.horizon * (1. + 1e-10) + r2_fe;
            for (unsigned int i = 0; i < x.size(); ++i)
              for (const auto &p : on_boundary)
                if (x[i].distance_square(p) <= (pd_node[i] ? r2 : r2_fe))
                  {
                    for (unsigned int c = 0; c < dim; ++c)
                      patch_loads.constrained[dim * i + c] = 1;
                    ++patch.held_nodes;
                    break;
                  }
            // linear regime: bond r = sqrt|xi| S <= 1e-4 r_c
            const double scale =
              1e-4 / std::sqrt(2. * model.beta) / std::sqrt(model.horizon);
            auto strain = std::make_shared<Tensor<2, dim>>();
            patch_loads.prescribed =
              [strain, x, centre](double, std::vector<double> &u) {
                for (unsigned int i = 0; i < x.size(); ++i)
                  {
                    const Tensor<1, dim> v = *strain * (x[i] - centre);
                    for (unsigned int c = 0; c < dim; ++c)
                      u[dim * i + c] = v[c];
                  }
              };
            patch_loads.external_force = [](double, std::vector<double> &f) {
              std::fill(f.begin(), f.end(), 0.);
            };
            Coupling::RNPSystem<dim> patch_system(
              x,
              volume,
              model,
              {},
              patch_loads,
              Coupling::RNPTangent::analytic,
              pd_node,
              elements,
              fe_members,
              energy_weight);
            const double lambda = settings.material.lambda();
            const double mu     = settings.material.mu();
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = a; b < dim; ++b)
                {
                  *strain         = Tensor<2, dim>();
                  (*strain)[a][b] = (*strain)[b][a] = scale;
                  Tensor<2, dim> sigma              = 2. * mu * *strain;
                  for (unsigned int c = 0; c < dim; ++c)
                    sigma[c][c] += lambda * trace(*strain);
                  TrilinosWrappers::MPI::Vector pu, pr, pdu;
                  patch_system.initialize_vector(pu);
                  patch_system.apply_dirichlet(pu, 0.);
                  double u_max = 0.;
                  for (unsigned int i = 0; i < x.size(); ++i)
                    u_max = std::max(u_max, (*strain * (x[i] - centre)).norm());
                  // ghost forces: f_int of the affine field on the free nodes
                  {
                    std::vector<double> affine(n_dofs), f;
                    patch_loads.prescribed(0., affine);
                    patch_system.internal_force(affine, f);
                    for (unsigned int i = 0; i < x.size(); ++i)
                      if (!patch_loads.constrained[dim * i])
                        {
                          double g = 0.;
                          for (unsigned int c = 0; c < dim; ++c)
                            g += f[dim * i + c] * f[dim * i + c];
                          patch.ghost_force =
                            std::max(patch.ghost_force,
                                     std::sqrt(g) /
                                       (sigma.norm() * std::pow(h, dim - 1)));
                        }
                  }
                  for (unsigned int it = 0; it < 2; ++it)
                    {
                      patch_system.residual(pu, 0., pr, true);
                      patch_system.solve_linear(pdu, pr);
                      pu += pdu;
                    }
                  for (unsigned int i = 0; i < x.size(); ++i)
                    {
                      const Tensor<1, dim> v = *strain * (x[i] - centre);
                      double               e = 0.;
                      for (unsigned int c = 0; c < dim; ++c)
                        e +=
                          (pu[dim * i + c] - v[c]) * (pu[dim * i + c] - v[c]);
                      patch.error = std::max(patch.error, std::sqrt(e) / u_max);
                    }
                  ++patch.modes;
                }
          }

        auto &timings          = setup.timings;
        timings["setup"]       = seconds_since(setup.setup_start);
        std::ostream *progress = options.quiet ? nullptr : &std::cout;
        if (progress)
          *progress << "pdfem " << PDFEM_VERSION << ": " << setup.file << "\n"
                    << "  " << dim << "D RNP, " << x.size() << " nodes ("
                    << std::count(pd_node.begin(), pd_node.end(), 1) << " PD, "
                    << elements.dofs.size() << " FE cells), "
                    << system.n_bonds() << " bonds (" << system.n_cut_bonds()
                    << " cut by pre-cracks), horizon " << model.horizon
                    << ", C = " << model.C << ", beta = " << model.beta
                    << ", band " << system.matrix().bandwidth() << std::endl;
        if (progress && patch.modes > 0)
          *progress << "  patch test of the RNP-FE coupling (" << patch.modes
                    << " strain modes, " << patch.held_nodes
                    << " boundary nodes held): max error " << patch.error
                    << " of the affine field, ghost force " << patch.ghost_force
                    << " sigma h^(d-1)" << std::endl;

        // ---- history
        // The common columns first (scene_internal.h, design.md), then the
        // RNP ones: softened nodes (d > 1), how far they reach in x, and
        // whether the state is stable (1), not (0), or was not checked (-1).
        std::vector<std::string> columns =
          base_history_columns<dim>(set_names, false);
        for (const char *c : {"softened_nodes", "softened_x_max", "stable"})
          columns.push_back(c);
        for (const auto &c : component_names<dim>())
          columns.push_back("max_abs_displacement_" + c);
        // 2D pre-cracks: the tip p1 advanced to the farthest softened node
        // (d > 1) within a horizon of the crack's line, ahead of p0.
        const unsigned int n_tips = dim == 2 ? settings.cracks.size() : 0;
        for (unsigned int k = 1; k <= n_tips; ++k)
          for (const char *c : {"_x", "_y"})
            columns.push_back("tip" + std::to_string(k) + c);
        auto crack_tips = [&]() {
          std::vector<std::pair<Point<dim>, double>> tips; // tip, advance
          const auto &d = system.damage_history();
          for (unsigned int k = 0; k < n_tips; ++k)
            {
              const Point<dim>    &p0      = settings.cracks[k].points[0];
              const Point<dim>    &p1      = settings.cracks[k].points[dim - 1];
              const double         L       = p0.distance(p1);
              const Tensor<1, dim> e       = (p1 - p0) / L;
              double               advance = 0.;
              for (unsigned int i = 0; i < x.size(); ++i)
                if (d[i] > 1.)
                  {
                    const Tensor<1, dim> r = x[i] - p0;
                    const double         s = r * e;
                    if (s > 0. && (r - s * e).norm() <= model.horizon)
                      advance = std::max(advance, s - L);
                  }
              tips.emplace_back(p1 + advance * e, advance);
            }
          return tips;
        };
        columns.push_back("wall_seconds");
        IO::History history(setup.out_dir + "/history.csv", columns, true);

        auto reactions = [&]() {
          std::vector<Tensor<1, dim>> R(set_names.size());
          const auto                 &fi = system.last_internal_force();
          const auto                 &fe = system.last_external_force();
          for (std::size_t s = 0; s < set_names.size(); ++s)
            {
              std::vector<unsigned int> nodes = set_nodes[s];
              std::sort(nodes.begin(), nodes.end());
              nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
              for (const unsigned int i : nodes)
                for (unsigned int c = 0; c < dim; ++c)
                  R[s][c] += thickness * (fi[dim * i + c] - fe[dim * i + c]);
            }
          return R;
        };
        auto softened = [&](unsigned int &count, double &x_max) {
          count         = 0;
          x_max         = 0.;
          const auto &d = system.damage_history();
          for (unsigned int i = 0; i < x.size(); ++i)
            if (d[i] > 1.)
              {
                x_max = count == 0 ? x[i][0] : std::max(x_max, x[i][0]);
                ++count;
              }
        };

        TrilinosWrappers::MPI::Vector u;
        system.initialize_vector(u);
        std::vector<double> last_u(n_dofs, 0.);
        double              last_load = 0., peak_load = 0.;
        unsigned int        n_steps = 0;
        // -1: not checked; the Newton driver records stable states only,
        // the arc length driver reports every check before the step
        double last_stable =
          setup.driver.type == "newton" && setup.driver.stability_check ? 1. :
                                                                          -1.;
        const auto on_check = [&](const Drivers::StabilityReport &report) {
          last_stable = report.stable() ? 1. : 0.;
        };
        const auto on_step = [&](const Drivers::StepRecord &record) {
          n_steps = record.step;
          last_u.assign(u.begin(), u.end());
          last_load = record.load_factor;
          peak_load = std::max(peak_load, last_load);
          system.update_damage_history(last_u);
          const auto  &d    = system.damage_history();
          const double dmax = *std::max_element(d.begin(), d.end());
          unsigned int n_soft;
          double       soft_x;
          softened(n_soft, soft_x);
          std::vector<double> row = {double(record.step),
                                     record.time,
                                     record.load_factor,
                                     double(record.newton_iterations),
                                     double(record.linear_iterations),
                                     record.relative_residual,
                                     0.,
                                     dmax};
          for (const auto &R : reactions())
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(R[c]);
          row.push_back(n_soft);
          row.push_back(soft_x);
          row.push_back(last_stable);
          for (unsigned int c = 0; c < dim; ++c)
            {
              double m = 0.;
              for (unsigned int i = 0; i < x.size(); ++i)
                m = std::max(m, std::abs(last_u[dim * i + c]));
              row.push_back(m);
            }
          for (const auto &tip : crack_tips())
            for (unsigned int c = 0; c < dim; ++c)
              row.push_back(tip.first[c]);
          row.push_back(seconds_since(setup.total_start));
          history.add_row(row);
          if (progress)
            *progress << "Step " << std::setw(4) << record.step
                      << "  t = " << std::setw(8) << std::setprecision(5)
                      << record.load_factor << "  iterations "
                      << record.newton_iterations
                      << "  |r|/|f| = " << std::scientific
                      << std::setprecision(2) << record.relative_residual
                      << std::defaultfloat << "  max damage "
                      << std::setprecision(4) << dmax << "  softened nodes "
                      << n_soft << std::endl;
        };

        std::string            exit_state = "completed", message;
        Drivers::NewtonOutcome outcome;
        start = clock::now();
        try
          {
            // f_ext(t) = t q and prescribed values affine in t,
            // u_p(t) = u_p(0) + t w: soft loading (w = 0), hard loading
            // (q = 0) or both. d r / d t = q - K_fp(u) w on the free
            // DoFs.
            std::vector<double> f0(n_dofs), f1(n_dofs), fh(n_dofs),
              u0(n_dofs, 0.), u1(n_dofs, 0.), uh(n_dofs, 0.);
            loads.external_force(0., f0);
            loads.external_force(1., f1);
            loads.external_force(0.5, fh);
            loads.prescribed(0., u0);
            loads.prescribed(1., u1);
            loads.prescribed(0.5, uh);
            double fmax = 0., fdev = 0., umax = 0., udev = 0.;
            auto   w = std::make_shared<std::vector<double>>(n_dofs, 0.);
            for (unsigned int d = 0; d < n_dofs; ++d)
              {
                fmax = std::max(fmax, std::abs(f1[d]));
                fdev = std::max(
                  {fdev, std::abs(f0[d]), std::abs(fh[d] - 0.5 * f1[d])});
                if (loads.constrained[d])
                  {
                    (*w)[d] = u1[d] - u0[d];
                    umax    = std::max(umax, std::abs((*w)[d]));
                    udev =
                      std::max(udev, std::abs(uh[d] - 0.5 * (u0[d] + u1[d])));
                  }
              }
            const bool linear_in_t =
              !(fdev > 1e-12 * fmax || udev > 1e-12 * umax ||
                (fmax == 0. && umax == 0.));
            auto q = std::make_shared<std::vector<double>>(n_dofs, 0.);
            for (unsigned int d = 0; d < n_dofs; ++d)
              if (!loads.constrained[d])
                (*q)[d] = f1[d];
            Drivers::NewtonDriver::LoadDerivative dr_dt;
            if (linear_in_t)
              dr_dt =
                [&system, q, w, umax, n_dofs, constrained = loads.constrained](
                  const TrilinosWrappers::MPI::Vector &u,
                  double,
                  TrilinosWrappers::MPI::Vector &out) {
                  system.initialize_vector(out);
                  std::vector<double> Kw(n_dofs, 0.);
                  if (umax > 0.)
                    system.tangent_product(
                      std::vector<double>(u.begin(), u.end()), *w, Kw);
                  for (unsigned int d = 0; d < n_dofs; ++d)
                    if (!constrained[d])
                      out[d] = (*q)[d] - Kw[d];
                  out.compress(VectorOperation::insert);
                };
            if (setup.driver.type == "arc length")
              {
                if (!linear_in_t)
                  throw InputError(
                    prm.file,
                    "Driver/Type",
                    "arc length needs loads linear in t (tractions and body "
                    "force t q, prescribed values u_p(0) + t w)",
                    "such loads, or the newton driver");
                Drivers::NewtonDriver driver(setup.driver);
                try
                  {
                    driver.run_arc_length(system,
                                          u,
                                          dr_dt,
                                          setup.driver.arc_length_steps,
                                          on_step,
                                          &system,
                                          on_check);
                  }
                catch (...)
                  {
                    outcome             = driver.outcome();
                    timings["assembly"] = driver.timings().assembly;
                    timings["solve"]    = driver.timings().solve;
                    throw;
                  }
                outcome             = driver.outcome();
                timings["assembly"] = driver.timings().assembly;
                timings["solve"]    = driver.timings().solve;
              }
            else if (setup.driver.type == "newton")
              {
                Drivers::NewtonDriver driver(setup.driver);
                try
                  {
                    // The snap-back continuation under hard loading only: under
                    // force control a fold is the end of quasi-static growth
                    // (the jump is the dynamic, unstable growth).
                    driver.run(system,
                               u,
                               on_step,
                               &system,
                               umax > 0. ?
                                 dr_dt :
                                 Drivers::NewtonDriver::LoadDerivative());
                  }
                catch (...)
                  {
                    outcome             = driver.outcome();
                    timings["assembly"] = driver.timings().assembly;
                    timings["solve"]    = driver.timings().solve;
                    throw;
                  }
                outcome             = driver.outcome();
                timings["assembly"] = driver.timings().assembly;
                timings["solve"]    = driver.timings().solve;
              }
            else
              {
                Drivers::StaticDriver driver(setup.driver);
                driver.run(system, u, on_step);
                timings["assembly"]      = driver.timings().assembly;
                timings["solve"]         = driver.timings().solve;
                outcome.last_stable_load = 1.;
              }
          }
        catch (const RunFailure &e)
          {
            exit_state = e.exit_state;
            message    = e.what();
            std::cerr << "pdfem: run stopped: " << message << std::endl;
          }

        // ---- results: the last converged state
        start = clock::now();
        {
          TrilinosWrappers::MPI::Vector v, r;
          system.initialize_vector(v);
          for (unsigned int d = 0; d < n_dofs; ++d)
            v[d] = last_u[d];
          v.compress(VectorOperation::insert);
          system.residual(v, last_load, r, false);
        }
        const auto R = reactions();
        if (setup.write_vtu)
          write_rnp_vtu<dim>(setup.out_dir,
                             tria,
                             node_of,
                             last_u,
                             system.damage_history(),
                             pd_node,
                             last_load);
        if (setup.write_nodes_csv)
          {
            std::ofstream out(setup.out_dir + "/nodes.csv");
            out << std::setprecision(12);
            const auto names = component_names<dim>();
            for (const auto &c : names)
              out << c << ",";
            for (const auto &c : names)
              out << "u_" << c << ",";
            out << "damage\n";
            for (unsigned int i = 0; i < x.size(); ++i)
              {
                for (unsigned int c = 0; c < dim; ++c)
                  out << x[i][c] << ",";
                for (unsigned int c = 0; c < dim; ++c)
                  out << last_u[dim * i + c] << ",";
                out << system.damage_history()[i] << "\n";
              }
          }
        timings["output"] = seconds_since(start);
        timings["total"]  = seconds_since(setup.total_start);
        struct rusage usage;
        getrusage(RUSAGE_SELF, &usage);

        std::ofstream  out(setup.out_dir + "/summary.json");
        IO::JsonWriter json(out);
        json.begin_object();
        {
          // the problem sizes every driver writes (scene_internal.h); the
          // RNP-only ones go to "rnp"
          Coupling::ProblemSize size;
          size.n_nodes    = x.size();
          size.n_pd_nodes = std::count(pd_node.begin(), pd_node.end(), 1);
          std::vector<std::uint8_t> in_fe(x.size(), 0);
          for (const auto &dofs : elements.dofs)
            for (const unsigned int d : dofs)
              in_fe[d / dim] = 1;
          for (unsigned int i = 0; i < x.size(); ++i)
            size.n_interface_nodes += pd_node[i] && in_fe[i];
          size.n_cells    = tria.n_active_cells();
          size.n_pd_cells = tria.n_active_cells() - elements.dofs.size();
          size.n_dofs     = n_dofs;
          size.n_bonds    = system.n_bonds();
          size.n_matrix_entries =
            system.matrix().size() * (system.matrix().bandwidth() + 1);
          Coupling::ProblemSize final_size = size;
          final_size.n_decoupled_nodes     = system.n_decoupled_nodes();
          write_summary_header(
            json, setup, comm, exit_state, message, size, final_size);
        }
        json.begin_object("rnp");
        json.value("fe_cells",
                   static_cast<unsigned long>(elements.dofs.size()));
        json.value("cut_bonds",
                   static_cast<unsigned long>(system.n_cut_bonds()));
        json.value("bandwidth",
                   static_cast<unsigned long>(system.matrix().bandwidth()));
        json.value("C", model.C);
        json.value("beta", model.beta);
        json.value("horizon", model.horizon);
        json.value("spacing", h);
        json.value("r_c", 1. / std::sqrt(2. * model.beta));
        json.end_object();
        if (patch.modes > 0)
          {
            json.begin_object("patch_test");
            json.value("strain_modes", static_cast<unsigned long>(patch.modes));
            json.value("held_nodes",
                       static_cast<unsigned long>(patch.held_nodes));
            json.value("max_relative_error", patch.error);
            json.value("max_relative_ghost_force", patch.ghost_force);
            json.end_object();
          }
        json.value("steps", static_cast<unsigned long>(n_steps));
        json.begin_object("stability");
        json.value("last_stable_load_factor", outcome.last_stable_load);
        json.value("failure_load_factor", outcome.failure_load);
        json.value("peak_load_factor", peak_load);
        json.value("step_cuts", static_cast<unsigned long>(outcome.n_cuts));
        json.value("unstable_states",
                   static_cast<unsigned long>(outcome.n_unstable_states));
        json.value("snap_backs",
                   static_cast<unsigned long>(outcome.n_snap_backs));
        json.value("path_states",
                   static_cast<unsigned long>(outcome.n_path_states));
        json.value("negative_eigenvalues",
                   static_cast<unsigned long>(outcome.last_check.n_negative));
        json.value("smallest_relative_pivot",
                   outcome.last_check.smallest_relative_pivot);
        json.end_object();

        json.begin_object("final");
        json.value("load_factor", last_load);
        const auto comps = component_names<dim>();
        for (const bool take_max : {true, false})
          {
            json.begin_object(take_max ? "max_displacement" :
                                         "min_displacement");
            for (unsigned int c = 0; c < dim; ++c)
              {
                double m = take_max ? -std::numeric_limits<double>::infinity() :
                                      std::numeric_limits<double>::infinity();
                for (unsigned int i = 0; i < x.size(); ++i)
                  m = take_max ? std::max(m, last_u[dim * i + c]) :
                                 std::min(m, last_u[dim * i + c]);
                json.value(comps[c], m);
              }
            json.end_object();
          }
        const auto  &d = system.damage_history();
        unsigned int n_soft;
        double       soft_x;
        softened(n_soft, soft_x);
        json.value("max_damage", *std::max_element(d.begin(), d.end()));
        json.value("softened_nodes", static_cast<unsigned long>(n_soft));
        json.value("softened_x_max", soft_x);
        {
          const auto tips = crack_tips();
          for (unsigned int k = 0; k < tips.size(); ++k)
            {
              json.begin_object("tip" + std::to_string(k + 1));
              for (unsigned int c = 0; c < dim; ++c)
                json.value(comps[c], tips[k].first[c]);
              json.value("advance", tips[k].second);
              json.end_object();
            }
        }
        json.begin_object("reaction");
        for (std::size_t s = 0; s < set_names.size(); ++s)
          {
            json.begin_object(set_names[s]);
            for (unsigned int c = 0; c < dim; ++c)
              json.value(comps[c], R[s][c]);
            json.end_object();
          }
        json.end_object();
        json.end_object();
        json.begin_object("timings");
        for (const char *phase :
             {"mesh", "setup", "assembly", "solve", "output", "total"})
          json.value(phase, timings[phase]);
        json.end_object();
        json.value("peak_memory_mb_rank0", usage.ru_maxrss / 1024.);
        json.end_object();

        if (progress)
          *progress << "Exit state: " << exit_state << ". Results in "
                    << setup.out_dir << "/" << std::endl;
        return exit_state == "completed" ? ExitCode::completed :
                                           ExitCode::run_failure;
      }

#define INSTANTIATE(dim)                                   \
  template int execute_rnp<dim>(Setup<dim> &,              \
                                const Parameters::Scene &, \
                                const RunOptions &,        \
                                MPI_Comm);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
