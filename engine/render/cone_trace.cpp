#include "render/cone_trace.hpp"

#include <cmath>

#include "core/error.hpp"
#include "gl/shader.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

ConeTrace::ConeTrace(int width, int height)
    : width_(width),
      height_(height),
      indirect_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect irradiance")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "cone_trace.comp"}})),
      counters_(gl::createBuffer(24, nullptr, GL_DYNAMIC_STORAGE_BIT, "cone counters")) {}

ConeStatistics ConeTrace::statistics() const {
    std::uint32_t c[6] = {};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof c, c);
    auto join = [&](int i) { return std::uint64_t(c[i]) | (std::uint64_t(c[i + 1]) << 32); };
    return {join(0), join(2), join(4)};
}

void ConeTrace::render(const GBuffer& gbuffer, const Octree& octree, const RadianceVolume& radiance,
                       const ConeSettings& settings) {
    if (!(settings.apertureScale > 0.0f) || !(settings.step > 0.0f) || !(settings.offset >= 0.0f))
        fail("cone settings must be positive: --cone-aperture ", settings.apertureScale, ", --cone-step ",
             settings.step, ", --cone-offset ", settings.offset);
    if (!(settings.lift >= 0.0f && settings.lift <= 4.0f))
        fail("--cone-lift ", settings.lift, " is out of range; use 0..4 (normal offset per unit of cone diameter)");
    if (!(settings.maxDistance >= 0.0f) || !std::isfinite(settings.maxDistance))
        fail("cone maximum distance ", settings.maxDistance, " must be a finite number ≥ 0 (0: the whole volume)");
    const std::vector<Cone> cones = makeConeSet(settings.cones);
    std::vector<glm::vec3> directions;
    std::vector<float> tangents, weights;
    for (const Cone& c : cones) {
        directions.push_back(c.direction);
        // Wider than ~80° a cone reaches the coarsest level within a step or two.
        tangents.push_back(std::min(std::tan(c.halfAngle) * settings.apertureScale, 5.0f));
        weights.push_back(c.weight);
    }
    const GLuint p = program_.id();
    glUseProgram(p);
    octree.bind(p);
    setBrickPoolUniforms(p, octree);
    gl::setUniform(p, "uConeCount", int(cones.size()));
    glProgramUniform3fv(p, glGetUniformLocation(p, "uConeDirection"), GLsizei(cones.size()), &directions[0].x);
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeTanHalfAngle"), GLsizei(cones.size()), tangents.data());
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeWeight"), GLsizei(cones.size()), weights.data());
    gl::setUniform(p, "uConeStep", settings.step);
    gl::setUniform(p, "uConeOffset", settings.offset);
    gl::setUniform(p, "uConeLift", settings.lift);
    const float diagonal = float(octree.grid.resolution()) * 1.7320508f;
    gl::setUniform(p, "uMaxDistance", settings.maxDistance > 0.0f ? settings.maxDistance : diagonal);
    gl::setUniform(p, "uUseBricks", settings.bricks ? 1 : 0);
    gl::setUniform(p, "uVoxelOrigin", glm::vec3(octree.grid.localMin));
    gl::setUniform(p, "uVoxelScale", float(1.0 / octree.grid.voxelSize));
    glBindTextureUnit(0, gbuffer.normal());
    glBindTextureUnit(1, gbuffer.position());
    glBindTextureUnit(2, radiance.brickRadiance.id());
    glBindTextureUnit(4, radiance.brickDirection.id());
    glBindTextureUnit(5, octree.brickOpacity.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 26, octree.rawOpacity.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 24, radiance.rawDirection.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 12, radiance.rawRadiance.id());
    glBindImageTexture(0, indirect_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const std::uint32_t zero = 0;
    glClearNamedBufferData(counters_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 22, counters_.id());
    glDispatchCompute(GLuint((width_ + 7) / 8), GLuint((height_ + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    gl::checkErrors("tracing cones");
}

}  // namespace vct
