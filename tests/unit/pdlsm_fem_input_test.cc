// SPDX-License-Identifier: LGPL-2.1-or-later
// Reader of PDLSM-FEM command and mesh files (specs/004 §4): hand-written
// files, malformed variants (file name and line number in the message) and,
// when present, the peer's own example inputs.
#include <pdfem/base/exceptions.h>
#include <pdfem/io/pdlsm_fem_input.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include <gtest/gtest.h>

#ifndef PDFEM_SOURCE_DIR
#  error "PDFEM_SOURCE_DIR must be defined (tests/CMakeLists.txt)"
#endif

using pdfem::IO::PDLSMFEMModel;
using pdfem::IO::read_pdlsm_fem;
using pdfem::IO::read_pdlsm_fem_mesh;
using Solver = PDLSMFEMModel::Solver;
using P      = std::array<double, 3>;
using T      = std::array<unsigned int, 3>;

namespace
{
  const std::string data_dir =
    std::string(PDFEM_SOURCE_DIR) + "/tests/data/pdlsm_fem/";

  /// The message of the InputError that @p f throws, or "(no error)".
  std::string
  error_of(const std::function<void()> &f)
  {
    try
      {
        f();
      }
    catch (const pdfem::InputError &e)
      {
        return e.what();
      }
    return "(no error)";
  }

  /// Reading @p file (command file if it ends in .in, else a mesh file)
  /// fails on line @p line of @p file_in_message with a message containing
  /// @p fragment.
  void
  expect_error(const std::string &file,
               const std::string &file_in_message,
               const unsigned int line,
               const std::string &fragment)
  {
    const std::string path = data_dir + file;
    const bool        is_command =
      file.size() > 3 && file.compare(file.size() - 3, 3, ".in") == 0;
    const std::string message = error_of([&] {
      if (is_command)
        read_pdlsm_fem(path);
      else
        read_pdlsm_fem_mesh(path);
    });
    const std::string where =
      file_in_message + ": line " + std::to_string(line) + ": ";
    EXPECT_NE(message.find(where), std::string::npos)
      << "expected '" << where << "' in: " << message;
    EXPECT_NE(message.find(fragment), std::string::npos)
      << "expected '" << fragment << "' in: " << message;
  }

  void
  expect_error(const std::string &file,
               const unsigned int line,
               const std::string &fragment)
  {
    expect_error(file, file, line, fragment);
  }

  std::vector<unsigned int>
  ids(std::initializer_list<unsigned int> one_based)
  {
    std::vector<unsigned int> v;
    for (const unsigned int i : one_based)
      v.push_back(i - 1);
    return v;
  }

