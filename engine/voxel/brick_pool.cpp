#include "voxel/brick_pool.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "gl/driver_checks.hpp"

namespace vct {

PartialBricks createPartialBricks(const Octree& octree, int level) {
    const std::uint64_t texels = std::uint64_t(std::max<std::uint32_t>(octree.levelCount[level], 1)) * 27;
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (texels > std::uint64_t(maxTexels))
        fail("level ", level, " of the octree has ", octree.levelCount[level],
             " nodes; their bricks exceed this GPU's buffer-texture limit; lower --voxel-levels");
    PartialBricks partial;
    partial.level = level;
    partial.data = gl::createBuffer(GLsizeiptr(texels * 16), nullptr, 0, "partial bricks");
    partial.texture = gl::createTexture(GL_TEXTURE_BUFFER, "partial bricks");
    glTextureBuffer(partial.texture.id(), GL_RGBA32F, partial.data.id());
    return partial;
}

glm::ivec3 brickPoolLayout(std::uint32_t bricks, const char* what, int depthShare) {
    GLint max3D = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
    const int maxBricksPerAxis = max3D / 3;
    const int maxDepth = std::max(maxBricksPerAxis / depthShare, 1);
    bricks = std::max<std::uint32_t>(bricks, 1);
    auto depthFor = [&](std::uint64_t side) { return std::uint64_t((bricks + side * side - 1) / (side * side)); };
    std::uint64_t side = std::min(maxBricksPerAxis, int(std::ceil(std::cbrt(double(bricks)))));
    while (depthFor(side) > std::uint64_t(maxDepth) && side < std::uint64_t(maxBricksPerAxis)) ++side;
    if (depthFor(side) > std::uint64_t(maxDepth))
        fail("the octree has ", bricks, " ", what, ", more bricks than a ", max3D, "³ texture holds; lower --voxel-levels");
    return {int(side), int(side), int(depthFor(side))};
}

gl::Texture createBrickPool(glm::ivec3 bricksPerAxis, GLenum format, const char* label) {
    gl::Texture t = gl::createTexture(GL_TEXTURE_3D, label);
    const glm::ivec3 size = 3 * bricksPerAxis;
    glTextureStorage3D(t.id(), 1, format, size.x, size.y, size.z);
    gl::poisonNewTexture(t.id(), format, 1);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl::checkErrors(concat("allocating the ", label, " (", size.x, "x", size.y, "x", size.z, ")"));
    return t;
}

void fitBrickPool(gl::Texture& pool, glm::ivec3& layout, std::uint32_t bricks, const char* what, int depthShare,
                  GLenum format, const char* label) {
    const glm::ivec3 wanted = brickPoolLayout(bricks, what, depthShare);
    if (pool && wanted == layout) {
        gl::poisonNewTexture(pool.id(), format, 1);
        return;
    }
    pool.reset();  // before the new one: both at once may not fit
    layout = wanted;
    pool = createBrickPool(layout * glm::ivec3(1, 1, depthShare), format, label);
}

std::size_t brickPoolBytes(glm::ivec3 b, std::size_t bytesPerTexel) {
    return std::size_t(b.x) * b.y * b.z * 27 * bytesPerTexel;
}

void fitBrickPools(Octree& octree) {
    // The three pools share one layout: the one they were made with, until fitBrickPool changes it.
    const glm::ivec3 held = octree.brickPoolBricks;
    const std::pair<gl::Texture*, const char*> pools[] = {{&octree.brickAlbedo, "brick pool albedo/opacity"},
                                                          {&octree.brickOpacityPlus, "brick pool opacity +x +y +z"},
                                                          {&octree.brickOpacityMinus, "brick pool opacity -x -y -z"}};
    for (const auto& [pool, label] : pools) {
        glm::ivec3 layout = held;
        fitBrickPool(*pool, layout, octree.nodeCount, "nodes", 1, GL_RGBA16F, label);
        octree.brickPoolBricks = layout;
    }
    gl::fitBuffer(octree.rawValue, GLsizeiptr(std::max<std::uint32_t>(octree.nodeCount, 1)) * 16, 0, "node raw values");
}

void setBrickPoolUniforms(GLuint program, const Octree& octree) {
    gl::setUniform(program, "uBrickPoolBricks", octree.brickPoolBricks);
}

gl::ComputeCall brickLevelCall(const gl::Program& program, const Octree& octree, int level) {
    gl::ComputeCall call(program);
    octree.bind(call.program());
    setBrickPoolUniforms(call.program(), octree);
    call.uniform("uLevel", level);
    return call;
}

BrickCompletion::BrickCompletion() : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_complete.comp"}})) {}

void BrickCompletion::run(const Octree& octree, const PartialBricks& partial, GLuint pool) {
    brickLevelCall(program_, octree, partial.level)
        .image(gl::IMAGE_PARTIAL_BRICKS, partial.texture.id(), GL_READ_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_BRICK_POOL, pool, GL_WRITE_ONLY, GL_RGBA16F, true)
        .dispatch1D(octree.levelCount[partial.level], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace vct
