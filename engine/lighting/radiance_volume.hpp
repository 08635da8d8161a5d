#pragma once
// Outgoing radiance stored in the octree (DESIGN 5.3): per voxel the area-average outgoing
// radiance of the surface inside it and the direction its reflected part leaves in, then filtered
// into bricks seen along each of six directions (brick_layout.hpp, "Slabs"). Rebuilt when lights
// change, only through the nodes beside light.
#include <vector>

#include "gl/compute.hpp"
#include "gl/objects.hpp"
#include "gl/shader_interface.hpp"
#include "voxel/octree.hpp"

namespace vct {

constexpr int kAccumulatorWords = gl::RADIANCE_ACCUMULATOR_WORDS;

struct RadianceVolume {
    // Per voxel (cell): 64-bit fixed-point sums of reflected flux (R, G, B: low, high words), the
    // sums of the photons' lit-side normals, their count and the sums of the normals' absolute
    // values (radiance_accumulators.glsl), and the resulting premultiplied radiance (L·τ, τ) and
    // the share of it that leaves towards each of the six axis directions (shaders/facing.glsl).
    gl::Buffer accumulators;  // kAccumulatorWords uints per cell
    gl::Buffer cellRadiance;  // vec4 per cell (touched ones; the rest 0: read opacity from the octree)
    gl::Buffer cellExitShares; // two vec4 per cell, likewise
    // The same two after the bounce pass's last bounce (the bounce pass sets cellRadiance and
    // cellExitShares back to the first bounce, which the radiance filter starts from): what narrow
    // cones thinner than a voxel read while the bricks hold more than one bounce. Empty until a
    // frame gathers bounces.
    gl::Buffer bouncedCellRadiance, bouncedCellExitShares;

    // Touched nodes: a flag per node (all levels and the cells) and, per level, the list of the
    // touched nodes stored at [levelStart[l], levelStart[l] + count[l]) of `touchedList`.
    // "Border" nodes: touched nodes and every node sharing a brick sample with one (their 3³
    // neighbourhood): the nodes whose samples can be other than zero.
    gl::Buffer touchedFlag, touchedList;
    gl::Buffer borderFlag, borderList;
    gl::Buffer listCounts;    // uints: touched counts per level, border counts per level, photons missed, own bounce gathers
    gl::Buffer indirectArgs;  // dispatch arguments, 3 uints per slot

    // What each brick sample's slab sends towards a cone travelling along +x, −x, +y, −y, +z, −z
    // (brick_layout.hpp, "Slabs"), premultiplied by the slab's density: (L·τ, τ), RGBA32F. Not half
    // floats: radiance follows the lights over 12 decades (1e-6 .. 1e6 W/sr) and half floats would
    // flush dim light to 0 and turn bright light into Inf (and the image into NaN).
    // One texture for the six directions, each a pool of one brick per node laid out as
    // `directionalBricks`, stacked along z in that order (shaders/directional_pool.glsl). One texture
    // rather than six because a cone picks the direction at run time, and a sampler array indexed
    // at run time costs llvmpipe about twice the lookup.
    gl::Texture directional;
    glm::ivec3 directionalBricks{1};
    // How many bounces of light the radiance bricks hold: 1 after the radiance filter, more after
    // the bounce pass. The voxels' own radiance (cellRadiance) always holds the first, and
    // bouncedCellRadiance as many as the bricks when they hold more.
    int bricksBounces = 1;
    // The voxels' radiance and exit shares with as many bounces as the bricks: what the passes
    // that read voxels (narrow cones thinner than a voxel, the voxel view) must read.
    const gl::Buffer& seenCellRadiance() const { return bricksBounces > 1 ? bouncedCellRadiance : cellRadiance; }
    const gl::Buffer& seenCellExitShares() const { return bricksBounces > 1 ? bouncedCellExitShares : cellExitShares; }
    // The geometry bricks (Octree::geometryBricksBuild) over whose density every node outside the
    // border lists holds no light (shaders/radiance_clear.comp); 0: none yet. While they are the
    // octree's, a new filtering only has to clear the bricks of the last one's border nodes that
    // are not on its own border.
    std::uint64_t darkOutsideBorderFor = 0;

    double wattsPerUnit = 0.0;  // fixed point of the photon sums (fluxWattsPerUnit, inject.hpp)
    // The octree build (Octree::geometryBricksBuild) the buffers were last fitted to.
    std::uint64_t octreeBuild = 0;

    // GPU memory held (the buffers may hold more than the octree needs: gl::fitBuffer).
    std::size_t bytes() const;
};

// Sizes everything for `octree` (once per octree build), keeping the storage of the previous
// build where it fits (gl::fitBuffer, fitBrickPool), and forgets what it held.
void fitRadianceVolume(const Octree& octree, RadianceVolume& volume);

// Sets list counts [first, end) (gl::*_SLOT) to zero.
void clearListCounts(const RadianceVolume& volume, unsigned first, unsigned end);

// The directional pool bound to `call` with its layout uniform: as a sampler for the cones and
// views, or as an image for the passes that write it.
void bindDirectionalTexture(gl::ComputeCall& call, const RadianceVolume& volume);
void bindDirectionalImage(gl::ComputeCall& call, const RadianceVolume& volume, GLenum access);

// Per-level numbers read back for the timing report (touched / all nodes).
struct RadianceStatistics {
    std::vector<std::uint32_t> touchedPerLevel;  // levels 0..L (L = cells)
    std::uint32_t photonsMissed = 0;
};
RadianceStatistics readRadianceStatistics(const Octree& octree, const RadianceVolume& volume);

}  // namespace vct
