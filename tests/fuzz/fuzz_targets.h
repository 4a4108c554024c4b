// SPDX-License-Identifier: BSD-3-Clause
// The three fuzzed entry points, shared by the libFuzzer harnesses (fuzz_*.cpp, `make fuzz`) and
// by the GoogleTest that replays every input they ever crashed on (tests/cpp/fuzz_regressions).
// Each returns normally for input the code answers with an InputError; anything else (another
// exception, a crash, a sanitizer report, a hang) is a finding.
#pragma once

#include <string_view>

namespace mc::fuzz {

/// Reads `text` as an mdpa file into a fresh model part with the structural elements,
/// conditions and laws registered.
void ReadMdpa(std::string_view text);

/// Parses `text` as JSON settings; when it parses, reads every value through every getter,
/// validates it against itself and against a fixed set of defaults, and checks that writing and
/// reading it back gives the same document. The text before the first NUL byte is the
/// settings, the rest (if any) a second document used as defaults.
void ReadParameters(std::string_view text);

/// Compiles `text` as a function expression and evaluates it at a few points.
void ParseExpression(std::string_view text);

}  // namespace mc::fuzz
