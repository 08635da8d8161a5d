#include "lighting/radiance_volume.hpp"

#include "core/error.hpp"

namespace vct {

constexpr int kCountSlots = 25;

void allocateRadianceVolume(const Octree& octree, RadianceVolume& v) {
    const std::uint32_t cells = std::max<std::uint32_t>(octree.cellCount(), 1);
    const std::uint32_t all = std::max<std::uint32_t>(octree.totalCount, 1);
    const std::uint32_t nodes = std::max<std::uint32_t>(octree.nodeCount, 1);
    const GLbitfield dynamic = GL_DYNAMIC_STORAGE_BIT;
    v.accumulators = gl::createBuffer(GLsizeiptr(cells) * 24, nullptr, dynamic, "radiance accumulators");
    v.cellRadiance = gl::createBuffer(GLsizeiptr(cells) * 16, nullptr, dynamic, "cell radiance");
    v.touchedFlag = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched flags");
    v.touchedList = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched lists");
    v.borderFlag = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border flags");
    v.borderList = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border lists");
    v.listCounts = gl::createBuffer(kCountSlots * 4, nullptr, dynamic, "radiance list counts");
    v.indirectArgs = gl::createBuffer(3 * 4 * 2 * (kMaxOctreeLevels + 1), nullptr, dynamic, "radiance dispatch args");
    v.partial.clear();
    for (int level = 0; level < octree.levels; ++level) v.partial.push_back(createPartialBricks(octree, level));
    v.brickRadiance = gl::createTexture(GL_TEXTURE_3D, "brick pool radiance");
    const glm::ivec3 size = 3 * octree.brickPoolBricks;
    glTextureStorage3D(v.brickRadiance.id(), 1, GL_RGBA32F, size.x, size.y, size.z);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(v.brickRadiance.id(), wrap, GL_CLAMP_TO_EDGE);
    glTextureParameteri(v.brickRadiance.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(v.brickRadiance.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    v.rawRadiance = gl::createBuffer(GLsizeiptr(nodes) * 16, nullptr, dynamic, "node raw radiance");
    gl::checkErrors("allocating the radiance volume");
}

std::size_t RadianceVolume::bytes(const Octree& octree) const {
    std::size_t partialBytes = 0;
    for (int l = 0; l < octree.levels; ++l) partialBytes += std::size_t(octree.levelCount[l]) * 27 * 16;
    return std::size_t(octree.cellCount()) * (24 + 16) + std::size_t(octree.totalCount) * 8 +
           std::size_t(octree.nodeCount) * (8 + 16) + partialBytes +
           std::size_t(octree.brickPoolBricks.x) * octree.brickPoolBricks.y * octree.brickPoolBricks.z * 27 * 16;
}

RadianceStatistics readRadianceStatistics(const Octree& octree, const RadianceVolume& v) {
    std::uint32_t counts[kCountSlots] = {};
    glGetNamedBufferSubData(v.listCounts.id(), 0, sizeof counts, counts);
    RadianceStatistics s;
    for (int l = 0; l <= octree.levels; ++l) s.touchedPerLevel.push_back(counts[l]);
    s.photonsMissed = counts[24];
    return s;
}

}  // namespace vct
