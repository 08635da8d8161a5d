#include "render/voxel_view.hpp"

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "render/eye_rays.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

VoxelView::VoxelView(int width, int height)
    : EyeRayView(width, height, "voxel view", "voxel_view.comp") {}

void VoxelView::render(const Octree& octree, const RadianceVolume* radiance, const Camera& camera, const Scene& scene,
                       int level, bool useBricks) {
    if (level < 1 || level > octree.levels)
        fail("--voxel-level ", level, " is out of range; this octree has levels 1..", octree.levels,
             " (", octree.levels, " = the voxels themselves)");
    gl::ComputeCall call(program_);
    octree.bind(call.program());
    setBrickPoolUniforms(call.program(), octree);
    call.uniform("uViewLevel", level)
        .uniform("uUseBricks", useBricks ? 1 : 0)
        .uniform("uShowRadiance", radiance ? 1 : 0)
        .texture(gl::TEXTURE_VIEW_ALBEDO_BRICKS, octree.brickAlbedo.id())
        .storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_RAW_VALUE, octree.rawValue);
    if (radiance) {
        // The voxels with as many bounces as the bricks the coarser levels show.
        call.storage(gl::SSBO_CELL_RADIANCE, radiance->seenCellRadiance())
            .storage(gl::SSBO_CELL_EXIT_SHARES, radiance->seenCellExitShares())
            .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity);
        bindDirectionalTexture(call, *radiance);
    }
    march(call, octree, camera, scene);
}

}  // namespace vct
