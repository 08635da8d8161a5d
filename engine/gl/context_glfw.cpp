// GLFW backend: a window with a 4.5 core context, used by the viewer (visible) and for offscreen
// rendering through a real window system (hidden), e.g. under Xvfb.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <string>

#include "core/error.hpp"
#include "gl/context.hpp"

namespace vct::gl {
namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no description";
}

class GLFWContextImpl final : public Context {
public:
    explicit GLFWContextImpl(const ContextOptions& options) {
        if (!glfwInit())
            fail("the glfw backend could not start (", lastGlfwError(),
                 "); it needs a display: set DISPLAY (or run under Xvfb), or use --backend osmesa|egl");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_VISIBLE, options.visibleWindow ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(options.windowWidth, options.windowHeight, options.windowTitle.c_str(), nullptr,
                                   nullptr);
        if (!window_) {
            const std::string why = lastGlfwError();
            glfwTerminate();
            fail("the glfw backend could not open a window with an OpenGL 4.5 core context (", why,
                 "); update the graphics driver or use --backend osmesa|egl");
        }
        makeCurrent();
        initialize("glfw", [](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); },
                   options);
    }
    ~GLFWContextImpl() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    GLFWwindow* window() override { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createGLFWContext(const ContextOptions& options) {
    return std::make_unique<GLFWContextImpl>(options);
}

}  // namespace vct::gl
