#include "render/cone_carry.hpp"

namespace vct {

ConeCarry::ConeCarry(int width, int height, int tracedWidth, int tracedHeight)
    : width_(width),
      height_(height),
      tracedWidth_(tracedWidth),
      tracedHeight_(tracedHeight),
      pixelAt_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "points of the pixels' indirect light")),
      pixelNormal_(gl::createTexture2D(GL_RGBA8_SNORM, width, height, 1, "normals of the pixels' indirect light")),
      carriedAt_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "last frame's points of indirect light")),
      carriedNormal_(gl::createTexture2D(GL_RGBA8_SNORM, width, height, 1, "last frame's normals of indirect light")),
      carriedIrradiance_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "last frame's indirect irradiance")),
      carriedFrom_(gl::createTexture2D(GL_R32UI, width, height, 1, "pixels the indirect light is carried from")),
      traceCells_(gl::createBuffer(GLsizeiptr(std::size_t(tracedWidth) * tracedHeight * 4), nullptr, 0, "pixels the listed cells trace")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "cone_carry.comp"}})) {}

std::size_t ConeCarry::bytes() const {
    return std::size_t(width_) * height_ * (16 + 4 + 16 + 4 + 16 + 4) + std::size_t(tracedWidth_) * tracedHeight_ * 4;
}

void ConeCarry::bindCarriedLight(gl::ComputeCall& call) const {
    call.texture(gl::TEXTURE_CARRIED_AT, carriedAt_.id())
        .texture(gl::TEXTURE_CARRIED_NORMAL, carriedNormal_.id())
        .texture(gl::TEXTURE_CARRIED_IRRADIANCE, carriedIrradiance_.id())
        .uniform("uCarry", carries_ ? 1 : 0);
}

void ConeCarry::listCells(const GBuffer& gbuffer, GLuint traced, GLuint tracedPixel, const gl::Buffer& counters,
                          const ConeCarryKey& key, const ViewTransform& view, int rotation, double voxelSize,
                          float maxVoxels) {
    key_ = key;
    viewProjection_ = view.viewProjection;
    carries_ = remembered_ && key == rememberedKey_ && maxVoxels > 0.0f && key.block > 1;
    gl::ComputeCall call(program_);
    bindCarriedLight(call);
    call.uniform("uCarriedViewProjection", rememberedViewProjection_)
        .uniform("uViewProjection", view.viewProjection)
        .uniform("uEye", view.eye)
        // A pixel spans 2 / (P[1][1] · height) per unit of distance in a perspective projection.
        .uniform("uPixelAngle", 2.0f / (view.projection[1][1] * float(view.height)))
        .uniform("uCarryVoxels", maxVoxels)
        .uniform("uCarryCos", kConeCarryCos)
        .uniform("uCarryScale", float(1.0 / voxelSize))
        .uniform("uCarryFrames", kConeCarryFrames)
        .texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .storage(gl::SSBO_TRACE_CELLS, traceCells_)
        .storage(gl::SSBO_CONE_COUNTERS, counters)
        .image(gl::IMAGE_INDIRECT, traced, GL_WRITE_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_TRACED_PIXEL, tracedPixel, GL_WRITE_ONLY, GL_R32UI)
        .image(gl::IMAGE_CARRIED_FROM, carriedFrom_.id(), GL_WRITE_ONLY, GL_R32UI)
        .uniform("uDownscale", key.block)
        .uniform("uRotation", rotation)
        .dispatchImage(tracedWidth_, tracedHeight_,
                       GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                           GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkErrors("listing the cells that trace cones");
}

void ConeCarry::bindCarried(gl::ComputeCall& call) const {
    bindCarriedLight(call);
    call.texture(gl::TEXTURE_CARRIED_FROM, carriedFrom_.id())
        .image(gl::IMAGE_PIXEL_AT, pixelAt_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_PIXEL_NORMAL, pixelNormal_.id(), GL_WRITE_ONLY, GL_RGBA8_SNORM);
}

void ConeCarry::remember(GLuint indirect) {
    // The images were written by shaders: copies must see those writes.
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    auto copy = [&](GLuint from, const gl::Texture& to) {
        glCopyImageSubData(from, GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width_, height_, 1);
    };
    copy(pixelAt_.id(), carriedAt_);
    copy(pixelNormal_.id(), carriedNormal_);
    copy(indirect, carriedIrradiance_);
    remembered_ = true;
    rememberedKey_ = key_;
    rememberedViewProjection_ = viewProjection_;
    gl::checkErrors("keeping the indirect light for the next frame");
}

}  // namespace vct
