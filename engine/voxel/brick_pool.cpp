#include "voxel/brick_pool.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "gl/compute.hpp"

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

void allocateBrickPool(Octree& octree) {
    GLint max3D = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
    const int maxBricksPerAxis = max3D / 3;
    const std::uint32_t bricks = std::max<std::uint32_t>(octree.nodeCount, 1);
    // x and y as square as possible, z as needed.
    const int side = std::min(maxBricksPerAxis, int(std::ceil(std::cbrt(double(bricks)))));
    const int z = int((bricks + std::uint64_t(side) * side - 1) / (std::uint64_t(side) * side));
    if (z > maxBricksPerAxis)
        fail("the octree has ", bricks, " nodes, more bricks than a ", max3D, "³ texture holds; lower --voxel-levels");
    octree.brickPoolBricks = {side, side, z};
    auto pool = [&](const char* name) {
        gl::Texture t = gl::createTexture(GL_TEXTURE_3D, name);
        glTextureStorage3D(t.id(), 1, GL_RGBA16F, 3 * side, 3 * side, 3 * z);
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        return t;
    };
    octree.brickAlbedo = pool("brick pool albedo/opacity");
    octree.brickOpacity = pool("brick pool opacity by axis");
    octree.rawValue = gl::createBuffer(GLsizeiptr(bricks) * 16, nullptr, 0, "node raw values");
    octree.rawOpacity = gl::createBuffer(GLsizeiptr(bricks) * 16, nullptr, 0, "node raw opacity by axis");
    gl::checkErrors(concat("allocating the brick pool (", 3 * side, "x", 3 * side, "x", 3 * z, " RGBA16F)"));
}

void setBrickPoolUniforms(GLuint program, const Octree& octree) {
    gl::setUniform(program, "uBrickPoolBricks", octree.brickPoolBricks);
}

BrickCompletion::BrickCompletion(const std::vector<std::string>& defines)
    : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_complete.comp"}}, defines)) {}

gl::ComputeCall BrickCompletion::prepare(const Octree& octree, const PartialBricks& partial, GLuint pool) {
    gl::ComputeCall call(program_);
    octree.bind(call.program());
    setBrickPoolUniforms(call.program(), octree);
    GLint format = GL_RGBA16F;  // the albedo pool; the radiance pool is RGBA32F (POOL_RGBA32F variant)
    glGetTextureLevelParameteriv(pool, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    call.uniform("uLevel", partial.level)
        .image(gl::IMAGE_PARTIAL_BRICKS, partial.texture.id(), GL_READ_ONLY, GL_RGBA32F)
        .image(gl::IMAGE_BRICK_POOL, pool, GL_WRITE_ONLY, GLenum(format), true);
    return call;
}

void BrickCompletion::run(const Octree& octree, const PartialBricks& partial, GLuint pool) {
    prepare(octree, partial, pool)
        .dispatch1D(octree.levelCount[partial.level], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace vct
