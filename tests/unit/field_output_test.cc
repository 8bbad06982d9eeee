// SPDX-License-Identifier: LGPL-2.1-or-later
// The VTU writer's base64 encoder against RFC 4648's examples and deal.II's
// encoder (which the writer used before).
#include <pdfem/io/field_output.h>

#include <deal.II/base/utilities.h>

#include <random>

#include <gtest/gtest.h>

using pdfem::IO::internal::base64;

namespace
{
  std::vector<unsigned char>
  bytes_of(const std::string &s)
  {
    return {s.begin(), s.end()};
  }
} // namespace

TEST(Base64, Rfc4648Examples)
{
  EXPECT_EQ(base64(bytes_of("")), "");
  EXPECT_EQ(base64(bytes_of("f")), "Zg==");
  EXPECT_EQ(base64(bytes_of("fo")), "Zm8=");
  EXPECT_EQ(base64(bytes_of("foo")), "Zm9v");
  EXPECT_EQ(base64(bytes_of("foob")), "Zm9vYg==");
  EXPECT_EQ(base64(bytes_of("fooba")), "Zm9vYmE=");
  EXPECT_EQ(base64(bytes_of("foobar")), "Zm9vYmFy");
}

TEST(Base64, SameAsDealIIForEveryLengthAndByte)
{
  std::mt19937                       random(42);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::size_t n = 0; n < 70; ++n)
    {
      std::vector<unsigned char> data(n);
      for (auto &b : data)
        b = static_cast<unsigned char>(byte(random));
      if (n == 3) // the extreme bytes
        data = {0, 255, 128};
      EXPECT_EQ(base64(data), dealii::Utilities::encode_base64(data))
        << n << " bytes";
    }
}
