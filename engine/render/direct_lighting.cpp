#include "render/direct_lighting.hpp"

#include <cmath>

#include "gl/compute.hpp"
#include "render/light_uniforms.hpp"
#include "render/pixel_samples.hpp"

namespace vct {

DirectLighting::DirectLighting(int width, int height)
    : width_(width),
      height_(height),
      radiance_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "direct radiance")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "direct_lighting.comp"}})) {}

void DirectLighting::render(const GBuffer& gbuffer, const Scene& scene, const std::vector<Light>& lights,
                            const LightViewSets& lightViews, int pcfRadius, const ViewTransform& camera,
                            int sample) {
    // A pixel's width at distance 1 (projection[1][1] = 1 / tan(fovY / 2)); a later, jittered
    // sample's share of the pixel is the one its texture lookups take (pixelSampleFootprint).
    const float pixelWidth = 2.0f / (camera.projection[1][1] * float(camera.height));
    gl::ComputeCall call(program_);
    call.texture(gl::TEXTURE_GBUFFER_ALBEDO, gbuffer.albedo())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .image(gl::IMAGE_DIRECT, radiance_.id(), GL_READ_WRITE, GL_RGBA32F)
        .uniform("uPcfRadius", pcfRadius)
        .uniform("uCameraEye", camera.eye)
        .uniform("uPixelWidth", pixelWidth)
        .uniform("uSampleFootprint", pixelSampleFootprint(sample));
    if (lights.empty()) {
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(radiance_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    }
    bool first = true;
    for (std::size_t i = 0; i < lights.size(); ++i)
        for (const LightViewMap& map : lightViews[i]) {
            setLightUniforms(call.program(), lights[i], scene, map.face());
            call.texture(gl::TEXTURE_SHADOW_MAP, map.shadowMap())
                .uniform("uLightViewProjection", map.transform().view.viewProjection)
                .uniform("uShadowTexelSize", map.shadowTexelWorldSize())
                .uniform("uShadowPerspective", map.transform().perspective ? 1 : 0)
                .uniform("uAccumulate", first ? 0 : 1)
                .dispatchImage(width_, height_, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
            first = false;
        }
}

}  // namespace vct