  std::string
  slurp(const std::string &file)
  {
    std::ifstream     in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace

// ---------------------------------------------------------------- good files

TEST(PDLSMFEMInput, Plate2DMeshAndCommands)
{
  const PDLSMFEMModel m = read_pdlsm_fem(data_dir + "plate2d.in");

  // command file
  EXPECT_EQ(m.command_file, data_dir + "plate2d.in");
  EXPECT_EQ(std::filesystem::path(m.mesh_file),
            std::filesystem::path(data_dir) / "plate2d.lis");
  EXPECT_TRUE(m.solver_given);
  EXPECT_EQ(m.solver, Solver::quasi_static);
  EXPECT_DOUBLE_EQ(m.dt, 1.);
  EXPECT_EQ(m.n_steps, 20u);
  EXPECT_EQ(m.write_frequency, 5u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 3.5);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.25);
  EXPECT_DOUBLE_EQ(m.adaptive_factor, 1.5);
  EXPECT_TRUE(m.newmark);
  EXPECT_DOUBLE_EQ(m.newmark_gamma, 0.6);
  EXPECT_DOUBLE_EQ(m.newmark_beta, 0.3);
  EXPECT_TRUE(m.lumped_mass);
  EXPECT_EQ(m.failure_criterion, 1);
  EXPECT_DOUBLE_EQ(m.fc1_contour_factor, 4.);
  EXPECT_DOUBLE_EQ(m.fc1_growth_factor, 0.5);
  EXPECT_EQ(m.top_k, 3u);
  EXPECT_EQ(m.reaction_sets, (std::vector<unsigned int>{0, 1}));
  EXPECT_TRUE(m.vtk_ascii);
  EXPECT_FALSE(m.fe_nodes_in_families);
  EXPECT_EQ(m.ebc_value, (std::map<unsigned int, double>{{1, 2e-3}}));
  EXPECT_EQ(m.ebc_rate, (std::map<unsigned int, double>{{1, 1e-4}}));
  EXPECT_EQ(m.nbc_value, (std::map<unsigned int, double>{{0, 1e6}}));
  EXPECT_EQ(m.nbc_rate, (std::map<unsigned int, double>{{0, 2e5}}));

  // mesh file header
  EXPECT_EQ(m.title, "plate2d");
  EXPECT_EQ(m.label,
            "***a 3x2-quad plate: one FE row below, one PD row above***");
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.problem_type, 1);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 7e10);
  EXPECT_DOUBLE_EQ(m.poissons_ratio, 0.33);
  EXPECT_DOUBLE_EQ(m.density, 2700.);
  EXPECT_DOUBLE_EQ(m.fracture_toughness, 2.2e7);
  EXPECT_DOUBLE_EQ(m.tensile_strength, 1.2e8);

  // nodes and elements
  ASSERT_EQ(m.nodes.size(), 12u);
  EXPECT_EQ(m.nodes[0], (P{{0., 0., 0.}}));
  EXPECT_EQ(m.nodes[3], (P{{3., 0., 0.}}));
  EXPECT_EQ(m.nodes[9], (P{{1., 2., 0.}})); // "+2.0"
  EXPECT_EQ(m.nodes[11], (P{{3., 2., 0.}}));
  ASSERT_EQ(m.elements.size(), 6u);
  for (unsigned int e = 0; e < 6; ++e)
    EXPECT_EQ(m.elements[e].type, e < 3 ? 2u : 1u) << "element " << e + 1;
  EXPECT_EQ(m.elements[0].vertices, ids({1, 2, 6, 5}));
  EXPECT_EQ(m.elements[5].vertices, ids({7, 8, 12, 11}));

  // essential sets, with EBC 1 and VEBC 1 applied
  ASSERT_EQ(m.essential.size(), 3u);
  EXPECT_EQ(m.essential[0].component, 0u);
  EXPECT_EQ(m.essential[0].nodes, ids({1, 5, 9}));
  EXPECT_DOUBLE_EQ(m.essential[0].value, 0.);
  EXPECT_DOUBLE_EQ(m.essential[0].rate, 0.);
  EXPECT_EQ(m.essential[1].component, 0u);
  EXPECT_EQ(m.essential[1].nodes, ids({4, 8, 12}));
  EXPECT_DOUBLE_EQ(m.essential[1].value, 2e-3); // file: 1e-3
  EXPECT_DOUBLE_EQ(m.essential[1].rate, 1e-4);
  EXPECT_EQ(m.essential[2].component, 1u);
  EXPECT_EQ(m.essential[2].nodes, ids({1}));

  // natural set, with NBC 0 and VNBC 0 applied
  ASSERT_EQ(m.natural.size(), 1u);
  EXPECT_DOUBLE_EQ(m.natural[0].traction, 1e6); // file: -5e6
  EXPECT_DOUBLE_EQ(m.natural[0].rate, 2e5);
  ASSERT_EQ(m.natural[0].faces.size(), 2u);
  EXPECT_EQ(m.natural[0].faces[0], ids({10, 9}));
  EXPECT_EQ(m.natural[0].faces[1], ids({11, 10}));

  EXPECT_EQ(m.no_fail_nodes, ids({4, 8}));
  ASSERT_EQ(m.cracks.size(), 1u);
  ASSERT_EQ(m.cracks[0].size(), 2u);
  EXPECT_EQ(m.cracks[0][0], (P{{1.5, 2., 0.}}));
  EXPECT_EQ(m.cracks[0][1], (P{{1.5, 1.5, 0.}})); // tip
}

