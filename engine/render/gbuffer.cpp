#include "render/gbuffer.hpp"

#include <iterator>

#include "core/error.hpp"
#include "gl/raster_state.hpp"
#include "gl/shader.hpp"

namespace vct {
namespace {
constexpr GLenum kColorTargets[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                    GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
constexpr GLsizei kColorTargetCount = GLsizei(std::size(kColorTargets));
}  // namespace

GBuffer::GBuffer(int width, int height)
    : width_(width),
      height_(height),
      albedo_(gl::createTexture2D(GL_RGBA16F, width, height, 1, "gbuffer albedo")),
      normal_(gl::createTexture2D(GL_RGBA16F, width, height, 1, "gbuffer normal")),
      position_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "gbuffer position")),
      emissive_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "gbuffer emissive")),
      geometricNormal_(gl::createTexture2D(GL_RGBA16F, width, height, 1, "gbuffer geometric normal")),
      depth_(gl::createTexture2D(GL_DEPTH_COMPONENT32F, width, height, 1, "gbuffer depth")),
      framebuffer_(gl::createFramebuffer("gbuffer")),
      program_(gl::buildProgram({{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}})) {
    const GLuint fbo = framebuffer_.id();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, albedo_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, normal_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, position_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT3, emissive_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT4, geometricNormal_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glNamedFramebufferDrawBuffers(fbo, kColorTargetCount, kColorTargets);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail("the G-buffer framebuffer is incomplete on this driver (", width, "x", height, ")");
}

std::size_t GBuffer::bytes() const { return std::size_t(width_) * height_ * (8 + 8 + 16 + 16 + 8 + 4); }

void GBuffer::render(const GpuScene& scene, const ViewTransform& camera, float sampleFootprint) {
    gl::beginRasterPass({framebuffer_.id(), width_, height_, true});
    const float zero[4] = {0, 0, 0, 0};
    for (GLint i = 0; i < kColorTargetCount; ++i) glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, zero);  // reversed depth: far = 0
    glUseProgram(program_.id());
    gl::setUniform(program_.id(), "uViewProjection", camera.viewProjection);
    gl::setUniform(program_.id(), "uEye", camera.eye);
    gl::setUniform(program_.id(), "uSampleFootprint", sampleFootprint);
    // Isotropic samplers: every sample filters over its share of the pixel's footprint itself
    // (shaders/material.glsl, footprintTexel).
    scene.draw(program_.id(), GpuScene::Materials::All, GpuScene::Filtering::Isotropic);
    gl::endRasterPass();
}

}  // namespace vct
