#include "lighting/inject.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "gl/shader.hpp"

namespace vct {

PhotonInjection::PhotonInjection()
    : inject_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject.comp"}})),
      emissive_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject_emissive.comp"}})),
      normalize_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_normalize.comp"}})) {}

double fluxWattsPerUnit(const std::vector<Light>& lights, const std::vector<LightViewMap>& lightViews) {
    double maxFlux = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i)
        maxFlux = std::max(maxFlux, LightViewMap::maxTexelFlux(lights[i], lightViews[i].transform()));
    return maxFlux > 0.0 && std::isfinite(maxFlux) ? maxFlux / 16777216.0 : 1.0;
}

void PhotonInjection::run(const Octree& octree, RadianceVolume& volume, const Scene& scene,
                          const std::vector<Light>& lights, const std::vector<LightViewMap>& lightViews, bool photons) {
    const std::uint32_t zero = 0;
    const float zeros[4] = {0, 0, 0, 0};
    for (const gl::Buffer* b : {&volume.accumulators, &volume.touchedFlag, &volume.borderFlag, &volume.listCounts})
        glClearNamedBufferData(b->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    for (const gl::Buffer* b : {&volume.cellRadiance, &volume.rawRadiance, &volume.cellDirection, &volume.rawDirection})
        glClearNamedBufferData(b->id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zeros);
    for (const auto* partials : {&volume.partial, &volume.partialDirection})
        for (const PartialBricks& partial : *partials)
            glClearNamedBufferData(partial.data.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zeros);
    glClearTexImage(volume.brickRadiance.id(), 0, GL_RGBA, GL_FLOAT, zeros);
    glClearTexImage(volume.brickDirection.id(), 0, GL_RGBA, GL_FLOAT, zeros);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    volume.wattsPerUnit = fluxWattsPerUnit(lights, lightViews);
    std::uint64_t texels = 0;
    for (const LightViewMap& map : lightViews) texels += std::uint64_t(map.resolution()) * std::uint64_t(map.resolution());
    if (texels > (std::uint64_t(1) << 33))
        fail("the light-view maps have ", texels, " texels in all; more than 2^33 could overflow the 64-bit photon sums. "
             "Lower --light-view-res or use fewer lights");

    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    if (photons) {
        const GLuint p = inject_.id();
        glUseProgram(p);
        octree.bind(p);
        bindRadianceVolume(volume);
        gl::setUniform(p, "uVoxelOrigin", glm::vec3(octree.grid.localMin));
        gl::setUniform(p, "uVoxelScale", float(1.0 / octree.grid.voxelSize));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, octree.cellArea.id());
        for (std::size_t i = 0; i < lightViews.size(); ++i) {
            const LightViewMap& map = lightViews[i];
            // Units for a texel of relative flux 1: ≤ 2^24 (the brightest light), in double first.
            const double units = LightViewMap::maxTexelFlux(lights[i], map.transform()) / volume.wattsPerUnit;
            gl::setUniform(p, "uUnitsPerRelativeFlux", float(std::min(units, 16777216.0)));
            glBindTextureUnit(0, map.position());
            glBindTextureUnit(1, map.flux());
            glBindTextureUnit(2, map.normal());
            glDispatchCompute(GLuint((map.resolution() + 7) / 8), GLuint((map.resolution() + 7) / 8), 1);
            glMemoryBarrier(barrier);
        }
    }
    if (octree.hasEmissive) {
        const GLuint p = emissive_.id();
        glUseProgram(p);
        octree.bind(p);
        bindRadianceVolume(volume);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, octree.cellEmissive.id());
        glDispatchCompute(GLuint((octree.cellCount() + 63) / 64), 1, 1);
        glMemoryBarrier(barrier);
    }
    const GLuint p = normalize_.id();
    glUseProgram(p);
    octree.bind(p);
    bindRadianceVolume(volume);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, octree.cellAlbedo.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, octree.cellArea.id());
    if (octree.hasEmissive) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 11, octree.cellEmissive.id());
    gl::setUniform(p, "uLevel", octree.levels);
    // Watts per unit / (π · voxel face area), in double: radiance = units × this / cell area.
    glProgramUniform1d(p, glGetUniformLocation(p, "uRadiancePerUnit"),
                       volume.wattsPerUnit / (3.14159265358979323846 * octree.grid.voxelSize * octree.grid.voxelSize));
    gl::setUniform(p, "uHasEmissive", octree.hasEmissive ? 1 : 0);
    listDispatch_.dispatch(volume, kTouchedCountSlot + unsigned(octree.levels));
    glMemoryBarrier(barrier);
    gl::checkErrors("injecting light into the octree");
}

}  // namespace vct
