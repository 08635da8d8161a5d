#pragma once
// The Dear ImGui panel (F1): frame time, per-pass GPU/CPU milliseconds as a table and a rolling
// graph, which passes ran this frame or were skipped and why, the memory of every GPU pool, and
// the settings, editable (edits land in ViewerState; the app hands them to the renderer).
#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/viewer_state.hpp"

namespace vct::viewer {

struct PanelInputs {
    const Scene& scene;
    const Renderer& renderer;
    const FrameStats& stats;
    const CameraController& camera;
    const gl::ContextInfo& context;
    int windowWidth = 0, windowHeight = 0;
    bool idle = false;  // this frame ran no pass: the viewer waits for input instead of redrawing
};

struct PanelEdits {
    bool settings = false;  // state.settings changed
    bool lights = false;    // state.lights changed
};

class UiPanel {
public:
    // Call between ImGuiLayer::beginFrame and endFrame.
    PanelEdits draw(ViewerState& state, const PanelInputs& in);

private:
    void expensiveSection(ViewerState& state, bool& changed);
    int levels_ = 0;     // slider values while being dragged
    float scale_ = 1.0f;
};

}  // namespace vct::viewer
