#include "pipeline/renderer.hpp"

#include "core/error.hpp"

namespace vct {

void validateRenderSettings(const RenderSettings& s) {
    GLint maxTexture = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int maxWidth = std::min(maxTexture, maxViewport[0]);
    const int maxHeight = std::min(maxTexture, maxViewport[1]);
    if (s.width < 1 || s.height < 1 || s.width > maxWidth || s.height > maxHeight)
        fail("image size ", s.width, "x", s.height, " is not possible on this GPU; width and height must be within 1..",
             maxWidth, " and 1..", maxHeight);
    if (s.lightViewResolution < 16 || s.lightViewResolution > maxTexture)
        fail("--light-view-res ", s.lightViewResolution, " is out of range; use 16..", maxTexture);
    if (s.pcfRadius < 0 || s.pcfRadius > 8) fail("--pcf-radius ", s.pcfRadius, " is out of range; use 0..8");
}

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_((validateRenderSettings(settings), settings)),
      gpuScene_(scene),
      gbuffer_(settings.width, settings.height),
      direct_(settings.width, settings.height),
      composite_(settings.width, settings.height) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth in [0,1] (render/view.hpp)
    for (std::size_t i = 0; i < scene.lights.size(); ++i) lightViews_.emplace_back(settings.lightViewResolution);
    gl::checkErrors("creating the renderer's GPU resources");
}

void Renderer::renderFrame(const Camera& camera) {
    const ViewTransform view = cameraView(camera, scene_, settings_.width, settings_.height);
    timer_.beginFrame();
    {
        gl::GpuTimer::Scope pass(timer_, "light_view");
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) lightViews_[i].render(gpuScene_, scene_, scene_.lights[i]);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "gbuffer");
        gbuffer_.render(gpuScene_, view);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "direct_lighting");
        direct_.render(gbuffer_, scene_, scene_.lights, lightViews_, settings_.pcfRadius);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "composite");
        const float depthScale = float(glm::length(scene_.worldBounds.size()));
        composite_.render(gbuffer_, direct_.radiance(), view, depthScale, settings_.display);
    }
    timer_.endFrame();
    gl::checkErrors("rendering a frame");
}

std::vector<MemoryPool> Renderer::memory() const {
    std::vector<MemoryPool> pools = {{"scene geometry and textures", gpuScene_.bytes()},
                                     {"gbuffer", gbuffer_.bytes()},
                                     {"direct radiance", direct_.bytes()},
                                     {"composite output", composite_.bytes()}};
    std::size_t lightBytes = 0;
    for (const auto& map : lightViews_) lightBytes += map.bytes();
    pools.push_back({"light-view maps", lightBytes});
    return pools;
}

}  // namespace vct
