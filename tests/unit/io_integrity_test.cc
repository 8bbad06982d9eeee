// SPDX-License-Identifier: LGPL-2.1-or-later
// Output integrity: a file is written whole or not at all, and a failed
// write is reported, not ignored.
#include <pdfem/base/parameter_tools.h>
#include <pdfem/io/atomic_file.h>
#include <pdfem/io/history.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace
{
  namespace fs = std::filesystem;

  std::string
  contents(const fs::path &file)
  {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), {}};
  }

  TEST(AtomicFile, ReplacesTheFileWholeAndLeavesNoTemporary)
  {
    const fs::path folder = fs::temp_directory_path() / "pdfem_atomic_file";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::string file = (folder / "summary.json").string();
    EXPECT_EQ(pdfem::IO::write_atomically(
                file, [](std::ostream &out) { out << "old"; }),
              "");
    EXPECT_EQ(pdfem::IO::write_atomically(
                file, [](std::ostream &out) { out << "new"; }),
              "");
    EXPECT_EQ(contents(file), "new");
    EXPECT_FALSE(fs::exists(file + ".tmp"));
    fs::remove_all(folder);
  }

  TEST(AtomicFile, ReportsAFolderItCannotWriteTo)
  {
    const std::string error =
      pdfem::IO::write_atomically("/nonexistent-pdfem-folder/summary.json",
                                  [](std::ostream &out) { out << "x"; });
    EXPECT_NE(error.find("cannot create"), std::string::npos) << error;
  }

  // /dev/full accepts the file but no byte of it (ENOSPC): a disk that
  // filled up during the run.
  TEST(History, ReportsARowThatCouldNotBeWritten)
  {
    if (!fs::exists("/dev/full"))
      GTEST_SKIP() << "no /dev/full";
    pdfem::IO::History  history("/dev/full", {"step", "time"}, true);
    std::vector<double> row(2, 1.);
    bool                written = true;
    // The stream buffers; within a few rows its flush fails.
    for (int i = 0; i < 4 && written; ++i)
      written = history.add_row(row);
    EXPECT_FALSE(written);
  }
  TEST(History, ColumnNamesSayWhatAPointIs)
  {
    using pdfem::IO::History;
    EXPECT_EQ(History::column_name("left"), "left");
    EXPECT_EQ(History::column_name("top edge"), "top_edge");
    EXPECT_EQ(History::column_name("(-0.5, -1.5)"), "at_x-0.5_y-1.5");
    EXPECT_EQ(History::column_name("(0,0.25, 1e-3)"), "at_x0_y0.25_z1e-3");
    // Not a point of 2 or 3 coordinates: the general rule.
    EXPECT_EQ(History::column_name("(1, 2, 3, 4)"), "1_2_3_4");
  }

  TEST(Messages, DealIIReportsBecomeOneLine)
  {
    // What Amesos_Mumps threw on a singular matrix (no explanation, only
    // the condition) and a report with an explanation and a stack trace.
    const std::string amesos =
      "\n--------------------------------------------------------\n"
      "An error occurred in line <842> of file "
      "<./source/lac/trilinos_solver.cc> in function\n"
      "    void dealii::TrilinosWrappers::SolverDirect::do_solve()\n"
      "The violated condition was: \n"
      "    ierr == 0\n"
      "Additional information: \n"
      "Stacktrace:\n-----------\n#0  libdeal.ii.so: f()\n";
    EXPECT_EQ(pdfem::ParameterTools::clean_dealii_message(amesos), "ierr == 0");
    const std::string explained =
      "\n--------\nAn error occurred in line <1> of file <a.cc>\n"
      "The violated condition was: \n    n > 0\n"
      "Additional information: \n    the entry is\n    not declared\n"
      "Stacktrace:\n#0 f()\n";
    EXPECT_EQ(pdfem::ParameterTools::clean_dealii_message(explained),
              "the entry is not declared");
    EXPECT_EQ(pdfem::ParameterTools::clean_dealii_message("plain"), "plain");
  }
} // namespace
