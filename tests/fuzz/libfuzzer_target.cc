// SPDX-License-Identifier: LGPL-2.1-or-later
// The libFuzzer entry point of one reader (PDFEM_FUZZ_READER: prm, msh or
// pdlsm_fem), built with -DPDFEM_BUILD_FUZZERS=ON (doc/reliability.md).
#include "readers.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  pdfem::Fuzz::PDFEM_FUZZ_READER(data, size);
  return 0;
}
