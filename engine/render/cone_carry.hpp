#pragma once
// Indirect light carried over camera moves (part of the cone_trace pass, DESIGN §4 pass 12;
// `--cone-carry`). The indirect irradiance of a surface point does not depend on the camera, and
// when only the camera moves most of the surfaces in view stay in view: a pixel whose surface point
// a pixel of the last frame saw takes that pixel's light (shaders/pixel_carry.glsl, in
// cone_upsample.comp), and a block of pixels that all take it traces no cones (cone_carry.comp,
// which lists the cells cone_trace.comp traces). The light a pixel takes keeps the point it was
// estimated at, so it never stands for light farther than a fraction of a voxel plus a pixel from
// there, however long it is carried. A change of anything but the camera (geometry, materials,
// lights, any setting) traces every block again, as do the later samples of an accumulated frame
// and GI traced at every pixel (`--gi-resolution full`: no upsampling to carry in).
//
// Light is carried for a frame or two, not for as long as its surface stays in view: the light a
// frame estimates where a surface has just come into view (beside the edge of what hid it, at the
// image's border) has the filter and the upsampling on one side only, and kept for many frames
// such estimates came to make up more and more of the image (docs/benchmark.md).
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "gl/compute.hpp"
#include "gl/objects.hpp"
#include "render/gbuffer.hpp"
#include "render/view.hpp"

namespace vct {

// How far (voxels), beyond a pixel's footprint, the point a pixel's carried light was estimated at
// may lie from the pixel's own point; and how alike their normals must be (cos). Irradiance varies
// on the scale of voxels (the edge-aware filter and the shared cones already average over several),
// so half a voxel keeps carried light well inside what a freshly traced frame mixes anyway.
constexpr float kDefaultConeCarryVoxels = 0.5f;
constexpr float kConeCarryCos = 0.95f;
// The most frames a pixel's light is carried before it is estimated anew: the light of each
// surface point goes on for 1 or 2 frames, by a hash of its voxel, so that about half of a view's
// light is estimated anew in every frame rather than all of it in one. Over 40 small camera steps
// on CameraMain it kept the indirect error within a few percent of fresh frames' for about 60 % of
// their cone tracing; light carried for as long as it stayed in view ended 50 % further from the
// path tracer (docs/benchmark.md).
constexpr int kConeCarryFrames = 2;

// What the light of a frame was traced for: the traced blocks and a version of everything else the
// cones saw, which changes whenever any input but the camera does (frame_passes.cpp).
struct ConeCarryKey {
    int block = 0;  // pixels per side of a traced block
    std::uint64_t sceneVersion = 0;
    bool operator==(const ConeCarryKey&) const = default;
};

class ConeCarry {
public:
    // The image's size and the traced image's (one cell per block).
    ConeCarry(int width, int height, int tracedWidth, int tracedHeight);

    // Lists the cells of the traced image that trace cones this frame, by the pixel each traces
    // (SSBO_TRACE_CELLS, its length in `counters`), and writes every cell's pixel to `tracedPixel`
    // (in blocks; 0: every pixel a cell) and the others into `traced` (RGBA32F): sky, or the
    // carried light of their pixel (CARRIED_CELL). The last remembered frame's light is carried
    // when `key` is its key and `maxVoxels` > 0 (in blocks only). `rotation` turns which pixel of
    // a block traces (the pixel sample).
    void listCells(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, const gl::Buffer& counters,
                   const ConeCarryKey& key, const ViewTransform& view, int rotation, double voxelSize, float maxVoxels);
    // Binds what cone_upsample.comp reads and writes for the carried light (carried_light.glsl, and
    // the pixel each pixel takes it from, which listCells found).
    void bindCarried(gl::ComputeCall& call) const;
    // Keeps this frame's indirect image, and the points and normals its pixels' light belongs to,
    // for the next frame (after cone_upsample.comp and the pixels' own traces).
    void remember(GLuint indirect);

    // The pixels cone_trace.comp traces, one per listed cell (its length in the counters).
    const gl::Buffer& traceCells() const { return traceCells_; }
    bool carries() const { return carries_; }
    int tracedWidth() const { return tracedWidth_; }
    int tracedHeight() const { return tracedHeight_; }
    std::size_t bytes() const;

private:
    // The last frame's light as shaders/carried_light.glsl reads it.
    void bindCarriedLight(gl::ComputeCall& call) const;

    int width_, height_, tracedWidth_, tracedHeight_;
    gl::Texture pixelAt_, pixelNormal_;                          // this frame's
    gl::Texture carriedAt_, carriedNormal_, carriedIrradiance_;  // the remembered frame's
    gl::Texture carriedFrom_;  // the last frame's pixel each pixel takes light from (cone_carry.comp)
    gl::Buffer traceCells_;
    gl::Program program_;
    bool remembered_ = false, carries_ = false;
    ConeCarryKey rememberedKey_, key_;
    glm::mat4 rememberedViewProjection_{1.0f}, viewProjection_{1.0f};
};

}  // namespace vct
