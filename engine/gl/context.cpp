#include "gl/context.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"
#include "core/log.hpp"
#include "gl/gl.hpp"

namespace vct::gl {

Backend parseBackend(const std::string& name) {
    if (name == "osmesa") return Backend::OSMesa;
    if (name == "egl") return Backend::EGL;
    if (name == "glfw") return Backend::GLFW;
    fail("unknown backend '", name, "'; use osmesa (offscreen, CPU), egl (headless GPU) or glfw (window)");
}

Backend defaultBackend() { return parseBackend(defaultBackendName()); }

std::string defaultBackendName() {
    const char* chosen = std::getenv("VCT_BACKEND");
    return chosen && *chosen ? chosen : "osmesa";  // an unknown name fails where it is parsed, naming the valid ones
}

const char* backendName(Backend backend) {
    switch (backend) {
        case Backend::OSMesa: return "osmesa";
        case Backend::EGL: return "egl";
        case Backend::GLFW: return "glfw";
    }
    return "?";
}

namespace {
void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                              const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::fprintf(stderr, "vct: GL debug%s: %s\n", type == GL_DEBUG_TYPE_ERROR ? " error" : "", message);
}
}  // namespace

void Context::initialize(const char* backend, void* (*getProc)(const char*), const ContextOptions& options) {
    info_.backend = backend;
    const int loaded = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProc));
    if (!loaded || !glGetString)
        fail("the ", backend, " backend created a context but OpenGL functions could not be loaded; "
             "check the graphics driver installation");
    auto str = [](GLenum name) {
        const GLubyte* s = glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    info_.vendor = str(GL_VENDOR);
    info_.renderer = str(GL_RENDERER);
    info_.version = str(GL_VERSION);
    info_.glslVersion = str(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &info_.major);
    glGetIntegerv(GL_MINOR_VERSION, &info_.minor);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    const bool core = (profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    if (info_.major * 10 + info_.minor < 45 || !core)
        fail("the ", backend, " backend gave OpenGL ", info_.major, ".", info_.minor, core ? " core" : " compatibility",
             " (", info_.renderer, "); vct needs OpenGL 4.5 core. Update the driver (Mesa ≥ 20 gives 4.5 on "
             "llvmpipe) or try another --backend");
    // Conventions every pass relies on, set once for the context's lifetime: clip space depth in
    // [0, 1] for reversed depth (render/view.hpp).
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    const char* env = std::getenv("VCT_GL_DEBUG");
    if (options.debugOutput || (env && std::strcmp(env, "0") != 0)) {
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(debugCallback, nullptr);
    }
    logInfo(concat("OpenGL ", info_.version, " on ", info_.renderer, " (", backend, ")"));
}

std::unique_ptr<Context> createContext(Backend backend, const ContextOptions& options) {
    switch (backend) {
        case Backend::OSMesa: return createOSMesaContext(options);
        case Backend::EGL: return createEGLContext(options);
        case Backend::GLFW: return createGLFWContext(options);
    }
    fail("unknown backend");
}

}  // namespace vct::gl
