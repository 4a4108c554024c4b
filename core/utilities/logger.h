// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>

namespace mc {

/// Where the C++ side writes human-readable messages (convergence logs, warnings). By default
/// to stdout/stderr; the Python layer installs a sink so that messages go through its console
/// (progress bars, notebooks).
class Logger {
 public:
  enum class Level { Info, Warning, Detail };
  using Sink = std::function<void(Level, const std::string&)>;

  static void SetSink(Sink sink);
  static void ResetSink();
  static void Info(const std::string& message);
  static void Warning(const std::string& message);
  static void Detail(const std::string& message);
};

}  // namespace mc
