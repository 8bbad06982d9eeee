// SPDX-License-Identifier: LGPL-2.1-or-later
// Private to the scene module: the RNP model of a scene (rnp_model.cc), which
// rnp_scene.cc turns into a system, runs and writes out.
#ifndef PDFEM_SOURCE_SCENE_RNP_MODEL_H
#define PDFEM_SOURCE_SCENE_RNP_MODEL_H

#include <pdfem/coupling/rnp_system.h>
#include <pdfem/io/parameters.h>
#include <pdfem/pd_models/rnp.h>

#include <deal.II/base/point.h>

#include <cstdint>
#include <string>
#include <vector>

#include "scene_internal.h"

namespace pdfem
{
  namespace Scene
  {
    namespace internal
    {
      /**
       * What a scene with Peridynamics/Model = rnp is made of (specs/000):
       * every used vertex of the mesh is a node; the PD cells give the RNP
       * region and the FE cells Q1 stiffness matrices on the same nodes.
       */
      template <int dim>
      struct RNPModel
      {
        /// C and beta (given or calibrated), the horizon, the influence.
        PDModels::RNPSettings settings;
        /// Triangulation vertex -> node (-1: unused vertex).
        std::vector<int>                node_of;
        std::vector<dealii::Point<dim>> x;
        /// Nodal volumes (PD cells' shares; every cell's with fe_members).
        std::vector<double>       volume;
        std::vector<std::uint8_t> pd_node;
        /// The spacing h: the largest size of a PD cell.
        double spacing = 0.;
        /// Peridynamics/FE nodes in families.
        bool fe_members = false;
        /// The PD share of each node's volume (empty: not partitioned).
        std::vector<double>                               energy_weight;
        typename Coupling::RNPSystem<dim>::LinearElements elements;
        /// Dirichlet layers, tractions and body force.
        typename Coupling::RNPSystem<dim>::Loads loads;
        /// The Dirichlet sets by name and their nodes (for the reactions).
        std::vector<std::string>               set_names;
        std::vector<std::vector<unsigned int>> set_nodes;

        unsigned int
        n_dofs() const
        {
          return dim * x.size();
        }
      };

      /// The patch test of the RNP-FE coupling (no modes: no FE cells).
      struct RNPPatchTest
      {
        unsigned int modes = 0, held_nodes = 0;
        double       error = 0., ghost_force = 0.;
      };

      /**
       * Check the input of an RNP scene (one rank, quadrilateral or
       * hexahedral FE cells, C and beta or the calibration from E, nu and
       * G_c) before any work, then build its model.
       */
      template <int dim>
      RNPModel<dim>
      make_rnp_model(const Setup<dim>        &setup,
                     const Parameters::Scene &prm,
                     MPI_Comm                 comm);

      /**
       * Patch test of the RNP-FE coupling (runs with FE cells): for each
       * unit strain mode eps, u = eps (x - x_c) prescribed on the boundary
       * (FE nodes on it, PD nodes within a horizon of it, so that the PD
       * surface effect is not counted), the rest solved in the linear
       * regime, without pre-cracks. An exact coupling reproduces the affine
       * field; the error is the ghost forces' doing (theory.md §8.3).
       */
      template <int dim>
      RNPPatchTest
      rnp_patch_test(const Setup<dim> &setup, const RNPModel<dim> &model);
    } // namespace internal
  }   // namespace Scene
} // namespace pdfem

#endif
