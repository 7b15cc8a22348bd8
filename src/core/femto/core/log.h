#pragma once
// Minimal thread-safe logging to stderr. Warnings can be turned into errors
// by the caller (see SceneLoader's strict mode); this only prints.
#include <string>

#include <femto/base/error.h>

namespace femto {

enum class LogLevel { Debug = 0, Info = 1, Warn = 2, Error = 3 };

/// Messages below this level are dropped (default Info; FEMTO_LOG_LEVEL=debug|info|warn|error).
void setLogLevel(LogLevel level);
LogLevel logLevel();
void logMessage(LogLevel level, const std::string& message);

template <typename... Args> void logDebug(Args&&... a) { if (logLevel() <= LogLevel::Debug) logMessage(LogLevel::Debug, str(std::forward<Args>(a)...)); }
template <typename... Args> void logInfo(Args&&... a) { if (logLevel() <= LogLevel::Info) logMessage(LogLevel::Info, str(std::forward<Args>(a)...)); }
template <typename... Args> void logWarn(Args&&... a) { logMessage(LogLevel::Warn, str(std::forward<Args>(a)...)); }
template <typename... Args> void logError(Args&&... a) { logMessage(LogLevel::Error, str(std::forward<Args>(a)...)); }

}  // namespace femto
