#include "gl/driver_checks.hpp"

#include <cstdlib>
#include <cstring>

namespace vct::gl {
namespace {
bool switchedOn(const char* name) {
    const char* value = std::getenv(name);
    return value && *value && std::strcmp(value, "0") != 0;
}
}  // namespace

void memoryBarrier(GLbitfield barriers) {
    static const bool all = switchedOn("VCT_GL_ALL_BARRIERS");
    glMemoryBarrier(all ? GL_ALL_BARRIER_BITS : barriers);
}

bool poisonNewStorage() {
    static const bool poison = switchedOn("VCT_GL_POISON");
    return poison;
}

}  // namespace vct::gl
