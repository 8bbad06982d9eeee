// SPDX-License-Identifier: LGPL-2.1-or-later
// The mesh checks of issue 19 (Mesh::check_msh_file, check_cell_shapes):
// - two valid meshes (gmsh 4.1 and 2.2, two quadrilaterals) pass and read;
// - the malformations that crashed deal.II's reader (truncated $Nodes, a
//   node count too small, swapped or deleted node-block lines, a blank or
//   inf coordinate) and others each give an InputError naming the line;
// - 3000 seeded random mutations of either file: each is refused with an
//   InputError naming a line, or else read without a crash;
// - a bow-tie, a vertex moved onto another and a clockwise triangle (as
//   the .lis reader builds it) are refused by the shape check, naming the
//   cell.
#include <pdfem/base/exceptions.h>
#include <pdfem/mesh/gmsh_input.h>
#include <pdfem/mesh/mesh_checks.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

namespace
{
  using namespace pdfem;

  const std::vector<std::string> mesh_41 = {"$MeshFormat",
                                            "4.1 0 8",
                                            "$EndMeshFormat",
                                            "$Entities",
                                            "0 0 1 0",
                                            "1 0 0 0 2 1 0 0 0",
                                            "$EndEntities",
                                            "$Nodes",
                                            "1 6 1 6",
                                            "2 1 0 6",
                                            "1",
                                            "2",
                                            "3",
                                            "4",
                                            "5",
                                            "6",
                                            "0 0 0",
                                            "1 0 0",
                                            "2 0 0",
                                            "0 1 0",
                                            "1 1 0",
                                            "2 1 0",
                                            "$EndNodes",
                                            "$Elements",
                                            "1 2 1 2",
                                            "2 1 3 2",
                                            "1 1 2 5 4",
                                            "2 2 3 6 5",
                                            "$EndElements"};

  const std::vector<std::string> mesh_22 = {"$MeshFormat",
                                            "2.2 0 8",
                                            "$EndMeshFormat",
                                            "$Nodes",
                                            "6",
                                            "1 0 0 0",
                                            "2 1 0 0",
                                            "3 2 0 0",
                                            "4 0 1 0",
                                            "5 1 1 0",
                                            "6 2 1 0",
                                            "$EndNodes",
                                            "$Elements",
                                            "2",
                                            "1 3 2 1 1 1 2 5 4",
                                            "2 3 2 1 1 2 3 6 5",
                                            "$EndElements"};

  /// A file of @p lines in the test's temporary folder.
  std::string
  write(const std::vector<std::string> &lines, const std::string &name)
  {
    const std::string file =
      (std::filesystem::temp_directory_path() /
       ("pdfem_mesh_checks_" + std::to_string(getpid()) + "_" + name))
        .string();
    std::ofstream out(file);
    for (const auto &l : lines)
      out << l << '\n';
    return file;
  }

  /// The InputError message of check_msh_file, or "" if it passed.
  std::string
  structure_error(const std::vector<std::string> &lines)
  {
    const std::string file = write(lines, "check.msh");
    try
      {
        Mesh::check_msh_file(file);
      }
    catch (const InputError &e)
      {
        std::filesystem::remove(file);
        return e.what();
      }
    std::filesystem::remove(file);
    return "";
  }

  /// The message of reading @p lines as a 2D mesh with both checks ("" if
  /// it was read; a reader exception past the checks is reported too).
  std::string
  read_error(const std::vector<std::string> &lines)
  {
    const std::string file = write(lines, "read.msh");
    std::string       message;
    // A refusal by deal.II's reader (an InputError too) after the file
    // passed the checks is marked "reader: ".
    bool checked = false;
    try
      {
        Mesh::check_msh_file(file);
        checked = true;
        dealii::Triangulation<2> tria;
        Mesh::read_msh<2>(file, tria);
        checked = false;
        Mesh::check_cell_shapes(tria, file);
      }
    catch (const std::exception &e)
      {
        message = (checked ? "reader: " : "") + std::string(e.what());
      }
    std::filesystem::remove(file);
    return message;
  }

  TEST(MeshChecks, ValidMeshesPassAndRead)
  {
    EXPECT_EQ(read_error(mesh_41), "");
    EXPECT_EQ(read_error(mesh_22), "");
  }

