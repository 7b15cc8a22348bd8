#include <femto/core/log.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <mutex>

namespace femto {
namespace {

LogLevel initialLevel() {
  const char* env = std::getenv("FEMTO_LOG_LEVEL");
  if (!env) return LogLevel::Info;
  if (!std::strcmp(env, "debug")) return LogLevel::Debug;
  if (!std::strcmp(env, "warn")) return LogLevel::Warn;
  if (!std::strcmp(env, "error")) return LogLevel::Error;
  return LogLevel::Info;
}

std::atomic<LogLevel> gLevel{initialLevel()};
std::mutex gMutex;

}  // namespace

void setLogLevel(LogLevel level) { gLevel = level; }
LogLevel logLevel() { return gLevel; }

void logMessage(LogLevel level, const std::string& message) {
  if (level < gLevel.load()) return;
  static const char* prefix[] = {"debug: ", "", "warning: ", "error: "};
  // One write per line: std::cerr is unbuffered, and under mpirun (which
  // forwards each write of each rank as it comes) a line written in pieces
  // could have another stream's output spliced into it.
  const std::string line = prefix[int(level)] + message + '\n';
  std::lock_guard<std::mutex> lock(gMutex);
  std::cerr.write(line.data(), std::streamsize(line.size()));
}

}  // namespace femto
