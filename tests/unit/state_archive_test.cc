// SPDX-License-Identifier: LGPL-2.1-or-later
// The checkpoint archive: values come back bit for bit, and a file cut short
// or altered is refused with a message naming it, never half read.
#include <pdfem/base/exceptions.h>
#include <pdfem/base/state_archive.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include <gtest/gtest.h>

namespace
{
  namespace fs = std::filesystem;
  using pdfem::StateArchive;

  struct Record
  {
    unsigned int step;
    double       time;
    bool         flag;
  };

  TEST(StateArchive, ValuesComeBackBitForBit)
  {
    const fs::path folder = fs::temp_directory_path() / "pdfem_state_archive";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const std::string file = (folder / "rank-0.state").string();

    StateArchive out;
    out.put("a/double", 0.1 + 0.2);
    out.put("a/record", Record{7, -0.0, true});
    out.put("a/values",
            std::vector<double>{1e-320,
                                std::numeric_limits<double>::max(),
                                -1.5});
    out.put("a/pairs", std::vector<std::array<unsigned int, 2>>{{{1, 2}}});
    out.put("a/empty", std::vector<double>());
    out.put("a/text", std::string("line one\nline two"));
    ASSERT_EQ(out.write(file), "");
    EXPECT_FALSE(fs::exists(file + ".tmp"));

    const StateArchive in = StateArchive::read(file);
    EXPECT_EQ(in.get<double>("a/double"), 0.1 + 0.2);
    const auto r = in.get<Record>("a/record");
    EXPECT_EQ(r.step, 7u);
    EXPECT_TRUE(std::signbit(r.time));
    EXPECT_TRUE(r.flag);
    const auto v = in.get_vector<double>("a/values");
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(v[0], 1e-320);
    EXPECT_EQ(v[1], std::numeric_limits<double>::max());
    const auto pairs = in.get_vector<std::array<unsigned int, 2>>("a/pairs");
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0][1], 2u);
    EXPECT_TRUE(in.get_vector<double>("a/empty").empty());
    EXPECT_EQ(in.get_text("a/text"), "line one\nline two");
    double three[3];
    in.get("a/values", three, 3);
    EXPECT_EQ(three[2], -1.5);

    // Missing entries and wrong sizes are input errors naming the file.
    EXPECT_THROW(in.get<double>("a/none"), pdfem::InputError);
    EXPECT_THROW(in.get<double>("a/record"), pdfem::InputError);
    EXPECT_THROW(in.get("a/values", three, 2), pdfem::InputError);
    try
      {
        in.get<double>("a/none");
      }
    catch (const pdfem::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos)
          << e.what();
      }

    // Every truncation and a changed byte anywhere are refused.
    std::ifstream     whole(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(whole), {}};
    const std::string damaged = (folder / "damaged.state").string();
    for (std::size_t n = 0; n < bytes.size(); ++n)
      {
        std::ofstream(damaged, std::ios::binary) << bytes.substr(0, n);
        EXPECT_THROW(StateArchive::read(damaged), pdfem::InputError) << n;
      }
    for (std::size_t at = 0; at < bytes.size(); at += 7)
      {
        std::string flipped = bytes;
        flipped[at] ^= 0x10;
        std::ofstream(damaged, std::ios::binary) << flipped;
        EXPECT_THROW(StateArchive::read(damaged), pdfem::InputError) << at;
      }
    EXPECT_THROW(StateArchive::read((folder / "none.state").string()),
                 pdfem::InputError);
    // A folder it cannot write to is reported, not thrown.
    EXPECT_NE(out.write((folder / "no/such/folder/x.state").string()), "");
    fs::remove_all(folder);
  }
} // namespace
