// EGL backend: a headless 4.5 core context with no window system. It tries, in order,
//   1. the device platform (EGL_EXT_platform_device), how NVIDIA drivers run without a display,
//   2. Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), llvmpipe or a Mesa GPU,
//   3. the default display,
// and uses the first that yields a 4.5 core context. No surface is created: the engine renders
// into its own FBOs (EGL_KHR_surfaceless_context).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/log.hpp"
#include "gl/context.hpp"

namespace vct::gl {
namespace {

std::string eglErrorText(EGLint error) {
    switch (error) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(error);
    }
}

bool hasExtension(const char* list, const std::string& name) {
    if (!list) return false;
    const std::string all = std::string(" ") + list + " ";
    return all.find(" " + name + " ") != std::string::npos;
}

class EGLContextImpl final : public Context {
public:
    explicit EGLContextImpl(const ContextOptions& options) {
        std::string attempts;
        for (EGLDisplay display : candidateDisplays()) {
            if (tryDisplay(display, attempts)) break;
        }
        if (context_ == EGL_NO_CONTEXT)
            fail("the egl backend found no display that gives an OpenGL 4.5 core context (tried: ", attempts,
                 "); install libegl1-mesa (Mesa) or the GPU driver's EGL, or use --backend osmesa");
        initialize("egl", [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); },
                   options);
    }

    ~EGLContextImpl() override {
        if (display_ != EGL_NO_DISPLAY) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
        }
    }

    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail("the egl backend could not make its context current: ", eglErrorText(eglGetError()));
    }

private:
    std::vector<EGLDisplay> candidateDisplays() {
        std::vector<EGLDisplay> displays;
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (getPlatformDisplay && hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
            EGLDeviceEXT devices[16];
            EGLint count = 0;
            if (queryDevices && queryDevices(16, devices, &count))
                for (EGLint i = 0; i < count; ++i)
                    displays.push_back(getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
        }
        if (getPlatformDisplay && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
            displays.push_back(getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
        displays.push_back(eglGetDisplay(EGL_DEFAULT_DISPLAY));
        return displays;
    }

    bool tryDisplay(EGLDisplay display, std::string& attempts) {
        if (display == EGL_NO_DISPLAY) return false;
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) {
            attempts += concat("[initialize: ", eglErrorText(eglGetError()), "] ");
            return false;
        }
        const char* vendor = eglQueryString(display, EGL_VENDOR);
        auto reject = [&](const std::string& why) {
            attempts += concat("[", vendor ? vendor : "?", ": ", why, "] ");
            eglTerminate(display);
            return false;
        };
        if (!eglBindAPI(EGL_OPENGL_API)) return reject("no desktop OpenGL");
        const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configCount = 0;
        const bool noConfigContext = hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context");
        if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0) {
            if (!noConfigContext) return reject("no OpenGL config");
            config = EGL_NO_CONFIG_KHR;
        }
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                            EGL_CONTEXT_MINOR_VERSION, 5,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            EGL_NONE};
        EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
        if (context == EGL_NO_CONTEXT) return reject(concat("no 4.5 core context (", eglErrorText(eglGetError()), ")"));
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            eglDestroyContext(display, context);
            return reject("surfaceless contexts unsupported");
        }
        display_ = display;
        context_ = context;
        return true;
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<Context> createEGLContext(const ContextOptions& options) {
    return std::make_unique<EGLContextImpl>(options);
}

}  // namespace vct::gl
