#include "render/indirect_filter.hpp"

#include "core/error.hpp"
#include "gl/compute.hpp"

namespace vct {

void validateGiFilter(float voxels) {
    if (!(voxels >= 0.0f && voxels <= 64.0f))
        fail("--gi-filter ", voxels, " is out of range; use 0 (off) .. 64 voxels (the filter's width along a surface)");
}

int indirectFilterPasses(int height) {
    // n passes reach 2^n − 1 cells.
    int passes = 1;
    while (passes < 12 && (1 << passes) - 1 < height / 3) ++passes;
    return passes;
}

IndirectFilter::IndirectFilter(int width, int height)
    : width_(width),
      height_(height),
      filtered_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "filtered indirect irradiance")),
      scratch_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect filter scratch")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "indirect_filter.comp"}})) {}

GLuint IndirectFilter::render(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, double voxelSize,
                              float voxels) {
    const int passes = indirectFilterPasses(height_);
    // Alternate between the two images so that the last pass writes `filtered_`.
    GLuint source = traced;
    for (int pass = 0; pass < passes; ++pass) {
        const GLuint target = (passes - 1 - pass) % 2 == 0 ? filtered_.id() : scratch_.id();
        gl::ComputeCall(program_)
            .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
            .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
            .texture(gl::TEXTURE_TRACED_IRRADIANCE, source)
            .texture(gl::TEXTURE_TRACED_PIXEL, tracedPixel)
            .image(gl::IMAGE_INDIRECT, target, GL_WRITE_ONLY, GL_RGBA32F)
            .uniform("uDownscale", tracedPixel ? 2 : 1)
            .uniform("uTapSpacing", 1 << pass)
            .uniform("uVoxelScale", float(1.0 / voxelSize))
            .uniform("uSigma", voxels)
            .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        source = target;
    }
    gl::checkErrors("filtering the indirect irradiance");
    return filtered_.id();
}

}  // namespace vct
