#pragma once
// `vct view`: a GLFW window with a 4.5 core context, the full pipeline rendered every frame by
// vct::Renderer, and on top of it only input, the ImGui panel and presentation.
#include <filesystem>
#include <optional>
#include <string>

#include "pipeline/renderer.hpp"
#include "scene/scene.hpp"

namespace vct::viewer {

struct ViewerOptions {
    int windowWidth = 1280;
    int windowHeight = 720;
    float renderScale = 1.0f;                   // render resolution / window resolution
    std::filesystem::path script;               // empty: interactive
    std::filesystem::path screenshotDir = ".";  // where F12 writes vct_view_NNNN.png
};

// Runs until Esc, the window is closed or the script ends. `settings` width/height are ignored
// (the window decides). Throws vct::Error for what the user can fix (no display, bad script).
void runViewer(const Scene& scene, const Camera& startCamera, const RenderSettings& settings,
               const ViewerOptions& options);

}  // namespace vct::viewer
