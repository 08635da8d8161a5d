#pragma once
// Dear ImGui on a GLFW window: context, GLFW and OpenGL 3 backends (from Debian's libimgui),
// created and torn down with this object (before the GL context goes away).
struct GLFWwindow;

namespace vct::viewer {

class ImGuiLayer {
public:
    // Installs ImGui's GLFW callbacks, chained to those the window already has. `ignoreMouse`:
    // the panel does not react to the pointer (scripted runs: screenshots must not depend on
    // where the pointer happens to be).
    ImGuiLayer(GLFWwindow* window, bool ignoreMouse);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    void endFrame(bool draw);  // draw = false: build but do not render (panel hidden)

    bool wantsMouse() const;     // the pointer is over a panel or a widget is being dragged
    bool wantsKeyboard() const;  // a text field has the keyboard
};

}  // namespace vct::viewer
