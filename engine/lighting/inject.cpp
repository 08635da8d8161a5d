#include "lighting/inject.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "gl/shader.hpp"

namespace vct {

PhotonInjection::PhotonInjection()
    : inject_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject.comp"}})),
      emissive_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject_emissive.comp"}})),
      normalize_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_normalize.comp"}})) {}

float fluxFixedPointScale(const std::vector<Light>& lights, const std::vector<LightViewMap>& lightViews) {
    double maxFlux = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        const double color = std::max({l.color.x, l.color.y, l.color.z});
        const double quantity = l.type == LightType::Directional ? l.irradiance : l.intensity;
        maxFlux = std::max(maxFlux, quantity * color * lightViews[i].transform().texelFootprint);
    }
    return maxFlux > 0.0 ? float(16777216.0 / maxFlux) : 1.0f;
}

void PhotonInjection::run(const Octree& octree, RadianceVolume& volume, const Scene& scene,
                          const std::vector<Light>& lights, const std::vector<LightViewMap>& lightViews, bool photons) {
    const std::uint32_t zero = 0;
    const float zeros[4] = {0, 0, 0, 0};
    for (const gl::Buffer* b : {&volume.accumulators, &volume.touchedFlag, &volume.borderFlag, &volume.listCounts})
        glClearNamedBufferData(b->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    for (const gl::Buffer* b : {&volume.cellRadiance, &volume.rawRadiance})
        glClearNamedBufferData(b->id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zeros);
    for (const PartialBricks& partial : volume.partial)
        glClearNamedBufferData(partial.data.id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zeros);
    glClearTexImage(volume.brickRadiance.id(), 0, GL_RGBA, GL_FLOAT, zeros);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    volume.fluxScale = fluxFixedPointScale(lights, lightViews);

    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    if (photons) {
        const GLuint p = inject_.id();
        glUseProgram(p);
        octree.bind(p);
        bindRadianceVolume(volume);
        gl::setUniform(p, "uVoxelOrigin", glm::vec3(octree.grid.localMin));
        gl::setUniform(p, "uVoxelScale", float(1.0 / octree.grid.voxelSize));
        gl::setUniform(p, "uFluxScale", volume.fluxScale);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 9, octree.cellArea.id());
        for (const LightViewMap& map : lightViews) {
            glBindTextureUnit(0, map.position());
            glBindTextureUnit(1, map.flux());
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
    gl::setUniform(p, "uFluxScale", volume.fluxScale);
    gl::setUniform(p, "uVoxelArea", float(octree.grid.voxelSize * octree.grid.voxelSize));
    gl::setUniform(p, "uHasEmissive", octree.hasEmissive ? 1 : 0);
    listDispatch_.dispatch(volume, kTouchedCountSlot + unsigned(octree.levels));
    glMemoryBarrier(barrier);
    gl::checkErrors("injecting light into the octree");
}

}  // namespace vct
