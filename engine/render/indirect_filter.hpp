#pragma once
// The cones' edge-aware filter (part of the cone_trace pass, DESIGN §4 pass 12): the cones read
// the octree's levels, so their result steps where a sample crosses a node's face; those steps
// (blocks a few voxels wide) are error against the path tracer, while irradiance along one surface
// varies slowly. The filter fits each traced point's irradiance to the traced points on its own
// surface within a few voxels (a plane by weighted least squares; world distance, normal and
// tangent plane weight them: shaders/indirect_filter.comp) and leaves other surfaces alone. It
// runs on the image the cones traced, before cones traced in blocks are upsampled, so it costs a
// quarter (2×2 blocks) or a sixteenth (4×4) there.
#include "gl/objects.hpp"
#include "render/gbuffer.hpp"

namespace vct {

// The filter's width along a surface (σ of its Gaussian, voxels); 0: off. Eight voxels: the four
// narrow cones of a traced pixel leave noise on the scale of the traced blocks, which four voxels
// left on flat walls (docs/benchmark.md, "The edge-aware filter").
constexpr float kDefaultGiFilterVoxels = 8.0f;
// Throws naming the option when `voxels` is outside 0..64.
void validateGiFilter(float voxels);

// Filter passes for a traced image `height` cells high: each pass doubles the tap spacing of a
// 3×3 kernel (à trous), and the passes reach about a third of the image from each cell at any
// resolution, so a Gaussian of a few voxels is not cut short where voxels are many pixels wide.
int indirectFilterPasses(int height);

class IndirectFilter {
public:
    IndirectFilter(int width, int height);  // the traced image's size
    // Filters `traced` (RGBA32F: irradiance, visibility per traced cell) with a Gaussian of
    // `voxels` voxels along the surfaces of `gbuffer`; `tracedPixel` (0: each cell is its pixel)
    // names the pixel each cell traced in blocks. `voxelSize` in world units. Returns the
    // filtered image (owned by the filter, valid until the next call).
    GLuint render(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, double voxelSize, float voxels);
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t bytes() const { return std::size_t(width_) * height_ * 16 * 2; }

private:
    int width_, height_;
    gl::Texture filtered_, scratch_;
    gl::Program program_;
};

}  // namespace vct
