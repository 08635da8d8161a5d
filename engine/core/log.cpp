#include "core/log.hpp"

#include <cstdio>
#include <mutex>
#include <set>

namespace vct {
namespace {
LogLevel g_level = LogLevel::Info;
std::mutex g_mutex;
std::set<std::string> g_warned;
}  // namespace

void setLogLevel(LogLevel level) { g_level = level; }
LogLevel logLevel() { return g_level; }

void logInfo(const std::string& message) {
    if (g_level >= LogLevel::Info) std::fprintf(stderr, "vct: %s\n", message.c_str());
}

void logWarn(const std::string& message) {
    if (g_level >= LogLevel::Warn) std::fprintf(stderr, "vct: warning: %s\n", message.c_str());
}

bool logWarnOnce(const std::string& key, const std::string& message) {
    std::lock_guard lock(g_mutex);
    if (!g_warned.insert(key).second) return false;
    logWarn(message);
    return true;
}

}  // namespace vct
