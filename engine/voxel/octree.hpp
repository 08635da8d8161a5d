#pragma once
// The sparse voxel octree's GPU data (layout documented in shaders/octree.glsl) and the fragment
// list it is built from. Filled by the passes voxelize → svo_build → svo_leaves → svo_neighbours
// → bricks → bricks_mip; read by the debug view and, later, by the GI passes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gl/objects.hpp"
#include "gl/shader_interface.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct {

constexpr int kMaxOctreeLevels = gl::MAX_OCTREE_LEVELS;

// Voxel fragments: one RGBA32UI texel each (cell, texture colour RGBA8, normal oct16,
// material index << 16 | area as half float) in a buffer texture, so the list may exceed the
// SSBO size limit. Material colour and emission are looked up by index in svo_leaves.
struct FragmentList {
    gl::Buffer data;
    gl::Texture dataTexture;
    gl::Buffer counter;
    std::uint32_t count = 0;
    std::uint32_t capacity = 0;
    int regrowths = 0;  // times the list was too small and voxelization ran again
    std::size_t bytes() const { return std::size_t(capacity) * 16; }
};

struct Octree {
    VoxelGrid grid;
    int levels = 0;  // L; nodes at levels 0..L−1, cells at level L
    std::array<std::uint32_t, kMaxOctreeLevels + 1> levelStart{};
    std::array<std::uint32_t, kMaxOctreeLevels + 1> levelCount{};
    std::uint32_t nodeCount = 0;  // levels 0..L−1 (these have bricks)
    std::uint32_t totalCount = 0;  // including the cells
    // Which build of the geometry bricks (albedo, opacity) the pools hold: a new number every time
    // bricks_mip completes them, never repeated by the same builder (radiance_volume.hpp).
    std::uint64_t geometryBricksBuild = 0;

    // Node pool (SoA), totalCount entries each.
    gl::Buffer child, mask, coord, parent;
    gl::Buffer neighbours;  // 6 per node, nodeCount nodes

    // Cells (level L), levelCount[L] entries each: albedo+opacity RGBA8, normal oct16, area in
    // voxel-face units, fragment count, emission float RGB(A) (only with emissive materials).
    gl::Buffer cellAlbedo, cellNormal, cellArea, cellFragments, cellEmissive;
    // Per cell, the cells beside it that hold the rest of one of its triangles' pixel columns
    // (bit 2a: below along axis a, 2a + 1: above; shaders/svo_leaves_normalize.comp).
    gl::Buffer cellColumns;
    // Opacity by direction, RGBA8 per cell: (αx, αy, αz, α) with α_a = min(1, max(A₊, A₋)), A±
    // the area projected along axis a (voxel-face units) of the faces that face ±a (a closed
    // object's silhouette, counted once), and α = min(1, Σ area).
    gl::Buffer cellOpacity;
    bool hasEmissive = false;

    // Bricks: one 3³ brick per node (levels 0..L−1) in 3D textures, brick index = node index.
    glm::ivec3 brickPoolBricks{0};  // bricks per axis
    // Albedo, RGBA16F, premultiplied (ρ·τ, τ), linear filters (brick_layout.hpp); and the node's
    // raw value, the mean of (ρ·τ, τ) over its cells: what the voxel view shows.
    gl::Texture brickAlbedo;
    gl::Buffer rawValue;
    // Opacity, RGBA16F: the density of each sample's slab along +x, +y, +z (and their mean), and
    // along −x, −y, −z (brick_layout.hpp, "Slabs"): what cones are blocked by.
    gl::Texture brickOpacityPlus, brickOpacityMinus;

    std::uint32_t cellCount() const { return levelCount[levels]; }
    std::uint32_t leafCount() const { return levelCount[levels - 1]; }  // nodes whose children are cells
    std::size_t nodePoolBytes() const { return std::size_t(totalCount) * 16; }
    std::size_t neighbourBytes() const { return std::size_t(nodeCount) * 24; }
    // What the cell buffers and the brick pools hold, which can exceed what the octree needs (kept
    // from an earlier build: gl::fitBuffer).
    std::size_t cellBytes() const;
    std::size_t brickPoolBytes() const;
    // A dense RGBA16F 3D texture of the same resolution with its full mip chain (for comparison).
    std::size_t denseTextureBytes() const;

    // Binds the node buffers to the bindings of octree.glsl and sets its uniforms.
    void bind(GLuint program) const;
};

}  // namespace vct
