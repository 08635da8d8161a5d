#pragma once
// Narrow cones shared between neighbouring traced pixels (part of the cone_trace pass, DESIGN §4
// pass 12; `--cone-reuse`): cone_trace.comp keeps every narrow cone of each traced cell, and
// shaders/cone_reuse.comp estimates each cell's irradiance from the cones of the cells around it
// as well as its own, weighted by the density with which the window drew each direction. It runs
// on the traced image, before the edge-aware filter (render/indirect_filter.hpp).
#include <cstddef>

#include "gl/objects.hpp"
#include "render/gbuffer.hpp"

namespace vct {

// The window's radius in traced cells (REUSE_RADIUS in the shader): 3×3 cells gave less of the
// gain, 7×7 no more than 5×5, at a cost that grows with the fourth power of the window's side.
constexpr int kConeReuseRadius = 2;
// The reused cones are kept per traced cell (32 bytes each); beyond this much memory the pixels
// keep their own cones (64 narrow cones at every pixel of a 1080p image would need 4 GiB).
constexpr std::size_t kMaxConeReuseBytes = std::size_t(512) << 20;

class ConeReuse {
public:
    // The bytes that `rays` cones of each cell of a width × height traced image take.
    static std::size_t coneBytes(int width, int height, int rays);

    ConeReuse(int width, int height, int rays);  // the traced image's size, the cones per cell
    // Where cone_trace.comp stores every cell's cones (SSBO_CONE_SAMPLES).
    const gl::Buffer& cones() const { return cones_; }
    // Each cell of `traced` (RGBA32F: irradiance, visibility) from the stored cones of its window;
    // `tracedPixel` (0: each cell is its pixel) names the pixel each cell traced in blocks.
    // `voxelSize` in world units, `coneOffset` (the cones' start off their surface) and `sigma`
    // (the neighbours' weight over their distance) in voxels. Returns the image (owned by this,
    // valid until the next call).
    GLuint render(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, double voxelSize, float coneOffset,
                  float sigma);
    int width() const { return width_; }
    int height() const { return height_; }
    int rays() const { return rays_; }
    std::size_t bytes() const { return coneBytes(width_, height_, rays_) + std::size_t(width_) * height_ * 16; }

private:
    int width_, height_, rays_;
    gl::Buffer cones_;
    gl::Texture reused_;
    gl::Program program_;
};

}  // namespace vct
