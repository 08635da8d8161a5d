#pragma once
// Debug view `--view voxels`: the octree at one level, ray-marched from the camera, unlit albedo
// composited with opacity, from the filtered bricks or from raw node values (`--no-bricks`).
#include "gl/objects.hpp"
#include "lighting/radiance_volume.hpp"
#include "render/eye_rays.hpp"
#include "render/view.hpp"
#include "voxel/octree.hpp"

namespace vct {

class VoxelView : public EyeRayView {
public:
    VoxelView(int width, int height);
    // The albedo of the octree's level `level`, or with `radiance` its radiance.
    void render(const Octree& octree, const RadianceVolume* radiance, const Camera& camera, const Scene& scene,
                int level, bool useBricks);
};

}  // namespace vct
