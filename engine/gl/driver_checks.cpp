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
    static const bool finish = switchedOn("VCT_GL_FINISH");
    glMemoryBarrier(all ? GL_ALL_BARRIER_BITS : barriers);
    if (finish) glFinish();
}

bool poisonNewStorage() {
    static const bool poison = switchedOn("VCT_GL_POISON");
    return poison;
}

bool cpuRasterizer() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!renderer) return false;
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader"})
        if (std::strstr(renderer, name)) return true;
    return false;
}

void poisonNewTexture(GLuint texture, GLenum internalFormat, int levels) {
    if (!poisonNewStorage()) return;
    const GLuint integers[4] = {0x7F7F7F7Fu, 0x7F7F7F7Fu, 0x7F7F7F7Fu, 0x7F7F7F7Fu};
    const float floats[4] = {3.0e38f, 3.0e38f, 3.0e38f, 3.0e38f};
    const float depth = 0.5f;
    for (int level = 0; level < levels; ++level) {
        switch (internalFormat) {
            case GL_R32UI:
            case GL_RG32UI:
            case GL_RGBA32UI: glClearTexImage(texture, level, GL_RGBA_INTEGER, GL_UNSIGNED_INT, integers); break;
            case GL_DEPTH_COMPONENT32F:
            case GL_DEPTH_COMPONENT24:
            case GL_DEPTH_COMPONENT16: glClearTexImage(texture, level, GL_DEPTH_COMPONENT, GL_FLOAT, &depth); break;
            default: glClearTexImage(texture, level, GL_RGBA, GL_FLOAT, floats); break;
        }
    }
}

}  // namespace vct::gl
