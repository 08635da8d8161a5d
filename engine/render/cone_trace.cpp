#include "render/cone_trace.hpp"

#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

ConeTrace::ConeTrace(int width, int height)
    : width_(width),
      height_(height),
      indirect_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect irradiance")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "cone_trace.comp"}})),
      counters_(gl::createBuffer(32, nullptr, GL_DYNAMIC_STORAGE_BIT, "cone counters")) {}

ConeStatistics ConeTrace::statistics() const {
    std::uint32_t c[8] = {};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof c, c);
    auto join = [&](int i) { return std::uint64_t(c[i]) | (std::uint64_t(c[i + 1]) << 32); };
    return {join(0), join(2), join(4), join(6)};
}

std::size_t ConeTrace::bytes() const {
    const std::size_t full = std::size_t(width_) * height_ * 16;
    const std::size_t blocks = std::size_t((width_ + 1) / 2) * ((height_ + 1) / 2);
    return full + (traced_.id() ? blocks * (16 + 4) : 0) + (filter_ ? filter_->bytes() : 0);
}

GiResolution parseGiResolution(const std::string& name) {
    if (name == "full") return GiResolution::Full;
    if (name == "half") return GiResolution::Half;
    fail("unknown --gi-resolution '", name, "'; use full (cones at every pixel) or half (at one pixel of each 2x2 block)");
}

const char* giResolutionName(GiResolution resolution) { return resolution == GiResolution::Half ? "half" : "full"; }

void validateConeSettings(const ConeSettings& s) {
    makeConeSet(s.cones);  // throws for an unknown set
    if (!(s.apertureScale > 0.0f && s.apertureScale <= 4.0f))
        fail("--cone-aperture ", s.apertureScale, " is out of range; use a factor in (0, 4]");
    if (!(s.step >= 0.05f && s.step <= 4.0f))
        fail("--cone-step ", s.step, " is out of range; use 0.05..4 (fraction of the cone diameter)");
    if (!(s.offset >= 0.0f && s.offset <= 16.0f))
        fail("--cone-offset ", s.offset, " is out of range; use 0..16 voxels");
    if (!(s.lift >= 0.0f && s.lift <= 4.0f))
        fail("--cone-lift ", s.lift, " is out of range; use 0..4 (normal offset per unit of cone diameter)");
    if (!(s.maxDistance >= 0.0f) || !std::isfinite(s.maxDistance))
        fail("cone maximum distance ", s.maxDistance, " must be a finite number ≥ 0 (0: the whole volume)");
}

void setConeMarchUniforms(gl::ComputeCall& call, const Octree& octree, const RadianceVolume& radiance,
                          const ConeSettings& settings) {
    const std::vector<Cone> cones = makeConeSet(settings.cones);
    std::vector<glm::vec3> directions;
    std::vector<float> tangents, weights;
    for (const Cone& c : cones) {
        directions.push_back(c.direction);
        // Wider than ~80° a cone reaches the coarsest level within a step or two. (The single
        // cone's half-angle is π/2, whose float tangent is a huge negative number.)
        tangents.push_back(std::min(std::tan(std::min(c.halfAngle, 1.5f)) * settings.apertureScale, 5.0f));
        weights.push_back(c.weight);
    }
    const GLuint p = call.program();
    octree.bind(p);
    setBrickPoolUniforms(p, octree);
    bindDirectionalTexture(call, radiance);
    glProgramUniform3fv(p, glGetUniformLocation(p, "uConeDirection"), GLsizei(cones.size()), &directions[0].x);
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeTanHalfAngle"), GLsizei(cones.size()), tangents.data());
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeWeight"), GLsizei(cones.size()), weights.data());
    const float diagonal = float(octree.grid.resolution()) * 1.7320508f;
    call.uniform("uConeCount", int(cones.size()))
        .uniform("uConeStep", settings.step)
        .uniform("uConeOffset", settings.offset)
        .uniform("uConeLift", settings.lift)
        .uniform("uMaxDistance", settings.maxDistance > 0.0f ? settings.maxDistance : diagonal)
        .uniform("uUseBricks", settings.bricks ? 1 : 0)
        .uniform("uVoxelOrigin", glm::vec3(octree.grid.localMin))
        .uniform("uVoxelScale", float(1.0 / octree.grid.voxelSize));
}

void ConeTrace::render(const GBuffer& gbuffer, const Octree& octree, const RadianceVolume& radiance,
                       const ConeSettings& settings, GiResolution resolution, int rotation, float filterVoxels) {
    const bool half = resolution == GiResolution::Half;
    const int tracedWidth = half ? (width_ + 1) / 2 : width_, tracedHeight = half ? (height_ + 1) / 2 : height_;
    if (half && !traced_.id()) {
        traced_ = gl::createTexture2D(GL_RGBA32F, tracedWidth, tracedHeight, 1, "indirect irradiance, traced blocks");
        tracedPixel_ = gl::createTexture2D(GL_R32UI, tracedWidth, tracedHeight, 1, "traced pixel of each block");
        upsampleProgram_ = gl::buildProgram({{GL_COMPUTE_SHADER, "cone_upsample.comp"}});
    }
    const std::uint32_t zero = 0;
    glClearNamedBufferData(counters_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

    gl::ComputeCall trace(program_);
    setConeMarchUniforms(trace, octree, radiance, settings);
    trace.texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
        .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, gbuffer.geometricNormal())
        .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
        .storage(gl::SSBO_CONE_COUNTERS, counters_)
        .image(gl::IMAGE_INDIRECT, half ? traced_.id() : indirect_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_TRACED_PIXEL, half ? tracedPixel_.id() : 0, GL_WRITE_ONLY, GL_R32UI)
        .uniform("uDownscale", half ? 2 : 1)
        .uniform("uRotation", rotation & 3)
        .dispatchImage(tracedWidth, tracedHeight, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    // The filter runs on the traced image; a different image size (the other GI resolution) makes
    // a new one.
    GLuint traced = half ? traced_.id() : indirect_.id();
    if (filterVoxels > 0.0f) {
        if (!filter_ || filter_->width() != tracedWidth) filter_ = std::make_unique<IndirectFilter>(tracedWidth, tracedHeight);
        traced = filter_->render(gbuffer, traced, half ? tracedPixel_.id() : 0, octree.grid.voxelSize, filterVoxels);
    }
    result_ = half ? indirect_.id() : traced;
    if (half) {
        gl::ComputeCall upsample(upsampleProgram_);
        setConeMarchUniforms(upsample, octree, radiance, settings);
        upsample.texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
            .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, gbuffer.geometricNormal())
            .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
            .texture(gl::TEXTURE_TRACED_IRRADIANCE, traced)
            .texture(gl::TEXTURE_TRACED_PIXEL, tracedPixel_.id())
            .storage(gl::SSBO_CONE_COUNTERS, counters_)
            .image(gl::IMAGE_INDIRECT, indirect_.id(), GL_WRITE_ONLY, GL_RGBA32F)
            .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    gl::checkErrors("tracing cones");
}

}  // namespace vct
