#pragma once
// Voxel space (DESIGN 5.1). The scene's bounds are mapped, in double precision, to the cube
// [0, N)³ with N = 2^levels. Every voxel pass works in these coordinates, never in world units,
// so a scene 10⁶ units from the origin or 10⁻³ units wide voxelizes like one at unit scale.
//
// Octree levels: level l has nodes of edge 2^(levels − l) voxels; level 0 is the root (the whole
// cube) and level levels − 1 holds the leaf nodes, each covering 2³ finest voxels ("cells").
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace vct {

constexpr int kMinVoxelLevels = 5;
constexpr int kMaxVoxelLevels = 10;

struct VoxelGrid {
    int levels = 8;                 // N = 2^levels voxels per axis
    glm::dvec3 localMin{0.0};       // scene-local position of voxel-space (0,0,0)
    double voxelSize = 1.0;         // scene-local units per voxel

    int resolution() const { return 1 << levels; }
    glm::dvec3 toVoxel(const glm::dvec3& local) const { return (local - localMin) / voxelSize; }
    glm::dvec3 toLocal(const glm::dvec3& voxel) const { return localMin + voxel * voxelSize; }
};

// The cube is the bounds' largest extent plus a margin of 1.5 voxels on every side (so geometry on
// the bounds never touches the volume's faces), centred on the bounds. Throws for levels outside
// [kMinVoxelLevels, kMaxVoxelLevels] and for scenes whose extent is zero or not finite.
VoxelGrid makeVoxelGrid(const Scene& scene, int levels);

// Packs a cell coordinate (each component < 2^10) into 30 bits: x | y << 10 | z << 20.
inline std::uint32_t packCell(glm::uvec3 c) { return c.x | (c.y << 10) | (c.z << 20); }
inline glm::uvec3 unpackCell(std::uint32_t p) { return {p & 1023u, (p >> 10) & 1023u, (p >> 20) & 1023u}; }

}  // namespace vct
