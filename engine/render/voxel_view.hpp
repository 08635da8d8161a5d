#pragma once
// Debug view `--view voxels`: the octree at one level, ray-marched from the camera, unlit albedo
// composited with opacity, from the filtered bricks or from raw node values (`--no-bricks`).
#include "gl/objects.hpp"
#include "lighting/radiance_volume.hpp"
#include "render/view.hpp"
#include "voxel/octree.hpp"

namespace vct {

class VoxelView {
public:
    // What the view shows: a brick pool with its per-voxel and per-node raw values.
    struct Source {
        GLuint bricks;       // 3D brick pool, premultiplied (value·α, α)
        GLuint cells;        // per voxel: RGBA8 albedo+opacity, or vec4 premultiplied radiance
        GLuint raw;          // vec4 per node
        bool radiance;       // radiance (no face shading, tone-mapped) or albedo
    };
    static Source albedo(const Octree& octree) {
        return {octree.brickAlbedo.id(), octree.cellAlbedo.id(), octree.rawValue.id(), false};
    }
    static Source radiance(const RadianceVolume& volume) {
        return {volume.brickRadiance.id(), volume.cellRadiance.id(), volume.rawRadiance.id(), true};
    }

    VoxelView(int width, int height);
    void render(const Octree& octree, const Source& source, const Camera& camera, const Scene& scene, int level,
                bool useBricks);
    GLuint image() const { return image_.id(); }
    std::size_t bytes() const { return std::size_t(width_) * height_ * 16; }

private:
    int width_, height_;
    gl::Texture image_;
    gl::Program program_;
};

}  // namespace vct
