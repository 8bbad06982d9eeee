// SPDX-License-Identifier: LGPL-2.1-or-later
// Replays inputs through a fuzz target without libFuzzer (ctest fuzz.*):
//
//   pdfem_fuzz_replay READER PATH...
//
// READER is prm, msh or pdlsm_fem; each PATH a file or a folder (its files,
// in name order). Every input must be accepted or refused with a one-line
// InputError; a crash or another exception aborts. Prints the counts.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "readers.h"

int
main(int argc, char **argv)
{
  namespace fs = std::filesystem;
  const auto read =
    argc > 2 ? pdfem::Fuzz::reader(argv[1]) : pdfem::Fuzz::Reader();
  if (read == nullptr)
    {
      std::cerr << "usage: pdfem_fuzz_replay prm|msh|pdlsm_fem PATH...\n";
      return 2;
    }
  std::vector<fs::path> inputs;
  for (int i = 2; i < argc; ++i)
    if (fs::is_directory(argv[i]))
      for (const auto &entry : fs::recursive_directory_iterator(argv[i]))
        {
          if (entry.is_regular_file())
            inputs.push_back(entry.path());
        }
    else if (fs::is_regular_file(argv[i]))
      inputs.emplace_back(argv[i]);
    else
      {
        std::cerr << "pdfem_fuzz_replay: no such file or folder: " << argv[i]
                  << '\n';
        return 2;
      }
  std::sort(inputs.begin(), inputs.end());

  unsigned int accepted = 0;
  for (const fs::path &input : inputs)
    {
      std::cout << input.filename().string() << std::endl; // names a crash
      std::ifstream                   in(input, std::ios::binary);
      const std::vector<std::uint8_t> bytes(
        (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      if (read(bytes.data(), bytes.size()) == pdfem::Fuzz::Outcome::accepted)
        ++accepted;
    }
  std::cout << argv[1] << ": " << inputs.size() << " inputs, " << accepted
            << " accepted, " << inputs.size() - accepted
            << " refused with one line, none crashed\n";
  return inputs.empty() ? 1 : 0;
}