TEST(PDLSMFEMInput, Mixed2DQuadAndTriangles)
{
  const PDLSMFEMModel m = read_pdlsm_fem(data_dir + "mixed2d.in");
  EXPECT_EQ(m.solver, Solver::dynamic);
  EXPECT_DOUBLE_EQ(m.dt, 5e-7);
  EXPECT_EQ(m.n_steps, 100u);
  EXPECT_EQ(m.write_frequency, 10u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 3.);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.33);
  EXPECT_DOUBLE_EQ(m.adaptive_factor, 0.);
  EXPECT_EQ(m.failure_criterion, 2);
  EXPECT_EQ(m.top_k, 7u);
  EXPECT_FALSE(m.vtk_ascii);
  EXPECT_FALSE(m.newmark);

  EXPECT_EQ(m.problem_type, 2);
  ASSERT_EQ(m.nodes.size(), 6u); // a blank line among the nodes is skipped
  EXPECT_EQ(m.nodes[4], (P{{2., 0., 0.}}));
  ASSERT_EQ(m.elements.size(), 3u);
  EXPECT_EQ(m.elements[0].type, 2u);
  EXPECT_EQ(m.elements[0].vertices, ids({1, 2, 3, 4}));
  EXPECT_EQ(m.elements[1].type, 1u);
  EXPECT_EQ(m.elements[1].vertices, ids({2, 5, 6})); // 2 5 6 6
  EXPECT_EQ(m.elements[2].vertices, ids({2, 6, 3})); // 2 6 3 3
  ASSERT_EQ(m.essential.size(), 2u);
  EXPECT_EQ(m.essential[0].component, 1u);
  EXPECT_EQ(m.essential[0].nodes, ids({1, 2}));
  EXPECT_EQ(m.essential[1].component, 0u);
  EXPECT_DOUBLE_EQ(m.essential[1].value, -2.5e-4);
  ASSERT_EQ(m.natural.size(), 1u);
  EXPECT_DOUBLE_EQ(m.natural[0].traction, 3e6); // NBC 0 3e6
  EXPECT_EQ(m.natural[0].faces,
            (std::vector<std::vector<unsigned int>>{ids({5, 6})}));
  EXPECT_TRUE(m.no_fail_nodes.empty());
  EXPECT_TRUE(m.cracks.empty());
}

