#pragma once
// svo_build pass (DESIGN §4 pass 2): the octree's structure, top-down, level by level, from the
// fragment list: flag (fragments mark child slots) → allocate (children placed by a prefix sum
// over the level's nodes, in node order: no atomics, so the pool is identical on every run) →
// init (parents write their children) → descend (fragments move one level down).
// The node pool grows as levels are added and is trimmed to the exact total at the end.
#include "gl/prefix_sum.hpp"
#include "voxel/octree.hpp"

namespace vct {

class SvoBuild {
public:
    SvoBuild();
    // Builds octree.{levels, level tables, child, mask, coord, parent}; leaves in
    // `fragmentNode` (one r32ui texel per fragment) the cell node of every fragment.
    void run(const FragmentList& fragments, const VoxelGrid& grid, Octree& octree);

    GLuint fragmentNodeTexture() const { return fragmentNodeTexture_.id(); }

private:
    void ensureCapacity(Octree& octree, std::uint32_t nodes);
    gl::Program flag_, alloc_, init_, descend_;
    gl::PrefixSum prefixSum_;
    gl::Buffer counts_;
    std::uint32_t countsCapacity_ = 0;
    std::uint32_t poolCapacity_ = 0;
    gl::Buffer fragmentNode_;
    gl::Texture fragmentNodeTexture_;
};

}  // namespace vct
