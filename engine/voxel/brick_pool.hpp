#pragma once
// The 3D-texture brick pool and the step both brick passes end with: turning one level's partial
// bricks into complete samples in the pool (brick_layout.hpp, shaders/bricks_complete.comp).
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

// The leaf level's partial bricks of the two geometry pools: albedo (brickAlbedo) and opacity by
// axis (brickOpacity).
struct LeafPartials {
    PartialBricks albedo, opacity;
};

// Allocates octree.brickAlbedo and brickOpacity with one brick per node (levels 0..L−1), and
// octree.rawValue and rawOpacity.
void allocateBrickPool(Octree& octree);

class BrickCompletion {
public:
    // `defines` select a variant of bricks_complete.comp (e.g. "WORK_LIST_BORDER 1").
    explicit BrickCompletion(const std::vector<std::string>& defines = {});
    // Completes every node of the partial's level into `pool`.
    void run(const Octree& octree, const PartialBricks& partial, GLuint pool);
    // Binds everything but the dispatch, for callers that dispatch over a list themselves.
    gl::ComputeCall prepare(const Octree& octree, const PartialBricks& partial, GLuint pool);

private:
    gl::Program program_;
};

void setBrickPoolUniforms(GLuint program, const Octree& octree);

}  // namespace vct
