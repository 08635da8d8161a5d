#pragma once
// Minimal logging to stderr. Warnings can be deduplicated by key so that, for example, a texture
// missing from 200 materials is reported once.
#include <string>

namespace vct {

enum class LogLevel { Quiet = 0, Warn = 1, Info = 2 };

void setLogLevel(LogLevel level);
LogLevel logLevel();

void logInfo(const std::string& message);
void logWarn(const std::string& message);
// Returns true (and prints) only the first time `key` is seen in this process.
bool logWarnOnce(const std::string& key, const std::string& message);

}  // namespace vct
