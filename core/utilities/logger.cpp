// SPDX-License-Identifier: BSD-3-Clause
#include "core/utilities/logger.h"

#include <iostream>
#include <mutex>

namespace mc {
namespace {
std::mutex& SinkMutex() {
  static std::mutex m;
  return m;
}
Logger::Sink& CurrentSink() {
  static Logger::Sink sink;
  return sink;
}
void Write(Logger::Level level, const std::string& message) {
  std::lock_guard<std::mutex> lock(SinkMutex());
  if (CurrentSink()) {
    CurrentSink()(level, message);
    return;
  }
  (level == Logger::Level::Warning ? std::cerr : std::cout) << message << '\n';
}
}  // namespace

void Logger::SetSink(Sink sink) {
  std::lock_guard<std::mutex> lock(SinkMutex());
  CurrentSink() = std::move(sink);
}
void Logger::ResetSink() { SetSink(nullptr); }
void Logger::Info(const std::string& message) { Write(Level::Info, message); }
void Logger::Warning(const std::string& message) { Write(Level::Warning, message); }
void Logger::Detail(const std::string& message) { Write(Level::Detail, message); }

}  // namespace mc