  TEST(MeshChecks, MalformedFilesNameTheLine)
  {
    struct Case
    {
      std::string                                     what;
      std::function<void(std::vector<std::string> &)> mutate;
      std::string                                     expected;
    };
    const std::vector<Case> cases = {
      {"truncated $Nodes",
       [](auto &l) { l.resize(14); },
       "line 14: the file ends inside $Nodes"},
      {"node count too small",
       [](auto &l) { l[8] = "1 5 1 6"; },
       "line 10: the node blocks hold more than the 5 nodes"},
      {"swapped node-block lines",
       [](auto &l) { std::swap(l[9], l[10]); },
       "line 10: $Nodes: expected a node block header"},
      {"deleted node-block line",
       [](auto &l) { l.erase(l.begin() + 9); },
       "line 10: $Nodes: expected a node block header"},
      {"blank coordinate",
       [](auto &l) { l[18] = "2 0"; },
       "line 19: $Nodes: expected the node's coordinates (3 fields)"},
      {"inf coordinate",
       [](auto &l) { l[18] = "inf 0 0"; },
       "line 19: coordinate 'inf' is not a finite number"},
      {"element node not in $Nodes",
       [](auto &l) { l[26] = "1 1 2 5 7"; },
       "line 27: element 1: node 7 is not in $Nodes"},
      {"repeated element node",
       [](auto &l) { l[26] = "1 1 2 2 4"; },
       "line 27: element 1 repeats node 2"},
      {"binary file",
       [](auto &l) { l[1] = "4.1 1 8"; },
       "line 2: a binary .msh file"},
      {"unknown element type",
       [](auto &l) { l[25] = "2 1 77 2"; },
       "line 26: element type 77 is not a gmsh type"},
      {"empty file", [](auto &l) { l.clear(); }, "the file has no $MeshFormat"},
      // A NUL after a node tag ended the number for the check but not for
      // deal.II's reader, which then wrote past a vector (a fuzzer's find).
      {"NUL in a node tag",
       [](auto &l) { l[10] += std::string(1, '\0') + "a"; },
       "line 11: a control character (byte 0) in the text"},
    };
    for (const Case &c : cases)
      {
        auto lines = mesh_41;
        c.mutate(lines);
        const std::string message = structure_error(lines);
        EXPECT_NE(message.find(c.expected), std::string::npos)
          << c.what << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << c.what;
      }
    auto lines = mesh_22;
    lines[6]   = "3 2 0";
    EXPECT_NE(structure_error(lines).find("line 7: $Nodes: expected a node"),
              std::string::npos);
  }

  TEST(MeshChecks, RandomMutationsAreRefusedOrRead)
  {
    // Deterministic: the same 3000 files every run. A crash fails the test.
    const std::vector<std::string> junk = {
      "", "inf", "nan", "1e-320", "-1", "0", "999999", "x", "$Nodes", "\"a\""};
    std::mt19937 random(2026);
    unsigned int refused = 0, read = 0;
    for (unsigned int i = 0; i < 3000; ++i)
      {
        auto       lines = i % 2 ? mesh_22 : mesh_41;
        const auto pick  = [&](const std::size_t n) {
          return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
        };
        const std::size_t at = pick(lines.size());
        switch (pick(5))
          {
            case 0:
              lines.erase(lines.begin() + at);
              break;
            case 1:
              lines.insert(lines.begin() + at, lines[pick(lines.size())]);
              break;
            case 2:
              std::swap(lines[at], lines[pick(lines.size())]);
              break;
            case 3:
              lines.resize(at);
              break;
            default:
              {
                std::istringstream       s(lines[at]);
                std::vector<std::string> fields;
                for (std::string f; s >> f;)
                  fields.push_back(f);
                if (fields.empty())
                  fields.push_back("");
                fields[pick(fields.size())] = junk[pick(junk.size())];
                lines[at].clear();
                for (const auto &f : fields)
                  lines[at] += (lines[at].empty() ? "" : " ") + f;
              }
          }
        const std::string message = read_error(lines);
        if (message.empty())
          ++read;
        else
          {
            ++refused;
            std::string file;
            for (const auto &l : lines)
              file += l + "\n";
            EXPECT_EQ(message.find("reader: "), std::string::npos)
              << "mutation " << i << " passed the checks but not the reader: "
              << message.substr(0, 300) << "\nthe file:\n"
              << file;
          }
      }
    EXPECT_GT(refused, 1500u);
    EXPECT_GT(read, 50u);
  }

