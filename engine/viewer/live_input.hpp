#pragma once
// Collects the window's keyboard and mouse events into one FrameInput per frame. Events the
// panel consumes (typing into a field, dragging a slider, the wheel over the panel) are not
// passed on; losing focus ends a drag, and the window system releases held keys.
#include "viewer/frame_input.hpp"

struct GLFWwindow;

namespace vct::viewer {

class LiveInput {
public:
    // Installs the GLFW callbacks; create it before the ImGui layer, which chains to them.
    explicit LiveInput(GLFWwindow* window);
    ~LiveInput();
    LiveInput(const LiveInput&) = delete;
    LiveInput& operator=(const LiveInput&) = delete;

    // Whether the panel wanted the mouse / keyboard in the frame just drawn.
    void setUiCapture(bool mouse, bool keyboard) {
        uiMouse_ = mouse;
        uiKeyboard_ = keyboard;
    }
    // The events since the last call, plus the keys held now.
    FrameInput collect();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onFocus(GLFWwindow* window, int focused);

    GLFWwindow* window_;
    FrameInput pending_;
    bool uiMouse_ = false, uiKeyboard_ = false;
    bool dragging_ = false;
    double cursorX_ = 0.0, cursorY_ = 0.0;
};

}  // namespace vct::viewer
