#pragma once
// An OpenGL 4.5 core context, made current on the calling thread. Three backends share this
// interface; all of them render into engine-owned framebuffers, so only presentation differs.
//   osmesa  offscreen on Mesa llvmpipe (CPU): CI and machines without a GPU
//   egl     headless through EGL (device or surfaceless platform): a real GPU without a display
//   glfw    a window (the viewer); hidden when used for offscreen rendering
#include <memory>
#include <string>

struct GLFWwindow;

namespace vct::gl {

enum class Backend { OSMesa, EGL, GLFW };

Backend parseBackend(const std::string& name);  // throws listing the valid names
const char* backendName(Backend backend);
// The backend used when none is chosen: $VCT_BACKEND if set (osmesa, egl or glfw), else osmesa.
// The commands' --backend defaults and the tests' contexts follow it, so that one variable moves
// everything onto a GPU (benchmarks/gpu.sh runs the test suite with VCT_BACKEND=egl).
Backend defaultBackend();
std::string defaultBackendName();

struct ContextInfo {
    std::string backend;
    std::string vendor;
    std::string renderer;
    std::string version;      // GL_VERSION string
    std::string glslVersion;
    int major = 0;
    int minor = 0;
};

struct ContextOptions {
    bool visibleWindow = false;  // glfw only
    int windowWidth = 1280;
    int windowHeight = 720;
    std::string windowTitle = "vct";
    bool debugOutput = false;    // KHR_debug messages to stderr (also with VCT_GL_DEBUG=1)
};

class Context {
public:
    virtual ~Context() = default;
    virtual void makeCurrent() = 0;
    virtual GLFWwindow* window() { return nullptr; }
    const ContextInfo& info() const { return info_; }

protected:
    // Loads GL entry points through `getProc`, fills info_ and fails clearly unless the context
    // is 4.5 core. Every backend calls it once after making its context current.
    void initialize(const char* backend, void* (*getProc)(const char*), const ContextOptions& options);
    ContextInfo info_;
};

std::unique_ptr<Context> createContext(Backend backend, const ContextOptions& options = {});

// Backends (one file each).
std::unique_ptr<Context> createOSMesaContext(const ContextOptions& options);
std::unique_ptr<Context> createEGLContext(const ContextOptions& options);
std::unique_ptr<Context> createGLFWContext(const ContextOptions& options);

}  // namespace vct::gl
