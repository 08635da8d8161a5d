#include "viewer/live_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>

#include "core/error.hpp"
#include "viewer/key_bindings.hpp"

namespace vct::viewer {
namespace {
LiveInput* instance = nullptr;  // GLFW callbacks are plain functions; one viewer window per process
}

LiveInput::LiveInput(GLFWwindow* window) : window_(window) {
    if (instance) fail("only one viewer window per process (engine bug)");
    instance = this;
    glfwSetKeyCallback(window, onKey);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetScrollCallback(window, onScroll);
    glfwSetWindowFocusCallback(window, onFocus);
    glfwGetCursorPos(window, &cursorX_, &cursorY_);
}

LiveInput::~LiveInput() {
    glfwSetKeyCallback(window_, nullptr);
    glfwSetMouseButtonCallback(window_, nullptr);
    glfwSetCursorPosCallback(window_, nullptr);
    glfwSetScrollCallback(window_, nullptr);
    glfwSetWindowFocusCallback(window_, nullptr);
    instance = nullptr;
}

FrameInput LiveInput::collect() {
    FrameInput input = std::exchange(pending_, {});
    if (!uiKeyboard_ && glfwGetWindowAttrib(window_, GLFW_FOCUSED))
        for (int key : kHeldKeys)
            if (glfwGetKey(window_, key) == GLFW_PRESS) input.held.push_back(key);
    return input;
}

void LiveInput::onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (!instance || action == GLFW_RELEASE || instance->uiKeyboard_) return;
    if (action == GLFW_REPEAT) {
        // Auto-repeat steps through octree levels; it must not flicker a toggle held a bit long.
        const Action repeated = actionFor({key, mods});
        if (repeated != Action::CoarserLevel && repeated != Action::FinerLevel) return;
    }
    instance->pending_.presses.push_back({key, mods});
}

void LiveInput::onMouseButton(GLFWwindow* window, int button, int action, int) {
    if (!instance || button != GLFW_MOUSE_BUTTON_LEFT) return;
    if (action == GLFW_PRESS && !instance->uiMouse_) {
        instance->dragging_ = true;
        glfwGetCursorPos(window, &instance->cursorX_, &instance->cursorY_);
    }
    if (action == GLFW_RELEASE) instance->dragging_ = false;
}

void LiveInput::onCursor(GLFWwindow*, double x, double y) {
    if (!instance) return;
    if (instance->dragging_) {
        instance->pending_.dragX += x - instance->cursorX_;
        instance->pending_.dragY += y - instance->cursorY_;
    }
    instance->cursorX_ = x;
    instance->cursorY_ = y;
}

void LiveInput::onScroll(GLFWwindow*, double, double dy) {
    if (!instance || instance->uiMouse_) return;
    instance->pending_.scroll += dy;
}

void LiveInput::onFocus(GLFWwindow*, int focused) {
    if (!instance || focused) return;
    instance->dragging_ = false;  // the button release may go to another window
}

}  // namespace vct::viewer