  TEST(MeshChecks, BadCellShapesNameTheCell)
  {
    // A bow-tie: element 2's last two nodes swapped.
    auto bow_tie = mesh_41;
    bow_tie[27]  = "2 2 3 5 6";
    // Found in the file, before deal.II's reader (which can loop forever
    // on a tangled cell), and named by its line.
    EXPECT_NE(read_error(bow_tie).find("line 28: element 2 is tangled"),
              std::string::npos)
      << read_error(bow_tie);
    // Node 5 moved onto node 2: both quadrilaterals lose a corner.
    auto flat                    = mesh_41;
    flat[20]                     = "1 0 0";
    const std::string flat_error = read_error(flat);
    EXPECT_NE(flat_error.find("degenerate"), std::string::npos) << flat_error;
    // A clockwise triangle in a .msh: deal.II's reader turns it round.
    const std::vector<std::string> triangles = {"$MeshFormat",
                                                "2.2 0 8",
                                                "$EndMeshFormat",
                                                "$Nodes",
                                                "4",
                                                "1 0 0 0",
                                                "2 1 0 0",
                                                "3 0 1 0",
                                                "4 1 1 0",
                                                "$EndNodes",
                                                "$Elements",
                                                "2",
                                                "1 2 2 1 1 1 2 3",
                                                "2 2 2 1 1 2 3 4",
                                                "$EndElements"};
    EXPECT_EQ(read_error(triangles), "");
    // The same triangles built directly, as the .lis reader does: the
    // clockwise one is refused as inverted.
    const std::vector<dealii::Point<2>> vertices = {{0, 0},
                                                    {1, 0},
                                                    {0, 1},
                                                    {1, 1}};
    std::vector<dealii::CellData<2>>    cells(2);
    cells[0].vertices = {0, 1, 2};
    cells[1].vertices = {1, 2, 3};
    dealii::Triangulation<2> tria;
    tria.create_triangulation(vertices, cells, dealii::SubCellData());
    try
      {
        Mesh::check_cell_shapes(tria, "triangles.lis");
        ADD_FAILURE() << "the clockwise triangle was not refused";
      }
    catch (const InputError &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("triangles.lis: elements: cell 2"),
                  std::string::npos)
          << message;
        EXPECT_NE(message.find("inverted"), std::string::npos) << message;
      }
    // The cells before a triangulation is built (IO::create_triangulation
    // checks them so, since consistently_order_cells() loops forever on a
    // bow-tie): the same triangles, and a bow-tie next to a sound quad.
    try
      {
        Mesh::check_cell_shapes(vertices, cells, "triangles.lis");
        ADD_FAILURE() << "the clockwise triangle was not refused";
      }
    catch (const InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find("cell 2"), std::string::npos);
      }
    const std::vector<dealii::Point<2>> strip = {
      {0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
    std::vector<dealii::CellData<2>> quads(2);
    quads[0].vertices = {0, 1, 3, 4}; // deal.II's lexicographic order
    quads[1].vertices = {1, 2, 4, 5};
    EXPECT_NO_THROW(Mesh::check_cell_shapes(strip, quads, "strip.lis"));
    quads[1].vertices = {1, 2, 5, 4};
    try
      {
        Mesh::check_cell_shapes(strip, quads, "strip.lis");
        ADD_FAILURE() << "the bow-tie was not refused";
      }
    catch (const InputError &e)
      {
        const std::string message = e.what();
        EXPECT_NE(message.find("strip.lis: elements: cell 2"),
                  std::string::npos)
          << message;
        EXPECT_NE(message.find("tangled"), std::string::npos) << message;
      }
  }

  TEST(MeshChecks, GeneratedMeshesPassTheShapeCheck)
  {
    dealii::Triangulation<3> hexes;
    dealii::GridGenerator::hyper_shell(hexes, dealii::Point<3>(), 0.5, 1.);
    EXPECT_NO_THROW(Mesh::check_cell_shapes(hexes, "shell"));
    dealii::Triangulation<2> quads;
    dealii::GridGenerator::hyper_ball(quads);
    EXPECT_NO_THROW(Mesh::check_cell_shapes(quads, "ball"));
  }
} // namespace
