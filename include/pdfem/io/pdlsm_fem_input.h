// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef PDFEM_IO_PDLSM_FEM_INPUT_H
#define PDFEM_IO_PDLSM_FEM_INPUT_H

#include <array>
#include <map>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace pdfem
{
  namespace IO
  {
    /**
     * Everything a PDLSM-FEM command file and its .lis mesh file say
     * (specs/004 §4.1 command file, §4.2 mesh file, §1.4 element kinds, §2.5
     * boundary conditions, §3 failure criteria). The model does not depend on
     * deal.II (create_triangulation() makes its cells): the numbering is the
     * file's, made 0-based.
     *
     * After read_pdlsm_fem() the command-file overrides (EBC, VEBC, NBC, VNBC)
     * have already been applied to #essential and #natural (see
     * apply_pdlsm_fem_overrides()); the maps keep what the command file said.
     */
    struct PDLSMFEMModel
    {
      // ----------------------------------------------------------------
      // command file
      /// The command file, as given to read_pdlsm_fem().
      std::string command_file;
      /// MSHFILE, resolved relative to the folder of the command file.
      std::string mesh_file;

      /// SOLVER STATIC | QUASI-STATIC | DYNAMIC (specs/004 §2).
      enum class Solver
      {
        static_solver,
        quasi_static,
        dynamic
      } solver = Solver::static_solver;
      /// SOLVER is required: read_pdlsm_fem() throws if it is missing.
      bool solver_given = false;

      /// SETSOLVING dt Nsteps writeFreq m a [m_e], stored as written (the
      /// peer forces dt = 1 in QUASI-STATIC runs; that is the solver's job).
      double       dt              = 1.;
      unsigned int n_steps         = 1;
      unsigned int write_frequency = 1;
      /// m: horizon = m * (characteristic element length).
      double horizon_factor = 3.;
      /// a: the non-local factor of the influence function.
      double weight_factor = 0.33;
      /// m_e: adaptive PD region radius factor (0 = off; undocumented).
      double adaptive_factor = 0.;
      /// SETSOLVING was given.
      bool setsolving_given = false;

      /// NEWMARK ON [gamma beta] | OFF (gamma and beta only if both given).
      bool   newmark       = false;
      double newmark_gamma = 0.5;
      double newmark_beta  = 0.25;
      /// LUMPMASS ON | OFF.
      bool lumped_mass = false;

      /// EBC / VEBC / NBC / VNBC id value, as the command file says (ids
      /// 0-based, checked against the mesh-file sets).
      std::map<unsigned int, double> ebc_value, ebc_rate, nbc_value, nbc_rate;

      /// FC 0 | FC 1 [m_r d_cf] | FC 2 [TopK]; TOPK k (specs/004 §3).
      int          failure_criterion  = 0;
      double       fc1_contour_factor = 6.;
      double       fc1_growth_factor  = 1.;
      unsigned int top_k              = 0;

      /// RF id ...: essential sets whose reaction force is summed.
      std::vector<unsigned int> reaction_sets;
      /// VTKFORMAT ASCII | BINARY (default BINARY).
      bool vtk_ascii = false;
      /// FENSF ON | OFF (default ON; no effect in the peer).
      bool fe_nodes_in_families = true;

      // ---------------------------------------------------------------- mesh
      // file
      /// First token of line 1: the peer's output-file prefix.
      std::string title;
      /// Line 2, as written (free text).
      std::string label;
      /// 2 or 3 (the `2D`/`3D` token of line 3).
      int dim = 2;
      /// 1 plane stress, 2 plane strain; in 3D any value (examples: -1).
      int problem_type = 1;
      /// Line 4: E, nu, rho, K_Ic, sigma_ult.
      double youngs_modulus = 0, poissons_ratio = 0, density = 0,
             fracture_toughness = 0, tensile_strength = 0;

      /// Node coordinates; index = node id - 1 (z = 0 in 2D as in the file).
      std::vector<std::array<double, 3>> nodes;

      /// One element of the file.
      struct Element
      {
        /// 1 = PD, 2 = FE.
        unsigned int type = 0;
        /**
         * 0-based node indices, distinct, in the order of the file with the
         * degenerate repeats removed: quadrilateral 4 (I J K L), triangle 3
         * (I J K K -> I J K), hexahedron 8 (I..P), tetrahedron 4
         * (I J K K L L L L -> I J K L). The order is the peer's, not
         * deal.II's.
         */
        std::vector<unsigned int> vertices;
      };
      /// Elements; index = element id - 1.
      std::vector<Element> elements;

      /// An essential BC set of the mesh file (its id is its index).
      struct EssentialSet
      {
        /// UX, UY, UZ -> 0, 1, 2.
        unsigned int component = 0;
        /// Initial value (mesh file, or EBC override).
        double value = 0.;
        /// Change per time or load step (VEBC; 0 if not given).
        double rate = 0.;
        /// 0-based node indices, in the order of the file.
        std::vector<unsigned int> nodes;
      };
      std::vector<EssentialSet> essential;

      /// A natural BC set of the mesh file (its id is its index).
      struct NaturalSet
      {
        /// Normal traction (mesh file, or NBC override).
        double traction = 0.;
        /// Change per time or load step (VNBC; 0 if not given).
        double rate = 0.;
        /// Faces, 0-based node indices: 2 per edge in 2D; 4 (or 3 for a
        /// triangle written p q r r) per face in 3D, in the order of the file.
        std::vector<std::vector<unsigned int>> faces;
      };
      std::vector<NaturalSet> natural;

      /// NO FAIL region: 0-based node indices, as listed (parsed but unused by
      /// the peer, specs/004 §3).
      std::vector<unsigned int> no_fail_nodes;

      /// Pre-existing cracks: 2 points in 2D (the second is the tip), 3 in 3D
      /// (a triangle).
      std::vector<std::vector<std::array<double, 3>>> cracks;
    };

    /**
     * Read a PDLSM-FEM command file and the mesh file its MSHFILE names
     * (specs/004 §4.1, §4.2), check them, and apply the overrides with
     * apply_pdlsm_fem_overrides().
     *
     * Command file: one command per line, whitespace-separated tokens; empty
     * lines and lines whose first token starts with `#` are skipped, and a
     * token starting with `#` ends a command (trailing comment). MSHFILE must
     * be the first command; SOLVER is required. Unlike the peer (which warns),
     * an unknown keyword is an error. As in the peer, `FC 1` reads m_r and d_cf
     * and `NEWMARK ON` reads gamma and beta only if both values are present,
     * and tokens beyond what a command reads are ignored.
     *
     * @throws pdfem::InputError naming the file and the line, e.g.
     * "mesh.lis: line 12: expected 4 node ids for element 7, found 3".
     */
    PDLSMFEMModel
    read_pdlsm_fem(const std::string &command_file);

    /**
     * Read only a .lis mesh file (specs/004 §4.2) into the mesh part of a
     * model (the command-file part keeps its defaults; no overrides).
     *
     * Layout: line 1 title, line 2 free text, then `2D|3D problem_type`, the
     * five material constants, `Ng Eg`, Ng node lines `id x y z`, Eg element
     * lines `id type n1..n4` (2D) or `id type n1..n8` (3D); then four sections
     * (essential BCs, natural BCs, NO FAIL region, pre-existing cracks), each
     * preceded by exactly one separator line whose text is not checked.
     * Node, element, set-header, face and crack records are one per line;
     * the node ids of essential sets and of the NO FAIL region are free
     * format. Ids are 1-based and node and element ids must be consecutive.
     *
     * @throws pdfem::InputError naming the file and the line.
     */
    PDLSMFEMModel
    read_pdlsm_fem_mesh(const std::string &mesh_file);

    /**
     * Apply the command-file overrides of @p model to its mesh-file sets:
     * ebc_value / ebc_rate set EssentialSet::value / rate, nbc_value /
     * nbc_rate set NaturalSet::traction / rate (specs/004 §2.5). Called by
     * read_pdlsm_fem(); calling it again changes nothing.
     *
     * @throws pdfem::InputError if an id does not name a set of the mesh file.
     */
    void
    apply_pdlsm_fem_overrides(PDLSMFEMModel &model);

    /**
     * The cells of @p model's mesh in @p tria (empty, of the model's
     * dimension): vertex k is node k, the material id is the element type
     * (1 PD, 2 FE). Quadrilaterals and hexahedra are taken from the peer's
     * counter-clockwise order to deal.II's lexicographic one, inverted cells
     * turned and all cells oriented consistently; then the shapes are
     * checked (Mesh::check_cell_shapes()).
     *
     * @throws pdfem::InputError naming the mesh file if deal.II cannot build
     * a mesh from the elements (non-conforming, not orientable) or a cell
     * is degenerate or tangled.
     */
    template <int dim>
    void
    create_triangulation(const PDLSMFEMModel             &model,
                         dealii::Triangulation<dim, dim> &tria);
  } // namespace IO
} // namespace pdfem

#endif