TEST(PDLSMFEMInput, Box3DHexesAndTet)
{
  const PDLSMFEMModel m = read_pdlsm_fem(data_dir + "box3d.in");
  EXPECT_EQ(m.solver, Solver::dynamic);
  // "NEWMARK ON 0.6" and "FC 1 5": a lone value is ignored, as by the peer
  EXPECT_TRUE(m.newmark);
  EXPECT_DOUBLE_EQ(m.newmark_gamma, 0.5);
  EXPECT_DOUBLE_EQ(m.newmark_beta, 0.25);
  EXPECT_EQ(m.failure_criterion, 1);
  EXPECT_DOUBLE_EQ(m.fc1_contour_factor, 6.);
  EXPECT_DOUBLE_EQ(m.fc1_growth_factor, 1.);
  EXPECT_EQ(m.reaction_sets, (std::vector<unsigned int>{2}));

  EXPECT_EQ(m.title, "box3d");
  EXPECT_EQ(m.dim, 3);
  EXPECT_EQ(m.problem_type, -1);
  ASSERT_EQ(m.nodes.size(), 13u);
  EXPECT_EQ(m.nodes[12], (P{{0.3, 0.3, 1.8}}));
  ASSERT_EQ(m.elements.size(), 3u);
  EXPECT_EQ(m.elements[0].type, 1u);
  EXPECT_EQ(m.elements[0].vertices, ids({1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(m.elements[1].type, 2u);
  EXPECT_EQ(m.elements[1].vertices, ids({2, 9, 10, 3, 6, 11, 12, 7}));
  EXPECT_EQ(m.elements[2].type, 1u);
  EXPECT_EQ(m.elements[2].vertices, ids({5, 6, 8, 13})); // 5 6 8 8 13 13 13 13

  ASSERT_EQ(m.essential.size(), 3u);
  EXPECT_EQ(m.essential[0].component, 2u);
  EXPECT_EQ(m.essential[0].nodes, ids({1, 2, 3, 4, 9, 10}));
  EXPECT_EQ(m.essential[1].component, 0u);
  EXPECT_EQ(m.essential[1].nodes, ids({1, 4, 5, 8}));
  EXPECT_EQ(m.essential[2].component, 1u);
  EXPECT_DOUBLE_EQ(m.essential[2].value, -1e-4);
  ASSERT_EQ(m.natural.size(), 1u);
  EXPECT_DOUBLE_EQ(m.natural[0].traction, 7e6);
  ASSERT_EQ(m.natural[0].faces.size(), 2u);
  EXPECT_EQ(m.natural[0].faces[0], ids({9, 10, 12, 11}));
  EXPECT_EQ(m.natural[0].faces[1], ids({6, 7, 13})); // 6 7 13 13
  EXPECT_EQ(m.no_fail_nodes, ids({13, 5, 6}));
  ASSERT_EQ(m.cracks.size(), 1u);
  ASSERT_EQ(m.cracks[0].size(), 3u);
  EXPECT_EQ(m.cracks[0][2], (P{{0.5, 0.5, 1.5}}));
}

TEST(PDLSMFEMInput, Defaults)
{
  const PDLSMFEMModel m = read_pdlsm_fem(data_dir + "minimal.in");
  const PDLSMFEMModel d;
  EXPECT_EQ(m.solver, Solver::static_solver);
  EXPECT_EQ(m.dt, d.dt);
  EXPECT_EQ(m.n_steps, 1u);
  EXPECT_EQ(m.write_frequency, 1u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 3.);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.33);
  EXPECT_FALSE(m.setsolving_given);
  EXPECT_FALSE(m.newmark);
  EXPECT_FALSE(m.lumped_mass);
  EXPECT_EQ(m.failure_criterion, 0);
  EXPECT_EQ(m.top_k, 0u);
  EXPECT_TRUE(m.reaction_sets.empty());
  EXPECT_FALSE(m.vtk_ascii);
  EXPECT_TRUE(m.fe_nodes_in_families);
  EXPECT_TRUE(m.ebc_value.empty());
  EXPECT_DOUBLE_EQ(m.essential[2].value, -1e-4); // the mesh file's value
}

TEST(PDLSMFEMInput, CRLFLineEndings)
{
  // the same files written with CRLF line ends read the same, and the line
  // numbers in messages stay right
  const auto folder =
    std::filesystem::temp_directory_path() / "pdfem_pdlsm_fem_crlf";
  std::filesystem::create_directories(folder);
  for (const std::string name :
       {"plate2d.in", "plate2d.lis", "bad_element_nodes.lis"})
    {
      std::string crlf;
      for (const char c : slurp(data_dir + name))
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
      std::ofstream(folder / name, std::ios::binary) << crlf;
    }
  const PDLSMFEMModel a = read_pdlsm_fem((folder / "plate2d.in").string());
  const PDLSMFEMModel b = read_pdlsm_fem(data_dir + "plate2d.in");
  EXPECT_EQ(a.title, b.title);
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.essential[1].nodes, b.essential[1].nodes);
  EXPECT_EQ(a.no_fail_nodes, b.no_fail_nodes);
  EXPECT_EQ(a.cracks, b.cracks);
  EXPECT_EQ(a.fe_nodes_in_families, b.fe_nodes_in_families);
  const std::string message = error_of(
    [&] { read_pdlsm_fem_mesh((folder / "bad_element_nodes.lis").string()); });
  EXPECT_NE(message.find("bad_element_nodes.lis: line 21: expected 4 node ids "
                         "for element 4, found 3"),
            std::string::npos)
    << message;
  std::filesystem::remove_all(folder);
}

TEST(PDLSMFEMInput, OverridesOfMissingSets)
{
  PDLSMFEMModel m = read_pdlsm_fem(data_dir + "mixed2d.in");
  pdfem::IO::apply_pdlsm_fem_overrides(m); // again: no change
  EXPECT_DOUBLE_EQ(m.natural[0].traction, 3e6);
  m.nbc_rate[4] = 1.;
  const std::string message =
    error_of([&] { pdfem::IO::apply_pdlsm_fem_overrides(m); });
  EXPECT_NE(message.find("mixed2d.in: VNBC 4: "), std::string::npos) << message;
}

// ---------------------------------------------------------------- bad mesh
// files

TEST(PDLSMFEMInput, MalformedMeshFiles)
{
  expect_error("bad_truncated_nodes.lis",
               12,
               "unexpected end of file, expected node 8 of 12");
  expect_error("bad_truncated_ebc.lis",
               30,
               "unexpected end of file, expected node id 3 of 3 of essential "
               "set 1");
  expect_error("bad_element_nodes.lis",
               21,
               "expected 4 node ids for element 4, found 3");
  expect_error("bad_fewer_elements.lis",
               24,
               "expected element 7 of 7, found '===='");
  expect_error("bad_ebc_count.lis",
               32,
               "expected node id 2 of 2 of essential set 2, found '----'");
  expect_error("bad_dof.lis", 28, "unknown DOF 'UZ' for essential set 2 in 2D");
  expect_error("bad_dof.lis", 28, "(allowed: UX, UY)");
  expect_error("bad_node_range.lis",
               19,
               "node 13 of element 2 does not exist (allowed: node ids 1..12)");
  expect_error("bad_node_zero.lis",
               29,
               "node 0 in essential set 0 does not exist");
  expect_error(
    "bad_dof_twice.lis",
    31,
    "DOF UX of node 5 is constrained twice, by essential sets 0 and 1");
  expect_error("bad_dof_twice_in_set.lis",
               29,
               "DOF UX of node 1 is listed twice in essential set 0");
  expect_error("bad_number.lis",
               4,
               "expected tensile strength, found '1.2e+O8'");
  expect_error("bad_type.lis", 20, "element type 3 of element 3 is unknown");
  expect_error("bad_dim.lis", 3, "found '2d' (allowed: 2D, 3D)");
  expect_error("bad_problem_type.lis",
               3,
               "problem type 3 is not a 2D problem type");
  expect_error("bad_crack.lis",
               42,
               "expected 2 points (6 coordinates) for crack 1 of 1 in 2D, "
               "found 9");
  expect_error("bad_degenerate.lis",
               22,
               "element 5: node ids 6 6 11 10 are neither a quadrilateral nor "
               "a triangle");
  expect_error("bad_node_ids.lis",
               10,
               "expected node id 5, found '6' (node ids must be consecutive "
               "from 1)");
  expect_error("bad_face.lis",
               35,
               "expected 2 node ids for face 1 of 2 of natural set 0, found 3");
  expect_error("bad_extra_crack.lis",
               43,
               "unexpected '0' after the 1 announced pre-existing cracks");
  expect_error("bad_tet.lis",
               21,
               "element 3: node ids 5 6 6 6 13 13 13 13 are neither a "
               "hexahedron nor a tetrahedron");
  expect_error("bad_crack_3d.lis",
               41,
               "expected 3 points (9 coordinates) for crack 1 of 1 in 3D, "
               "found 6");
  EXPECT_NE(error_of([] {
              read_pdlsm_fem_mesh(data_dir + "no_such.lis");
            }).find("no_such.lis: cannot read the mesh file"),
            std::string::npos);
}

// ---------------------------------------------------------------- bad command
// files

TEST(PDLSMFEMInput, MalformedCommandFiles)
{
  expect_error("bad_first.in",
               2,
               "expected MSHFILE as the first command, found 'SOLVER'");
  expect_error("bad_keyword.in", 4, "unknown keyword 'SETSOLVNG' (allowed: ");
  expect_error("bad_keyword.in", 4, "MSHFILE, SOLVER, SETSOLVING, NEWMARK");
  expect_error("bad_number.in",
               3,
               "SETSOLVING: Nsteps must be a whole number, found '2O'");
  expect_error("bad_ebc_id.in",
               3,
               "EBC: the mesh file has no essential BC set 3 (allowed: 0..2)");
  expect_error("bad_solver.in",
               3,
               "SOLVER: unknown value 'IMPLICIT' (allowed: STATIC, "
               "QUASI-STATIC, DYNAMIC)");
  expect_error("bad_missing_mesh.in", 2, "no_such_mesh.lis does not exist");
  // an error in the mesh file names the mesh file and its line
  expect_error("bad_mesh.in",
               "bad_element_nodes.lis",
               21,
               "expected 4 node ids for element 4, found 3");

  const std::string no_solver =
    error_of([] { read_pdlsm_fem(data_dir + "bad_no_solver.in"); });
  EXPECT_NE(no_solver.find("bad_no_solver.in: SOLVER: missing"),
            std::string::npos)
    << no_solver;
  EXPECT_NE(error_of([] {
              read_pdlsm_fem(data_dir + "no_such.in");
            }).find("no_such.in: cannot read the command file"),
            std::string::npos);
}

// ---------------------------------------------------------------- the peer's
// inputs

namespace
{
  const std::string peer_dir =
    std::string(PDFEM_SOURCE_DIR) + "/../shared/peer-inputs/pdlsm-fem/";

  std::array<unsigned int, 3>
  count_types(const PDLSMFEMModel &m)
  {
    std::array<unsigned int, 3> n{{0, 0, 0}};
    for (const auto &e : m.elements)
      ++n[e.type];
    return n;
  }
} // namespace

TEST(PDLSMFEMInput, PeerPlateCrack)
{
  if (!std::filesystem::exists(peer_dir))
    GTEST_SKIP() << "the PDLSM-FEM example inputs are not in " << peer_dir;
  const std::string folder = peer_dir + "plateCrack/";

  const PDLSMFEMModel m =
    read_pdlsm_fem(folder + "platCrack_quasiStatic_FC1.in");
  EXPECT_EQ(m.solver, Solver::quasi_static);
  EXPECT_DOUBLE_EQ(m.dt, 1.);
  EXPECT_EQ(m.n_steps, 60u);
  EXPECT_EQ(m.write_frequency, 2u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 4.);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.33);
  EXPECT_FALSE(m.fe_nodes_in_families);
  EXPECT_FALSE(m.newmark);
  EXPECT_FALSE(m.lumped_mass);
  EXPECT_EQ(m.failure_criterion, 1);
  EXPECT_DOUBLE_EQ(m.fc1_contour_factor, 6.);
  EXPECT_DOUBLE_EQ(m.fc1_growth_factor, 1.);
  EXPECT_EQ(m.reaction_sets, (std::vector<unsigned int>{1}));
  EXPECT_FALSE(m.vtk_ascii);

  EXPECT_EQ(m.title, "plateCrack");
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.problem_type, 1);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 7e10);
  EXPECT_DOUBLE_EQ(m.poissons_ratio, 0.33);
  EXPECT_DOUBLE_EQ(m.density, 2700.);
  EXPECT_DOUBLE_EQ(m.fracture_toughness, 22e6);
  EXPECT_DOUBLE_EQ(m.tensile_strength, 1.2e8);
  ASSERT_EQ(m.nodes.size(), 7140u);
  EXPECT_EQ(m.nodes.front(), (P{{-0.5, -0.5, 0.}}));
  EXPECT_DOUBLE_EQ(m.nodes.back()[0], -8.9473684211e-02);
  EXPECT_DOUBLE_EQ(m.nodes.back()[1], 0.2125);
  ASSERT_EQ(m.elements.size(), 6972u);
  EXPECT_EQ(count_types(m), (T{{0, 2940, 4032}}));
  EXPECT_EQ(m.elements.front().vertices, ids({1, 3, 97, 74}));
  EXPECT_EQ(m.elements.back().vertices, ids({7140, 2739, 2709, 5051}));
  for (const auto &e : m.elements)
    ASSERT_EQ(e.vertices.size(), 4u);

  ASSERT_EQ(m.essential.size(), 3u);
  const unsigned int sizes[3]      = {85, 85, 84};
  const unsigned int components[3] = {0, 0, 1};
  const double       rates[3]      = {-4.79e-5, 4.79e-5, 0.};
  for (unsigned int s = 0; s < 3; ++s)
    {
      EXPECT_EQ(m.essential[s].nodes.size(), sizes[s]);
      EXPECT_EQ(m.essential[s].component, components[s]);
      EXPECT_DOUBLE_EQ(m.essential[s].value, 0.); // EBC 0/1 0e-5; file 0
      EXPECT_DOUBLE_EQ(m.essential[s].rate, rates[s]);
    }
  EXPECT_EQ(m.essential[0].nodes.front(), 0u);
  EXPECT_TRUE(m.natural.empty());
  EXPECT_TRUE(m.no_fail_nodes.empty());
  ASSERT_EQ(m.cracks.size(), 2u);
  EXPECT_EQ(m.cracks[0][0], (P{{0., 0., 0.}}));
  EXPECT_EQ(m.cracks[0][1], (P{{0., 0.098, 0.}}));
  EXPECT_EQ(m.cracks[1][1], (P{{0., -0.098, 0.}}));

  // the other command files of the example
  const PDLSMFEMModel s = read_pdlsm_fem(folder + "platCrack_Static.in");
  EXPECT_EQ(s.solver, Solver::static_solver);
  EXPECT_EQ(s.failure_criterion, 1);
  EXPECT_DOUBLE_EQ(s.essential[0].value, -5e-5);
  EXPECT_DOUBLE_EQ(s.essential[1].value, 5e-5);
  EXPECT_TRUE(s.ebc_rate.empty());
  EXPECT_TRUE(s.fe_nodes_in_families);

  const PDLSMFEMModel q =
    read_pdlsm_fem(folder + "platCrack_quasiStatic_FC2.in");
  EXPECT_EQ(q.solver, Solver::quasi_static);
  EXPECT_EQ(q.n_steps, 70u);
  EXPECT_EQ(q.failure_criterion, 2);
  EXPECT_EQ(q.top_k, 4u);
  EXPECT_DOUBLE_EQ(q.essential[1].rate, 4.79e-5);

  const PDLSMFEMModel x =
    read_pdlsm_fem(folder + "platCrack_NewMarkOFF_FC2.in");
  EXPECT_EQ(x.solver, Solver::dynamic);
  EXPECT_DOUBLE_EQ(x.dt, 5e-7);
  EXPECT_EQ(x.n_steps, 1100u);
  EXPECT_EQ(x.write_frequency, 20u);
  EXPECT_DOUBLE_EQ(x.weight_factor, 1.);
  EXPECT_FALSE(x.newmark);
  EXPECT_TRUE(x.lumped_mass);
  EXPECT_EQ(x.failure_criterion, 2);
  EXPECT_EQ(x.top_k, 0u);
  EXPECT_DOUBLE_EQ(x.essential[0].rate, -1.);
  EXPECT_DOUBLE_EQ(x.essential[1].rate, 1.);

  const PDLSMFEMModel n = read_pdlsm_fem(folder + "platCrack_NewMarkON_FC2.in");
  EXPECT_EQ(n.solver, Solver::dynamic);
  EXPECT_TRUE(n.newmark);
  EXPECT_DOUBLE_EQ(n.newmark_gamma, 0.5);
  EXPECT_DOUBLE_EQ(n.newmark_beta, 0.25);
  EXPECT_FALSE(n.lumped_mass);
}

