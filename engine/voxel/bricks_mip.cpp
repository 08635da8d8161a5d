#include "voxel/bricks_mip.hpp"

#include "voxel/bricks.hpp"

namespace vct {

BricksMip::BricksMip()
    : albedo_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_mip.comp"}})),
      opacity_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_opacity.comp"}})),
      share_(gl::buildProgram({{GL_COMPUTE_SHADER, "bricks_share.comp"}})) {}

void BricksMip::run(const Octree& octree, PartialBricks leafAlbedo) {
    // Only two levels of partial bricks are alive at a time: the level and its children.
    PartialBricks child = std::move(leafAlbedo);
    for (int level = octree.levels - 2; level >= 0; --level) {
        PartialBricks partial = createPartialBricks(octree, level);
        brickLevelCall(albedo_, octree, level)
            .storage(gl::SSBO_RAW_VALUE, octree.rawValue)
            .image(gl::IMAGE_PARTIAL_BRICKS, partial.texture.id(), GL_WRITE_ONLY, GL_RGBA32F)
            .image(gl::IMAGE_CHILD_PARTIAL_BRICKS, child.texture.id(), GL_READ_ONLY, GL_RGBA32F)
            .dispatch1D(octree.levelCount[level], 64, GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        completion_.run(octree, partial, octree.brickAlbedo.id());
        child = std::move(partial);
        runOpacityPass(opacity_, octree, level);
        runOpacityPass(share_, octree, level);
    }
    gl::checkErrors("filtering bricks up the octree");
}

}  // namespace vct
