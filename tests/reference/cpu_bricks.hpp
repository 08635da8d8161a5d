#pragma once
// CPU reference for the brick samples of engine/voxel/brick_layout.hpp, implemented literally and
// in double: leaf partials (box filter), parent partials (¼ ½ ¼ tent over the children's
// partials), complete bricks (canonical-order sums of the partials of every node sharing a
// sample) and raw node values (mean over the node's cells).
//
// Coordinates. Lattice points are integer voxel-space points: level l has node edge
// e_l = 2^(levels − l) and sample spacing h_l = e_l / 2 ≥ 1. Sample (i, j, k) of the node with
// coordinate n sits at n·e_l + (i, j, k)·h_l and has index i + 3j + 9k.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

namespace vct::reference {

using Brick = std::array<glm::dvec4, 27>;  // index i + 3j + 9k

struct CpuBricks {
    int levels = 0;
    // Per level 0..levels − 1, keyed by packed node coordinate (packCell), one entry per existing
    // node (a node exists iff an occupied cell — a key of cellValues — lies inside it).
    std::vector<std::map<std::uint32_t, Brick>> complete;  // S_n
    std::vector<std::map<std::uint32_t, Brick>> partial;   // P_n
    std::vector<std::map<std::uint32_t, glm::dvec4>> raw;  // mean V over the node's e_l³ cells
};

// cellValues: packed cell → premultiplied V = (ρ·α, α); every key is an occupied cell even if its
// value is 0. Throws std::invalid_argument for levels outside 1..10 or a cell outside the grid.
CpuBricks computeCpuBricks(const std::map<std::uint32_t, glm::dvec4>& cellValues, int levels);

}  // namespace vct::reference
