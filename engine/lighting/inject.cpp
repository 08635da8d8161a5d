#include "lighting/inject.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/math_constants.hpp"
#include "gl/driver_checks.hpp"

namespace vct {

PhotonInjection::PhotonInjection()
    : inject_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject.comp"}})),
      emissive_(gl::buildProgram({{GL_COMPUTE_SHADER, "inject_emissive.comp"}})),
      normalize_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_normalize.comp"}})) {}

double fluxWattsPerUnit(const std::vector<Light>& lights, const LightViewSets& lightViews) {
    double maxFlux = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i)
        for (const LightViewMap& map : lightViews[i])
            maxFlux = std::max(maxFlux, LightViewMap::maxTexelFlux(lights[i], map.transform()));
    return maxFlux > 0.0 && std::isfinite(maxFlux) ? maxFlux / 16777216.0 : 1.0;
}

void PhotonInjection::run(const Octree& octree, RadianceVolume& volume, const Scene& scene,
                          const std::vector<Light>& lights, const LightViewSets& lightViews, bool photons) {
    const std::uint32_t zero = 0;
    const float zeros[4] = {0, 0, 0, 0};
    for (const gl::Buffer* b : {&volume.accumulators, &volume.touchedFlag})
        glClearNamedBufferData(b->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    // The border lists stay: the radiance filter first clears the bricks of the nodes on them, the
    // only ones the last filtering lit (RadianceFilter::leaves), then rebuilds them.
    clearListCounts(volume, 0, gl::BORDER_COUNT_SLOT);
    clearListCounts(volume, gl::MISSED_COUNT_SLOT, gl::LIST_COUNT_SLOTS);
    for (const gl::Buffer* b : {&volume.cellRadiance, &volume.cellExitShares})
        glClearNamedBufferData(b->id(), GL_RGBA32F, GL_RGBA, GL_FLOAT, zeros);
    gl::memoryBarrier(GL_ALL_BARRIER_BITS);
    volume.wattsPerUnit = fluxWattsPerUnit(lights, lightViews);
    std::uint64_t texels = 0;
    for (const std::vector<LightViewMap>& maps : lightViews)
        for (const LightViewMap& map : maps) texels += std::uint64_t(map.resolution()) * std::uint64_t(map.resolution());
    if (texels > (std::uint64_t(1) << 33))
        fail("the light-view maps have ", texels, " texels in all; more than 2^33 could overflow the 64-bit photon sums. "
             "Lower --light-view-res or use fewer lights");

    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    if (photons) {
        gl::ComputeCall inject(inject_);
        octree.bind(inject.program());
        bindRadianceVolume(volume);
        inject.uniform("uVoxelOrigin", glm::vec3(octree.grid.localMin))
            .uniform("uVoxelScale", float(1.0 / octree.grid.voxelSize))
            .storage(gl::SSBO_CELL_AREA, octree.cellArea)
            .storage(gl::SSBO_CELL_COLUMNS, octree.cellColumns);
        for (std::size_t i = 0; i < lights.size(); ++i)
            for (const LightViewMap& map : lightViews[i]) {
                // Units for a texel of relative flux 1: ≤ 2^24 (the brightest light), in double first.
                const double units = LightViewMap::maxTexelFlux(lights[i], map.transform()) / volume.wattsPerUnit;
                inject.uniform("uUnitsPerRelativeFlux", float(std::min(units, 16777216.0)))
                    .texture(gl::TEXTURE_LIGHT_POSITION, map.position())
                    .texture(gl::TEXTURE_LIGHT_FLUX, map.flux())
                    .texture(gl::TEXTURE_LIGHT_NORMAL, map.normal())
                    .dispatchImage(map.resolution(), map.resolution(), barrier);
            }
    }
    if (octree.hasEmissive) {
        gl::ComputeCall emissive(emissive_);
        octree.bind(emissive.program());
        bindRadianceVolume(volume);
        emissive.storage(gl::SSBO_CELL_EMISSIVE, octree.cellEmissive).dispatch1D(octree.cellCount(), 64, barrier);
    }
    gl::ComputeCall normalize(normalize_);
    octree.bind(normalize.program());
    bindRadianceVolume(volume);
    normalize.storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_CELL_AREA, octree.cellArea)
        .storage(gl::SSBO_CELL_COLUMNS, octree.cellColumns)
        .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity)
        .uniform("uLevel", octree.levels)
        .uniform("uHasEmissive", octree.hasEmissive ? 1 : 0);
    if (octree.hasEmissive) normalize.storage(gl::SSBO_CELL_EMISSIVE, octree.cellEmissive);
    // Watts per unit / (π · voxel face area), in double: radiance = units × this / cell area.
    glProgramUniform1d(normalize.program(), glGetUniformLocation(normalize.program(), "uRadiancePerUnit"),
                       volume.wattsPerUnit / (kPi * octree.grid.voxelSize * octree.grid.voxelSize));
    listDispatch_.dispatch(normalize, volume, kTouchedCountSlot + unsigned(octree.levels), barrier);
    gl::checkErrors("injecting light into the octree");
}

}  // namespace vct
