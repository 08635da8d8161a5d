#include "render/composite.hpp"

#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "gl/shader.hpp"

namespace vct {

Aov parseAov(const std::string& name) {
    if (name == "final") return Aov::Final;
    if (name == "direct") return Aov::Direct;
    if (name == "albedo") return Aov::Albedo;
    if (name == "normal") return Aov::Normal;
    if (name == "depth") return Aov::Depth;
    if (name == "indirect") return Aov::Indirect;
    if (name == "ao") return Aov::Ao;
    fail("unknown --aov '", name, "'; use final, direct, indirect, ao, albedo, normal or depth");
}

const char* aovName(Aov aov) {
    switch (aov) {
        case Aov::Final: return "final";
        case Aov::Direct: return "direct";
        case Aov::Albedo: return "albedo";
        case Aov::Normal: return "normal";
        case Aov::Depth: return "depth";
        case Aov::Indirect: return "indirect";
        case Aov::Ao: return "ao";
    }
    return "?";
}

Composite::Composite(int width, int height)
    : width_(width),
      height_(height),
      hdr_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "composite hdr")),
      ldr_(gl::createTexture2D(GL_RGBA8, width, height, 1, "composite ldr")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "composite.comp"}})) {}

void Composite::render(const GBuffer& gbuffer, GLuint directRadiance, GLuint indirect, const ViewTransform& camera,
                       float depthScale, const DisplaySettings& display, GLuint debugImage, bool toneMapDebugImage) {
    const GLuint p = program_.id();
    glUseProgram(p);
    glBindTextureUnit(0, gbuffer.albedo());
    glBindTextureUnit(1, gbuffer.normal());
    glBindTextureUnit(2, gbuffer.position());
    glBindTextureUnit(3, gbuffer.emissive());
    glBindTextureUnit(4, directRadiance);
    glBindTextureUnit(5, debugImage);
    glBindTextureUnit(6, indirect);
    gl::setUniform(p, "uHasIndirect", indirect != 0 ? 1 : 0);
    gl::setUniform(p, "uGiScale", display.giScale);
    gl::setUniform(p, "uShowDebugImage", debugImage == 0 ? 0 : (toneMapDebugImage ? 2 : 1));
    glBindImageTexture(0, hdr_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, ldr_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    gl::setUniform(p, "uAov", int(display.aov));
    // 2^EV in float: beyond ±kMaxExposureEV it is 0 or Inf and the tone-mapped image garbage.
    if (!std::isfinite(display.exposureEV) || std::abs(display.exposureEV) > kMaxExposureEV)
        fail("exposure ", display.exposureEV, " EV must be a finite number of stops within ±", kMaxExposureEV);
    gl::setUniform(p, "uExposure", float(std::exp2(display.exposureEV)));
    gl::setUniform(p, "uToneCurve", int(display.toneCurve));
    gl::setUniform(p, "uEye", camera.eye);
    gl::setUniform(p, "uForward", camera.forward);
    gl::setUniform(p, "uDepthScale", depthScale);
    glDispatchCompute(GLuint((width_ + 7) / 8), GLuint((height_ + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

namespace {
template <class Image, class T>
Image readTexture(GLuint texture, int width, int height, GLenum type) {
    Image image(width, height);
    std::vector<T> raw(image.rgba.size());
    glGetTextureImage(texture, 0, GL_RGBA, type, GLsizei(raw.size() * sizeof(T)), raw.data());
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)  // GL rows run bottom to top
        std::memcpy(&image.rgba[row * y], &raw[row * (height - 1 - y)], row * sizeof(T));
    return image;
}
}  // namespace

ImageF Composite::readHdr() const { return readTexture<ImageF, float>(hdr_.id(), width_, height_, GL_FLOAT); }
Image8 Composite::readLdr() const {
    return readTexture<Image8, std::uint8_t>(ldr_.id(), width_, height_, GL_UNSIGNED_BYTE);
}

}  // namespace vct
