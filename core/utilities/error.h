// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace mc {

/// Base of every error raised by mortarcontact.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A mistake in the user's input (files, settings, names, values). The command line prints the
/// message alone, without a traceback, and exits non-zero.
class InputError : public Error {
 public:
  using Error::Error;
};

/// A documented option that this version does not implement yet.
class NotImplementedError : public Error {
 public:
  using Error::Error;
};

/// A solution that could not be computed: singular system, non-convergence, inverted element.
class SolutionError : public Error {
 public:
  using Error::Error;
};

/// Joins any streamable values into one string: Concat("node ", id, ": value ", v).
template <class... Args>
std::string Concat(Args&&... args) {
  std::ostringstream out;
  out.precision(10);
  (out << ... << std::forward<Args>(args));
  return out.str();
}

}  // namespace mc