TEST(PDLSMFEMInput, PeerPlateHole)
{
  if (!std::filesystem::exists(peer_dir))
    GTEST_SKIP() << "the PDLSM-FEM example inputs are not in " << peer_dir;
  const std::string folder = peer_dir + "plateHole/";

  const PDLSMFEMModel m = read_pdlsm_fem(folder + "platHole_Static.in");
  EXPECT_EQ(m.solver, Solver::static_solver);
  EXPECT_EQ(m.n_steps, 50u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 4.);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.33);
  EXPECT_EQ(m.failure_criterion, 2);
  EXPECT_EQ(m.top_k, 4u);
  EXPECT_EQ(m.reaction_sets, (std::vector<unsigned int>{1}));
  EXPECT_EQ(m.title, "platHolePDFEM");
  EXPECT_DOUBLE_EQ(m.density, 7800.);
  EXPECT_DOUBLE_EQ(m.fracture_toughness, 8e7);
  ASSERT_EQ(m.nodes.size(), 5270u);
  ASSERT_EQ(m.elements.size(), 5100u);
  EXPECT_EQ(count_types(m), (T{{0, 2300, 2800}}));
  EXPECT_EQ(m.elements.back().vertices, ids({5270, 4880, 3764, 3863}));
  // the file has 71/71/62 constrained nodes (specs/004 §6.3 says "as in 6.2")
  ASSERT_EQ(m.essential.size(), 3u);
  EXPECT_EQ(m.essential[0].nodes.size(), 71u);
  EXPECT_EQ(m.essential[1].nodes.size(), 71u);
  EXPECT_EQ(m.essential[2].nodes.size(), 62u);
  EXPECT_EQ(m.essential[2].component, 1u);
  EXPECT_DOUBLE_EQ(m.essential[0].value, -5e-5);
  EXPECT_DOUBLE_EQ(m.essential[1].value, 5e-5);
  EXPECT_TRUE(m.natural.empty());
  EXPECT_TRUE(m.cracks.empty());

  const PDLSMFEMModel q =
    read_pdlsm_fem(folder + "platHole_quasiStatic_FC2.in");
  EXPECT_EQ(q.solver, Solver::quasi_static);
  EXPECT_EQ(q.n_steps, 110u);
  EXPECT_EQ(q.write_frequency, 3u);
  EXPECT_DOUBLE_EQ(q.essential[0].value, 0.);
  EXPECT_DOUBLE_EQ(q.essential[0].rate, -6.35e-5);
  EXPECT_DOUBLE_EQ(q.essential[1].rate, 6.35e-5);
  EXPECT_EQ(q.top_k, 4u);
}

