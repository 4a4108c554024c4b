// SPDX-License-Identifier: BSD-3-Clause
// The message of an expected exception, for tests that check what an error says.
#pragma once

#include <string>

#include "core/utilities/error.h"

namespace mc::test {

/// The message of the `Error` that `f()` throws, or "" when it throws none.
template <class Error = InputError, class F>
std::string ErrorMessageOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace mc::test
