// SPDX-License-Identifier: LGPL-2.1-or-later
// Output integrity: a file is written whole or not at all, and a failed
// write is reported, not ignored.
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
} // namespace