TEST(PDLSMFEMInput, PeerBox)
{
  if (!std::filesystem::exists(peer_dir))
    GTEST_SKIP() << "the PDLSM-FEM example inputs are not in " << peer_dir;

  const auto          start = std::chrono::steady_clock::now();
  const PDLSMFEMModel m = read_pdlsm_fem(peer_dir + "box/boxVpd4_static.in");
  const double        seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count();
  std::cout << "[ info ] box (3.8 MB .lis) parsed in " << seconds << " s"
            << std::endl;
  RecordProperty("box_parse_seconds", std::to_string(seconds));
  EXPECT_LT(seconds, 1.);

  EXPECT_EQ(m.solver, Solver::static_solver);
  EXPECT_EQ(m.n_steps, 72u);
  EXPECT_DOUBLE_EQ(m.horizon_factor, 4.);
  EXPECT_DOUBLE_EQ(m.weight_factor, 0.25);
  EXPECT_FALSE(m.newmark);
  EXPECT_EQ(m.failure_criterion, 0);
  EXPECT_EQ(m.reaction_sets, (std::vector<unsigned int>{1}));

  EXPECT_EQ(m.title, "boxVpd4");
  EXPECT_EQ(m.dim, 3);
  EXPECT_EQ(m.problem_type, -1);
  ASSERT_EQ(m.nodes.size(), 35301u);
  EXPECT_EQ(m.nodes.front(), (P{{-0.5, 0.5, 0.}}));
  EXPECT_EQ(m.nodes.back(), (P{{0.025, -0.475, -0.025}}));
  ASSERT_EQ(m.elements.size(), 32000u);
  EXPECT_EQ(count_types(m), (T{{0, 12800, 19200}}));
  for (const auto &e : m.elements)
    ASSERT_EQ(e.vertices.size(), 8u);
  EXPECT_EQ(m.elements.front().vertices,
            ids({2, 30, 49, 5, 365, 385, 643, 567}));

  ASSERT_EQ(m.essential.size(), 3u);
  const unsigned int sizes[3] = {861, 861, 1681};
  for (unsigned int s = 0; s < 3; ++s)
    {
      EXPECT_EQ(m.essential[s].nodes.size(), sizes[s]);
      EXPECT_EQ(m.essential[s].component, s); // UX, UY, UZ
      EXPECT_DOUBLE_EQ(m.essential[s].value, 0.);
    }
  ASSERT_EQ(m.natural.size(), 1u);
  EXPECT_DOUBLE_EQ(m.natural[0].traction, 7e6);
  ASSERT_EQ(m.natural[0].faces.size(), 1600u);
  for (const auto &f : m.natural[0].faces)
    ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(m.natural[0].faces.front(), ids({1, 115, 145, 7}));
  EXPECT_EQ(m.natural[0].faces.back(), ids({8040, 7815, 7811, 7851}));
  EXPECT_TRUE(m.no_fail_nodes.empty());
  EXPECT_TRUE(m.cracks.empty());
}
