// SPDX-License-Identifier: LGPL-2.1-or-later
// The set-up of a scene with Peridynamics/Model = rnp (specs/000): the input
// checks and the constants C and beta, the nodes and their volumes, the FE
// cells' stiffness matrices, the loads, and the patch test of the coupling.
#include "rnp_model.h"

#include <pdfem/base/config.h>
#include <pdfem/base/exceptions.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <memory>

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      using namespace dealii;

      namespace
      {
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

        /// The input checks (before any work), then C and beta: given, or
        /// calibrated from E, nu and G_c.
        template <int dim>
        PDModels::RNPSettings
        rnp_settings(const Setup<dim>        &setup,
                     const Parameters::Scene &prm,
                     MPI_Comm                 comm)
        {
          const auto &tria = *setup.tria;
          const auto &rp   = prm.rnp;
          const bool  plane_strain =
            dim == 2 &&
            prm.material.plane == Parameters::PlaneModel::plane_strain;

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
                    (dim == 2 ? (plane_strain ? " in plane strain" :
                                                " in plane stress") :
                                " in 3D"),
                  number(nu) +
                    " (or Peridynamics/RNP/Calibration = constants)");
              if (!(rp.fracture_energy > 0.))
                throw InputError(prm.file,
                                 "Peridynamics/RNP/Fracture energy",
                                 "G_c = " + number(rp.fracture_energy) +
                                   " is not positive",
                                 "G_c > 0 with Calibration = moduli");
              const double c_beta =
                PDModels::rnp_c_beta(prm.material.youngs_modulus,
                                     model.influence,
                                     dim,
                                     plane_strain);
              model.C = PDModels::rnp_c_from_fracture_energy(rp.fracture_energy,
                                                             model.influence,
                                                             dim);
              model.beta = c_beta / model.C;
            }
          return model;
        }

        /// The nodes (the used vertices), their volumes, which are PD, the
        /// spacing and the energy partition.
        template <int dim>
        void
        set_up_nodes(const Setup<dim>        &setup,
                     const Parameters::Scene &prm,
                     RNPModel<dim>           &m)
        {
          const auto             &tria     = *setup.tria;
          const auto             &rp       = prm.rnp;
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
          const bool fe_members = prm.peridynamics.fe_nodes_in_families;
          std::vector<double>       volume(x.size(), 0.);
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
          m.node_of       = std::move(node_of);
          m.x             = std::move(x);
          m.volume        = std::move(volume);
          m.pd_node       = std::move(pd_node);
          m.spacing       = h;
          m.fe_members    = fe_members;
          m.energy_weight = std::move(energy_weight);
        }

        /// The FE cells: Q1 stiffness matrices on the shared nodes.
        template <int dim>
        typename Coupling::RNPSystem<dim>::LinearElements
        fe_cells(const Setup<dim> &setup, const std::vector<int> &node_of)
        {
          const auto &tria     = *setup.tria;
          const auto &settings = setup.settings;
          typename Coupling::RNPSystem<dim>::LinearElements elements;
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
          return elements;
        }

        /// The loads: Dirichlet layers, tractions, body force.
        template <int dim>
        void
        set_up_loads(const Setup<dim>        &setup,
                     const Parameters::Scene &prm,
                     RNPModel<dim>           &m)
        {
          const auto                              &tria     = *setup.tria;
          const auto                              &settings = setup.settings;
          const auto                              &rp       = prm.rnp;
          const auto                              &model    = m.settings;
          const auto                              &node_of  = m.node_of;
          const auto                              &x        = m.x;
          const auto                              &volume   = m.volume;
          const auto                              &pd_node  = m.pd_node;
          const double                             h        = m.spacing;
          const unsigned int                       n_dofs   = dim * x.size();
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
                    if (face->at_boundary() &&
                        std::count(bc.boundary_ids.begin(),
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
          loads.prescribed =
            [prescribed, functions, x](double t, std::vector<double> &u) {
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
                      const auto n = outward_normal<dim>(face, cell->center());
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
          m.loads     = std::move(loads);
          m.set_names = std::move(set_names);
          m.set_nodes = std::move(set_nodes);
        }
      } // namespace



      template <int dim>
      RNPModel<dim>
      make_rnp_model(const Setup<dim>        &setup,
                     const Parameters::Scene &prm,
                     MPI_Comm                 comm)
      {
        RNPModel<dim> m;
        m.settings = rnp_settings(setup, prm, comm);
        set_up_nodes(setup, prm, m);
        m.elements         = fe_cells(setup, m.node_of);
        m.settings.horizon = prm.peridynamics.horizon_factor * m.spacing;
        set_up_loads(setup, prm, m);
        return m;
      }



      template <int dim>
      RNPPatchTest
      rnp_patch_test(const Setup<dim> &setup, const RNPModel<dim> &m)
      {
        const auto        &tria          = *setup.tria;
        const auto        &settings      = setup.settings;
        const auto        &model         = m.settings;
        const auto        &x             = m.x;
        const auto        &pd_node       = m.pd_node;
        const double       h             = m.spacing;
        const unsigned int n_dofs        = m.n_dofs();
        const auto        &volume        = m.volume;
        const auto        &elements      = m.elements;
        const auto        &fe_members    = m.fe_members;
        const auto        &energy_weight = m.energy_weight;
        RNPPatchTest       patch;
        if (m.elements.dofs.empty())
          return patch;
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
        const double r2 = model.horizon * model.horizon * (1. + 1e-10) + r2_fe;
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
        auto strain            = std::make_shared<Tensor<2, dim>>();
        patch_loads.prescribed = [strain, x, centre](double,
                                                     std::vector<double> &u) {
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
        Coupling::RNPSystem<dim> patch_system(x,
                                              volume,
                                              model,
                                              {},
                                              patch_loads,
                                              Coupling::RNPTangent::analytic,
                                              pd_node,
                                              elements,
                                              fe_members,
                                              energy_weight);
        const double             lambda = settings.material.lambda();
        const double             mu     = settings.material.mu();
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
                    e += (pu[dim * i + c] - v[c]) * (pu[dim * i + c] - v[c]);
                  patch.error = std::max(patch.error, std::sqrt(e) / u_max);
                }
              ++patch.modes;
            }
        return patch;
      }

#define INSTANTIATE(dim)                                                \
  template RNPModel<dim> make_rnp_model<dim>(const Setup<dim> &,        \
                                             const Parameters::Scene &, \
                                             MPI_Comm);                 \
  template RNPPatchTest  rnp_patch_test<dim>(const Setup<dim> &,        \
                                            const RNPModel<dim> &);
      PDFEM_INSTANTIATE(INSTANTIATE)
#undef INSTANTIATE
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem
