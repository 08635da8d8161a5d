#pragma once
// CPU reference for the slab opacity of engine/voxel/brick_layout.hpp ("Slabs"), implemented
// literally and in double, one lattice point at a time, level by level bottom-up. The GPU pass is
// shaders/bricks_opacity.comp (variant LEAF for the leaf level, the other for every level above).
//
// Coordinates as in cpu_bricks.hpp: level l has nodes of edge e_l = 2^(levels − l) voxels and a
// sample lattice of spacing h_l = e_l / 2; lattice point P of level l (integer, in lattice units)
// sits at voxel position P·h_l. Sample (i, j, k) of the node with coordinate n is lattice point
// 2n + (i, j, k) and has index i + 3j + 9k.
//
// Definitions (a = the slab's axis, b = (a + 1) mod 3, c = (a + 2) mod 3, e_a the unit vector):
//   Leaf level (h = 1). The +a slab of lattice point q holds the 4 cells whose a-coordinate is q_a
//     and whose b- and c-coordinates are q_b − 1 or q_b and q_c − 1 or q_c; the −a slab the 4
//     cells with a-coordinate q_a − 1 (same b, c). T = mean over the 4 of (1 − min(α_a, 0.999)),
//     α_a the cell's opacity along a (0 for a cell that is not occupied).
//   Parent levels, child sample spacing h_c voxels. With T_c(p) = exp(−τ_c(p)·h_c) for the child
//     level's slab in the same direction at child-lattice point p (1 where p does not exist):
//       T_{+a}(Q) = Σ_{d_b, d_c ∈ {−1,0,1}} w(d_b)·w(d_c)·T_c(2Q + d)·T_c(2Q + d + e_a),
//       T_{−a}(Q) = Σ_{d_b, d_c ∈ {−1,0,1}} w(d_b)·w(d_c)·T_c(2Q + d)·T_c(2Q + d − e_a),
//     d = d_b·e_b + d_c·e_c, w = (¼, ½, ¼).
//   τ = min(−ln T / h, −ln 0.001) with h the level's sample spacing (h = 1 at the leaves,
//   h = 2·h_c above).
// A lattice point exists at level l iff some existing node of level l (a node exists iff an
// occupied cell lies inside it) contains it in its closed cube. Values belong to lattice points,
// so every node sharing a point holds the same value.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

namespace vct::reference {

// The six slab densities of one sample: τ+x, τ+y, τ+z, τ−x, τ−y, τ−z (per voxel length).
using SlabDensities = std::array<double, 6>;
using SlabBrick = std::array<SlabDensities, 27>;  // index i + 3j + 9k

struct CpuSlabOpacity {
    int levels = 0;
    // Per level 0..levels − 1, keyed by packed node coordinate (packCell), one entry per existing node.
    std::vector<std::map<std::uint32_t, SlabBrick>> nodes;
    // Per level, keyed by packLatticePoint(P): the value of every existing lattice point.
    std::vector<std::map<std::uint64_t, SlabDensities>> points;
};

// Lattice coordinates reach 2^levels (one past the last cell) and do not fit packCell's 10 bits.
inline std::uint64_t packLatticePoint(glm::ivec3 p) {
    return std::uint64_t(std::uint32_t(p.x)) | std::uint64_t(std::uint32_t(p.y)) << 21 |
           std::uint64_t(std::uint32_t(p.z)) << 42;
}

// cellOpacity: packed cell → (α_x, α_y, α_z) ∈ [0,1]; every key is an occupied cell (even with α = 0).
// Throws std::invalid_argument for levels outside 1..10 or a cell outside the grid.
CpuSlabOpacity computeCpuSlabOpacity(const std::map<std::uint32_t, glm::dvec3>& cellOpacity, int levels);

}  // namespace vct::reference
