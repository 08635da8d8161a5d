#include "lighting/radiance_volume.hpp"

#include "core/error.hpp"
#include "gl/shader.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

void fitRadianceVolume(const Octree& octree, RadianceVolume& v) {
    const std::uint32_t cells = std::max<std::uint32_t>(octree.cellCount(), 1);
    const std::uint32_t all = std::max<std::uint32_t>(octree.totalCount, 1);
    const std::uint32_t nodes = std::max<std::uint32_t>(octree.nodeCount, 1);
    const GLbitfield dynamic = GL_DYNAMIC_STORAGE_BIT;
    gl::fitBuffer(v.accumulators, GLsizeiptr(cells) * 4 * kAccumulatorWords, dynamic, "radiance accumulators");
    gl::fitBuffer(v.cellRadiance, GLsizeiptr(cells) * 16, dynamic, "cell radiance");
    gl::fitBuffer(v.cellExitShares, GLsizeiptr(cells) * 32, dynamic, "cell exit shares");
    gl::fitBuffer(v.touchedFlag, GLsizeiptr(all) * 4, dynamic, "touched flags");
    gl::fitBuffer(v.touchedList, GLsizeiptr(all) * 4, dynamic, "touched lists");
    gl::fitBuffer(v.borderFlag, GLsizeiptr(nodes) * 4, dynamic, "border flags");
    gl::fitBuffer(v.borderList, GLsizeiptr(nodes) * 4, dynamic, "border lists");
    gl::fitBuffer(v.listCounts, gl::LIST_COUNT_SLOTS * 4, dynamic, "radiance list counts");
    gl::fitBuffer(v.indirectArgs, 3 * 4 * gl::LIST_COUNT_SLOTS, dynamic, "radiance dispatch args");
    fitBrickPool(v.directional, v.directionalBricks, octree.nodeCount, "nodes", 6, GL_RGBA32F,
                 "radiance pool (+x -x +y -y +z -z)");
    // Whatever the pools held belongs to the previous octree.
    v.bricksBounces = 1;
    v.darkOutsideBorderFor = 0;
    v.octreeBuild = octree.geometryBricksBuild;
    gl::checkErrors("allocating the radiance volume");
}

void clearListCounts(const RadianceVolume& v, unsigned first, unsigned end) {
    const std::uint32_t zero = 0;
    glClearNamedBufferSubData(v.listCounts.id(), GL_R32UI, GLintptr(4 * first), GLsizeiptr(4 * (end - first)),
                              GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void bindDirectionalTexture(gl::ComputeCall& call, const RadianceVolume& v) {
    call.texture(gl::TEXTURE_DIRECTIONAL_RADIANCE, v.directional.id()).uniform("uDirectionalBricks", v.directionalBricks);
}

void bindDirectionalImage(gl::ComputeCall& call, const RadianceVolume& v, GLenum access) {
    call.image(gl::IMAGE_DIRECTIONAL_RADIANCE, v.directional.id(), access, GL_RGBA32F, true)
        .uniform("uDirectionalBricks", v.directionalBricks);
}

std::size_t RadianceVolume::bytes() const {
    std::size_t total = brickPoolBytes(directionalBricks * glm::ivec3(1, 1, 6), 16);
    for (const gl::Buffer* b : {&accumulators, &cellRadiance, &cellExitShares, &bouncedCellRadiance,
                                &bouncedCellExitShares, &touchedFlag, &touchedList, &borderFlag, &borderList, &listCounts,
                                &indirectArgs})
        total += std::size_t(gl::bufferBytes(*b));
    return total;
}

RadianceStatistics readRadianceStatistics(const Octree& octree, const RadianceVolume& v) {
    std::uint32_t counts[gl::LIST_COUNT_SLOTS] = {};
    glGetNamedBufferSubData(v.listCounts.id(), 0, sizeof counts, counts);
    RadianceStatistics s;
    for (int l = 0; l <= octree.levels; ++l) s.touchedPerLevel.push_back(counts[l]);
    s.photonsMissed = counts[gl::MISSED_COUNT_SLOT];
    return s;
}

}  // namespace vct
