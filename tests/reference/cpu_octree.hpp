#pragma once
// CPU reference sparse octree over an occupied-cell set: which nodes exist at each level, their
// child masks and same-level neighbours. The GPU octree's node counts and pointers are checked
// against this.
//
// Levels as in engine/voxel/voxel_grid.hpp: level l (0 ≤ l < levels) has nodes of edge
// 2^(levels − l) cells; level 0 is the root, level levels − 1 the leaves (2³ cells each). A node
// exists iff at least one occupied cell lies inside it, so an empty cell set has no nodes at all
// (not even a root); any non-empty set has nodes[0] = {0}.
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace vct::reference {

struct CpuOctree {
    int levels = 0;
    // nodes[l]: sorted unique packed (packCell) node coordinates at level l, coordinate =
    // cell >> (levels − l) per component. Sorted packed order = z, then y, then x.
    std::vector<std::vector<std::uint32_t>> nodes;
    // The occupied cells themselves, sorted unique (the "children" of the leaf level).
    std::vector<std::uint32_t> cells;

    bool hasNode(int level, glm::uvec3 coord) const;
    // Bit (cx | cy << 1 | cz << 2) set for each existing child, cx = child.x & 1 etc. The children
    // of a leaf node (level levels − 1) are its occupied cells.
    std::uint8_t childMask(int level, glm::uvec3 coord) const;
    // The node at coord ± 1 along axis (0 = x, 1 = y, 2 = z; sign = ±1) at the same level, if it
    // exists (nullopt at the border of the grid).
    std::optional<glm::uvec3> neighbour(int level, glm::uvec3 coord, int axis, int sign) const;
};

// Throws std::invalid_argument for levels outside 1..10 or a cell outside [0, 2^levels)³.
CpuOctree buildCpuOctree(const std::vector<std::uint32_t>& cells, int levels);

// The octree of the cells that carry a value (the keys of a per-cell map).
template <class Value>
CpuOctree buildCpuOctree(const std::map<std::uint32_t, Value>& cellValues, int levels) {
    std::vector<std::uint32_t> cells;
    cells.reserve(cellValues.size());
    for (const auto& entry : cellValues) cells.push_back(entry.first);
    return buildCpuOctree(cells, levels);
}

}  // namespace vct::reference
