#pragma once
// What the user controls in the viewer, edited by keys (viewer_app), the panel (ui_panel) and
// scripts alike. The renderer is told only when something differs from what it has.
#include <string>
#include <vector>

#include "pipeline/renderer.hpp"
#include "scene/light.hpp"

namespace vct::viewer {

struct ViewerState {
    RenderSettings settings;      // width/height follow the window × renderScale
    std::vector<Light> lights;
    float renderScale = 1.0f;     // render resolution / window resolution
    // While nothing changes, frames jittered inside the pixel are averaged, up to this many
    // (1 = off); any change starts again from one sample.
    int accumulateSamples = 64;
    bool panelVisible = true;
    int cameraPreset = -1;        // set by the panel: jump to Scene::cameras[i] (-1 = no request)
    bool screenshotRequested = false;
    std::string status;           // last message (screenshot path, rejected setting)
};

}  // namespace vct::viewer
