#pragma once
// `vct view`: a GLFW window with a 4.5 core context, the full pipeline rendered every frame by
// vct::Renderer, and on top of it only input, the ImGui panel and presentation.
#include <filesystem>
#include <optional>
#include <string>

#include "pipeline/renderer.hpp"
#include "scene/scene.hpp"
#include "viewer/input_script.hpp"

namespace vct::viewer {

struct ViewerOptions {
    int windowWidth = 1280;
    int windowHeight = 720;
    float renderScale = 1.0f;                   // render resolution / window resolution
    std::filesystem::path screenshotDir = ".";  // where F12 writes vct_view_NNNN.png
};

// Throws a clear vct::Error unless a window system is reachable (DISPLAY or WAYLAND_DISPLAY set)
// and the options are in range; cheap, so `vct view` checks before loading a large scene.
void checkViewerOptions(const ViewerOptions& options);

// Runs until Esc, the window is closed or the script (nullopt: interactive) ends. `settings`
// width/height are ignored (the window decides). Throws vct::Error for what the user can fix.
void runViewer(const Scene& scene, const Camera& startCamera, const RenderSettings& settings,
               const ViewerOptions& options, std::optional<InputScript> script);

}  // namespace vct::viewer
