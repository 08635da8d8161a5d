#include "render/composite.hpp"

#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "gl/compute.hpp"

namespace vct {

Aov parseAov(const std::string& name) {
    if (name == "final") return Aov::Final;
    if (name == "direct") return Aov::Direct;
    if (name == "albedo") return Aov::Albedo;
    if (name == "normal") return Aov::Normal;
    if (name == "depth") return Aov::Depth;
    if (name == "indirect") return Aov::Indirect;
    if (name == "ao") return Aov::Ao;
    if (name == "gi") return Aov::Gi;
    fail("unknown --aov '", name, "'; use final, direct, gi, indirect, ao, albedo, normal or depth");
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
        case Aov::Gi: return "gi";
    }
    return "?";
}

Composite::Composite(int width, int height)
    : width_(width),
      height_(height),
      hdr_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "composite hdr")),
      hdrSum_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "composite hdr sum")),
      indirectSum_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "composite indirect sum")),
      ldr_(gl::createTexture2D(GL_RGBA8, width, height, 1, "composite ldr")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "composite.comp"}})) {}

void Composite::render(const GBuffer& gbuffer, GLuint directRadiance, GLuint indirect, const ViewTransform& camera,
                       float depthScale, const DisplaySettings& display, int samplesInAverage,
                       float indirectWeight, GLuint debugImage, bool toneMapDebugImage) {
    gl::ComputeCall(program_)
        .texture(gl::TEXTURE_GBUFFER_ALBEDO, gbuffer.albedo())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .texture(gl::TEXTURE_GBUFFER_EMISSIVE, gbuffer.emissive())
        .texture(gl::TEXTURE_DIRECT, directRadiance)
        .texture(gl::TEXTURE_DEBUG_IMAGE, debugImage)
        .texture(gl::TEXTURE_INDIRECT, indirect)
        .image(gl::IMAGE_HDR, hdr_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_LDR, ldr_.id(), GL_WRITE_ONLY, GL_RGBA8)
        .image(gl::IMAGE_HDR_SUM, hdrSum_.id(), GL_READ_WRITE, GL_RGBA32F)
        .image(gl::IMAGE_INDIRECT_SUM, indirectSum_.id(), GL_READ_WRITE, GL_RGBA32F)
        .uniform("uSamplesInAverage", samplesInAverage)
        .uniform("uIndirectWeight", indirectWeight)
        .uniform("uHasIndirect", indirect != 0 ? 1 : 0)
        .uniform("uGiScale", display.giScale)
        .uniform("uShowDebugImage", debugImage == 0 ? 0 : (toneMapDebugImage ? 2 : 1))
        .uniform("uAov", int(display.aov))
        .uniform("uExposure", float(std::exp2(display.exposureEV)))
        .uniform("uToneCurve", int(display.toneCurve))
        .uniform("uEye", camera.eye)
        .uniform("uForward", camera.forward)
        .uniform("uDepthScale", depthScale)
        .dispatchImage(width_, height_,
                       GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
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
