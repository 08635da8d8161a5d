#pragma once
// bounce pass: light that bounces more than once (`--bounces N`). Each further bounce gathers,
// for every occupied voxel, the irradiance arriving at its surface by cones through the radiance
// bricks as they stand (shaders/bounce_gather.comp), sets the voxel's outgoing radiance to its
// first bounce plus ρ/π of that irradiance, and filters the radiance bricks again
// (RadianceFilter): after N − 1 of these the bricks hold N bounces. The voxels' own radiance is
// put back to the first bounce at the end, so that the radiance filter alone (after a change of
// the bounce count) gives one bounce again; a copy of their N bounces stays for the narrow cones
// that read voxels (RadianceVolume::bouncedCellRadiance). Cells whose parent's first child has nearly their
// normal take that child's gathered irradiance; of the others, those that agree with the parent's
// second gatherer take its irradiance, and the rest gather their own.
#include <array>

#include "gl/objects.hpp"
#include "lighting/list_dispatch.hpp"
#include "lighting/radiance_filter.hpp"
#include "render/cone_trace.hpp"

namespace vct {

constexpr int kMaxBounces = 8;

class BounceGather {
public:
    BounceGather();
    // Adds bounces 2..`bounces` to the radiance bricks, which must hold the first bounce.
    // `cones`: the cone set of the gather (the camera's settings, so that every bounce is gathered alike).
    void run(const Octree& octree, RadianceVolume& volume, RadianceFilter& filter, int bounces,
             const ConeSettings& cones);
    std::size_t bytes() const { return baseBytes_ + listBytes_; }
    // How many voxels of the last bounce gathered their own (read back from the GPU: statistics).
    std::uint32_t ownGathers(const RadianceVolume& volume) const;

private:
    // The two passes that gather, for each count of cone lanes (coneLanes), made on first use.
    struct Gathers {
        gl::Program firstChildren, listed;
    };
    const Gathers& gathers(int lanes);
    std::array<Gathers, kMaxConeLanes + 1> gathers_;
    gl::Program shareWithSiblings_, shareWithSecond_;
    ListDispatch listDispatch_;
    // The first bounce, (L·τ, τ) then (N·τ, τ) of every cell, then the irradiance on both sides
    // of every cell (written for first children).
    gl::Buffer base_;
    // The cells that gather their own from the front, those that share a leaf's second gather
    // from the end (SHARE_WITH_SIBLINGS lists both), one uint each.
    gl::Buffer ownGatherCells_;
    std::size_t baseBytes_ = 0, listBytes_ = 0;
};

}  // namespace vct
