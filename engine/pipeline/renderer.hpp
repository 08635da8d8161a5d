#pragma once
// One frame of vct, pass by pass, each bracketed by the GPU timer. The command line (`vct
// render`), the viewer and the tests all render through this class, so they share one pipeline.
//
// Passes today (DESIGN §4): light_view (per light), gbuffer, direct_lighting, composite.
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "gl/gpu_timer.hpp"
#include "render/composite.hpp"
#include "render/direct_lighting.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view.hpp"
#include "scene/scene.hpp"

namespace vct {

struct RenderSettings {
    int width = 1280;
    int height = 720;
    int lightViewResolution = 2048;  // texels per side of each light-view (shadow) map
    int pcfRadius = 1;               // shadow filter: (2r+1)² hardware-bilinear taps
    DisplaySettings display;
};

// Throws a clear error when the settings cannot work on this context (size 0, beyond GL limits).
void validateRenderSettings(const RenderSettings& settings);

struct MemoryPool {
    std::string name;
    std::size_t bytes = 0;
};

class Renderer {
public:
    Renderer(const Scene& scene, const RenderSettings& settings);

    void renderFrame(const Camera& camera);
    ImageF readHdr() const { return composite_.readHdr(); }
    Image8 readLdr() const { return composite_.readLdr(); }
    GLuint outputTexture() const { return composite_.ldr(); }

    gl::GpuTimer& timer() { return timer_; }
    std::vector<MemoryPool> memory() const;
    const RenderSettings& settings() const { return settings_; }
    void setDisplay(const DisplaySettings& display) { settings_.display = display; }

private:
    const Scene& scene_;
    RenderSettings settings_;
    GpuScene gpuScene_;
    GBuffer gbuffer_;
    std::vector<LightViewMap> lightViews_;
    DirectLighting direct_;
    Composite composite_;
    gl::GpuTimer timer_;
};

}  // namespace vct
