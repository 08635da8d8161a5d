#include "voxel/voxel_grid.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace vct {

VoxelGrid makeVoxelGrid(const Scene& scene, int levels) {
    if (levels < kMinVoxelLevels || levels > kMaxVoxelLevels)
        fail("--voxel-levels ", levels, " is out of range; use ", kMinVoxelLevels, "..", kMaxVoxelLevels,
             " (", 1 << kMinVoxelLevels, "³ to ", 1 << kMaxVoxelLevels, "³ voxels)");
    const Bounds bounds = scene.localBounds();
    const glm::dvec3 size = bounds.size();
    const double extent = std::max({size.x, size.y, size.z});
    if (!(extent > 0.0) || !std::isfinite(extent))
        fail("scene '", scene.name, "' has no extent (all vertices at one point?); it cannot be voxelized");
    VoxelGrid grid;
    grid.levels = levels;
    const int n = grid.resolution();
    // n voxels = extent + a margin of 1.5 voxels on each side. The half voxel keeps planes on the
    // bounds (walls of a box) in the middle of a voxel rather than on a voxel boundary.
    grid.voxelSize = extent / double(n - 3);
    grid.localMin = bounds.centre() - glm::dvec3(0.5 * n * grid.voxelSize);
    return grid;
}

}  // namespace vct
