#include "lighting/radiance_volume.hpp"

#include "core/error.hpp"

namespace vct {


void allocateRadianceVolume(const Octree& octree, RadianceVolume& v) {
    const std::uint32_t cells = std::max<std::uint32_t>(octree.cellCount(), 1);
    const std::uint32_t all = std::max<std::uint32_t>(octree.totalCount, 1);
    const std::uint32_t nodes = std::max<std::uint32_t>(octree.nodeCount, 1);
    const GLbitfield dynamic = GL_DYNAMIC_STORAGE_BIT;
    v.accumulators = gl::createBuffer(GLsizeiptr(cells) * 4 * kAccumulatorWords, nullptr, dynamic, "radiance accumulators");
    v.cellRadiance = gl::createBuffer(GLsizeiptr(cells) * 16, nullptr, dynamic, "cell radiance");
    v.cellDirection = gl::createBuffer(GLsizeiptr(cells) * 16, nullptr, dynamic, "cell radiance direction");
    v.touchedFlag = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched flags");
    v.touchedList = gl::createBuffer(GLsizeiptr(all) * 4, nullptr, dynamic, "touched lists");
    v.borderFlag = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border flags");
    v.borderList = gl::createBuffer(GLsizeiptr(nodes) * 4, nullptr, dynamic, "border lists");
    v.listCounts = gl::createBuffer(gl::LIST_COUNT_SLOTS * 4, nullptr, dynamic, "radiance list counts");
    v.indirectArgs = gl::createBuffer(3 * 4 * 2 * (kMaxOctreeLevels + 1), nullptr, dynamic, "radiance dispatch args");
    v.partial.clear();
    v.partialDirection.clear();
    for (int level = 0; level < octree.levels; ++level) {
        v.partial.push_back(createPartialBricks(octree, level));
        v.partialDirection.push_back(createPartialBricks(octree, level));
    }
    const glm::ivec3 size = 3 * octree.brickPoolBricks;
    auto pool = [&](const char* name, GLenum format) {
        gl::Texture t = gl::createTexture(GL_TEXTURE_3D, name);
        glTextureStorage3D(t.id(), 1, format, size.x, size.y, size.z);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        return t;
    };
    v.brickRadiance = pool("brick pool radiance", GL_RGBA32F);
    v.brickDirection = pool("brick pool radiance direction", GL_RGBA16F);
    v.rawRadiance = gl::createBuffer(GLsizeiptr(nodes) * 16, nullptr, dynamic, "node raw radiance");
    v.rawDirection = gl::createBuffer(GLsizeiptr(nodes) * 16, nullptr, dynamic, "node raw radiance direction");
    gl::checkErrors("allocating the radiance volume");
}

std::size_t RadianceVolume::bytes(const Octree& octree) const {
    std::size_t partialBytes = 0;
    for (int l = 0; l < octree.levels; ++l) partialBytes += std::size_t(octree.levelCount[l]) * 27 * 16;
    const std::size_t bricks = std::size_t(octree.brickPoolBricks.x) * octree.brickPoolBricks.y * octree.brickPoolBricks.z;
    return std::size_t(octree.cellCount()) * (4 * kAccumulatorWords + 16 + 16) + std::size_t(octree.totalCount) * 8 +
           std::size_t(octree.nodeCount) * (8 + 16 + 16) + 2 * partialBytes + bricks * 27 * (16 + 8);
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
