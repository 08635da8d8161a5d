#pragma once
// The 3D-texture brick pools, and the step the linear brick filters end with: turning one
// level's partial bricks into complete samples in a pool (brick_layout.hpp,
// shaders/bricks_complete.comp).
#include "gl/compute.hpp"
#include "voxel/octree.hpp"

namespace vct {

// Partial bricks of one level: 27 RGBA32F texels per node, in the level's node order.
struct PartialBricks {
    int level = -1;
    gl::Buffer data;
    gl::Texture texture;
};

PartialBricks createPartialBricks(const Octree& octree, int level);

// Bricks per axis of a pool holding `bricks` bricks: x and y as square as possible, z as needed,
// within GL_MAX_3D_TEXTURE_SIZE (fails naming `what` when they do not fit). With depthShare n, z
// stays within 1/n of the limit, for a texture that stacks n such layouts along z.
glm::ivec3 brickPoolLayout(std::uint32_t bricks, const char* what, int depthShare = 1);
// A pool of that many bricks per axis (3 texels each), linear filtering, clamped at its edges.
gl::Texture createBrickPool(glm::ivec3 bricksPerAxis, GLenum format, const char* label);
// gl::fitBuffer for a pool of `bricks` bricks (the texture holds depthShare such pools stacked
// along z): keeps `pool` while brickPoolLayout gives the `layout` it has, else replaces both. No
// room to spare: lookups in the pool use coordinates normalized by its size, whose rounding would
// differ in the last bits between a roomier pool and a fresh one, and an image must not depend on
// the builds before it. The samples are undefined either way.
void fitBrickPool(gl::Texture& pool, glm::ivec3& layout, std::uint32_t bricks, const char* what, int depthShare,
                  GLenum format, const char* label);
std::size_t brickPoolBytes(glm::ivec3 bricksPerAxis, std::size_t bytesPerTexel);

// Sizes octree.brickAlbedo and the opacity pools for one brick per node (levels 0..L−1), and
// octree.rawValue, keeping the previous build's storage where it fits (fitBrickPool).
void fitBrickPools(Octree& octree);

class BrickCompletion {
public:
    BrickCompletion();
    // Completes every node of the partial's level into `pool` (RGBA16F).
    void run(const Octree& octree, const PartialBricks& partial, GLuint pool);

private:
    gl::Program program_;
};

void setBrickPoolUniforms(GLuint program, const Octree& octree);

// A compute call of a pass over one octree level's bricks: `program` in use, the octree bound,
// the brick pool layout and uLevel set; the caller adds its buffers and images and dispatches.
gl::ComputeCall brickLevelCall(const gl::Program& program, const Octree& octree, int level);

}  // namespace vct
