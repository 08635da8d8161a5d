#include "lighting/radiance_volume.hpp"

#include "core/error.hpp"
#include "gl/shader.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

void allocateRadianceVolume(const Octree& octree, RadianceVolume& v) {
    const std::uint32_t cells = std::max<std::uint32_t>(octree.cellCount(), 1);
    const std::uint32_t all = std::max<std::uint32_t>(octree.totalCount, 1);
    const std::uint32_t nodes = std::max<std::uint32_t>(octree.nodeCount, 1);
    const GLbitfield dynamic = GL_DYNAMIC_STORAGE_BIT;
    v.accumulators = gl::createBuffer(GLsizeiptr(cells) * 4 * kAccumulatorWords, nullptr, dynamic, "radiance accumulators");
    v.cellRadiance = gl::createBuffer(GLsizeiptr(cells) * 16, nullptr, dynamic, "cell radiance");
    v.cellExitShares = gl::createBuffer(GLsizeiptr(cells) * 32, nullptr, dynamic, "cell exit shares");
    v.touchedFlag = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched flags");
    v.touchedList = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched lists");
    v.borderFlag = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border flags");
    v.borderList = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border lists");
    v.listCounts = gl::createBuffer(gl::LIST_COUNT_SLOTS * 4, nullptr, dynamic, "radiance list counts");
    v.indirectArgs = gl::createBuffer(3 * 4 * gl::LIST_COUNT_SLOTS, nullptr, dynamic, "radiance dispatch args");
    v.directionalBricks = brickPoolLayout(octree.nodeCount, "nodes", 6);
    v.directional = createBrickPool(v.directionalBricks * glm::ivec3(1, 1, 6), GL_RGBA32F,
                                    "radiance pool (+x -x +y -y +z -z)");
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

std::size_t RadianceVolume::bytes(const Octree& octree) const {
    return std::size_t(octree.cellCount()) * (4 * kAccumulatorWords + 16 + 32) + std::size_t(octree.totalCount) * 8 +
           std::size_t(octree.nodeCount) * 8 + brickPoolBytes(directionalBricks * glm::ivec3(1, 1, 6), 16);
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
