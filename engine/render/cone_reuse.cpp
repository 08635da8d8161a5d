#include "render/cone_reuse.hpp"

#include <string>

#include "gl/compute.hpp"

namespace vct {

std::size_t ConeReuse::coneBytes(int width, int height, int rays) {
    return std::size_t(width) * std::size_t(height) * std::size_t(rays) * 32;
}

ConeReuse::ConeReuse(int width, int height, int rays)
    : width_(width),
      height_(height),
      rays_(rays),
      cones_(gl::createBuffer(GLsizeiptr(coneBytes(width, height, rays)), nullptr, 0, "narrow cones of the traced cells")),
      reused_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect irradiance, cones reused")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "cone_reuse.comp"}},
                                {"REUSE_RADIUS " + std::to_string(kConeReuseRadius)})) {}

GLuint ConeReuse::render(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, double voxelSize, float coneOffset,
                         float sigma) {
    gl::ComputeCall(program_)
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, gbuffer.geometricNormal())
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .texture(gl::TEXTURE_TRACED_IRRADIANCE, traced)
        .texture(gl::TEXTURE_TRACED_PIXEL, tracedPixel)
        .storage(gl::SSBO_CONE_SAMPLES, cones_)
        .image(gl::IMAGE_INDIRECT, reused_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .uniform("uDownscale", tracedPixel ? 2 : 1)
        .uniform("uRayCount", rays_)
        .uniform("uVoxelScale", float(1.0 / voxelSize))
        .uniform("uConeOffset", coneOffset)
        .uniform("uReuseVoxels", sigma)
        .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gl::checkErrors("sharing the narrow cones between neighbours");
    return reused_.id();
}

}  // namespace vct
