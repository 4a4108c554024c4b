// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer entry point for mc::fuzz::ReadMdpa (see fuzz_targets.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mc::fuzz::ReadMdpa(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
