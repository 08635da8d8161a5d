#include "render/near_detail.hpp"

#include <algorithm>

#include "gl/compute.hpp"
#include "render/cone_trace.hpp"

namespace vct {

namespace {
// Pixels per side of a visibility cell: the visibility is followed at every pixel below 360 lines
// and at one of each 2×2 block from there up, where the cones are traced in 4×4 blocks: the same
// share of the image per cell as at 320×180, a quarter of the cost.
int visibilityBlock(int width, int height) { return std::min(width, height) >= kQuarterResolutionLines ? 2 : 1; }
// The mean of the visibility is taken over taps this many pixels apart: three at 180 lines, and in
// proportion above, so that the patch it averages covers the same share of the image at any size.
int tapSpacingPixels(int height) { return 3 * std::max(1, height / 180); }
}  // namespace

NearDetail::NearDetail(int width, int height)
    : width_(width),
      height_(height),
      block_(visibilityBlock(width, height)),
      cellsWide_((width + block_ - 1) / block_),
      cellsHigh_((height + block_ - 1) / block_),
      visibility_(gl::createTexture2D(GL_R32F, cellsWide_, cellsHigh_, 1, "near-field visibility")),
      means_(gl::createTexture2D(GL_RG32F, cellsWide_, cellsHigh_, 1, "near-field visibility and its mean")),
      detailed_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect irradiance with the near field's detail")),
      visibilityProgram_(gl::buildProgram({{GL_COMPUTE_SHADER, "near_detail.comp"}}, {"NEAR_VISIBILITY 1"})),
      meanProgram_(gl::buildProgram({{GL_COMPUTE_SHADER, "near_detail.comp"}}, {"NEAR_MEAN 1"})),
      detailProgram_(gl::buildProgram({{GL_COMPUTE_SHADER, "near_detail.comp"}})) {}

std::size_t NearDetail::visibilityBytes() const {
    return std::size_t(cellsWide_) * cellsHigh_ * (4 + 8);
}

GLuint NearDetail::render(const GBuffer& gbuffer, GLuint indirect, GLuint directRadiance, const ViewTransform& view,
                          double voxelSize, float coneOffset) {
    const float voxelScale = float(1.0 / voxelSize);
    gl::ComputeCall(visibilityProgram_)
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, gbuffer.geometricNormal())
        .texture(gl::TEXTURE_NEAR_FIELD_DIRECT, directRadiance)
        .texture(gl::TEXTURE_NEAR_FIELD_EMISSIVE, gbuffer.emissive())
        .image(gl::IMAGE_NEAR_VISIBILITY, visibility_.id(), GL_WRITE_ONLY, GL_R32F)
        .uniform("uVoxelScale", voxelScale)
        .uniform("uConeOffset", coneOffset)
        .uniform("uViewProjection", view.viewProjection)
        .uniform("uEye", view.eye)
        .uniform("uBlock", block_)
        .dispatchImage(cellsWide_, cellsHigh_, GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::ComputeCall(meanProgram_)
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_NEAR_VISIBILITY, visibility_.id())
        .image(gl::IMAGE_NEAR_VISIBILITY, means_.id(), GL_WRITE_ONLY, GL_RG32F)
        .uniform("uVoxelScale", voxelScale)
        .uniform("uBlock", block_)
        .uniform("uTapSpacing", std::max(1, tapSpacingPixels(height_) / block_))
        .dispatchImage(cellsWide_, cellsHigh_, GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::ComputeCall(detailProgram_)
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_NEAR_VISIBILITY, means_.id())
        .texture(gl::TEXTURE_INDIRECT, indirect)
        .image(gl::IMAGE_INDIRECT, detailed_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .uniform("uVoxelScale", voxelScale)
        .uniform("uBlock", block_)
        .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gl::checkErrors("adding the near field's detail to the indirect irradiance");
    return detailed_.id();
}

}  // namespace vct
