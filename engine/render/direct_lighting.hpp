#pragma once
// Direct lighting pass: per pixel, the Lambertian reflection of every light with its shadow
// (PCF over the light-view map's depth). Output: linear radiance, RGBA32F.
#include <vector>

#include "gl/objects.hpp"
#include "render/gbuffer.hpp"
#include "render/light_view.hpp"

namespace vct {

class DirectLighting {
public:
    DirectLighting(int width, int height);
    // `camera` and `sample` (render/pixel_samples.hpp) give each pixel sample's footprint, which
    // the shadow filter spans where it is wider than the filter's texels (shaders/shadow.glsl).
    void render(const GBuffer& gbuffer, const Scene& scene, const std::vector<Light>& lights,
                const LightViewSets& lightViews, int pcfRadius, const ViewTransform& camera, int sample);
    GLuint radiance() const { return radiance_.id(); }
    std::size_t bytes() const { return std::size_t(width_) * height_ * 16; }

private:
    int width_, height_;
    gl::Texture radiance_;
    gl::Program program_;
};

}  // namespace vct
