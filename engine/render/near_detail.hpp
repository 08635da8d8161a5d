#pragma once
// The near field's detail at every pixel (part of the cone_trace pass, after the cones' light is
// upsampled; shaders/near_detail.comp). The cones' irradiance is traced at one pixel of a block
// and filtered along surfaces over several voxels, so it holds the amount of light a patch of
// surface receives but not how it varies within a voxel or two: the shade inside a crease, under
// a moulding, at a column's foot. Each pixel's visibility within the cones' start offset (the
// near field's test against the G-buffer, a fixed set of directions), divided by its mean over the
// pixel's own surface around it, scales the pixel's irradiance: the light stays where the cones
// put it on average and lands where the near field leaves it open.
#include "gl/objects.hpp"
#include "render/gbuffer.hpp"
#include "render/view.hpp"

namespace vct {

class NearDetail {
public:
    NearDetail(int width, int height);  // the full image's size
    // `indirect`: RGBA32F irradiance and visibility of every pixel. `coneOffset` in voxels (the
    // near field's reach), `voxelSize` in world units; `directRadiance`: the direct light the
    // near field's test reads beside its hits. Returns the detailed image (owned, valid until the
    // next call); its alpha (the cones' visibility) is `indirect`'s.
    GLuint render(const GBuffer& gbuffer, GLuint indirect, GLuint directRadiance, const ViewTransform& view,
                  double voxelSize, float coneOffset);
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t bytes() const { return std::size_t(width_) * height_ * 16 + visibilityBytes(); }

private:
    std::size_t visibilityBytes() const;
    int width_, height_;
    int block_;                   // pixels per side of a visibility cell
    int cellsWide_, cellsHigh_;   // the visibility cells
    gl::Texture visibility_, means_, detailed_;  // per cell: V; (V, V̄); per pixel: the result
    gl::Program visibilityProgram_, meanProgram_, detailProgram_;
};

}  // namespace vct
