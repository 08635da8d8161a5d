#include "reference/cpu_octree.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "voxel/voxel_grid.hpp"

namespace vct::reference {

namespace {

bool contains(const std::vector<std::uint32_t>& sorted, std::uint32_t value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

// Sorted unique packed coordinates of the level whose nodes are 2^shift cells wide.
std::vector<std::uint32_t> coarsen(const std::vector<std::uint32_t>& cells, int shift) {
    std::vector<std::uint32_t> out;
    out.reserve(cells.size());
    for (std::uint32_t cell : cells) out.push_back(packCell(unpackCell(cell) >> glm::uvec3(shift)));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

CpuOctree buildCpuOctree(const std::vector<std::uint32_t>& cells, int levels) {
    if (levels < 1 || levels > 10) throw std::invalid_argument("buildCpuOctree: levels " + std::to_string(levels));
    const std::uint32_t n = 1u << levels;
    for (std::uint32_t cell : cells) {
        const glm::uvec3 c = unpackCell(cell);
        // unpackCell drops bits above 30; a value with those set is not a packed cell.
        if (cell >> 30 || c.x >= n || c.y >= n || c.z >= n)
            throw std::invalid_argument("buildCpuOctree: cell " + std::to_string(cell) + " outside the grid");
    }
    CpuOctree tree;
    tree.levels = levels;
    tree.cells = coarsen(cells, 0);
    tree.nodes.resize(levels);
    for (int l = 0; l < levels; ++l) tree.nodes[l] = coarsen(tree.cells, levels - l);
    return tree;
}

bool CpuOctree::hasNode(int level, glm::uvec3 coord) const {
    if (level < 0 || level >= levels) return false;
    const std::uint32_t extent = 1u << level;  // nodes per axis at this level
    if (coord.x >= extent || coord.y >= extent || coord.z >= extent) return false;
    return contains(nodes[level], packCell(coord));
}

std::uint8_t CpuOctree::childMask(int level, glm::uvec3 coord) const {
    if (!hasNode(level, coord)) return 0;
    // Children of the leaf level are cells (the "level" `levels`).
    const std::vector<std::uint32_t>& children = level + 1 < levels ? nodes[level + 1] : cells;
    std::uint8_t mask = 0;
    for (std::uint32_t bit = 0; bit < 8; ++bit) {
        const glm::uvec3 child = 2u * coord + glm::uvec3(bit & 1u, (bit >> 1) & 1u, (bit >> 2) & 1u);
        if (contains(children, packCell(child))) mask |= std::uint8_t(1u << bit);
    }
    return mask;
}

std::optional<glm::uvec3> CpuOctree::neighbour(int level, glm::uvec3 coord, int axis, int sign) const {
    if (axis < 0 || axis > 2 || (sign != 1 && sign != -1)) throw std::invalid_argument("CpuOctree::neighbour");
    if (sign < 0 && coord[axis] == 0) return std::nullopt;  // unsigned: no wrap-around to 2^32 − 1
    glm::uvec3 other = coord;
    other[axis] = sign > 0 ? coord[axis] + 1u : coord[axis] - 1u;
    if (!hasNode(level, other)) return std::nullopt;
    return other;
}

}  // namespace vct::reference
