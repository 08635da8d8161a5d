#include "reference/cpu_bricks.hpp"

#include <algorithm>

#include "reference/cpu_octree.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct::reference {

namespace {

int sampleIndex(glm::ivec3 s) { return s.x + 3 * s.y + 9 * s.z; }

// Leaf level (h = 1): P_n(q) = 1/8 · Σ V(c) over the cells c inside n whose closed cube [c, c+1]³
// contains q. Node n covers cells 2n + b, b ∈ {0,1}³; q = 2n + s, s ∈ {0,1,2}³; the cell contains
// q iff b ≤ s ≤ b + 1 on every axis.
Brick leafPartial(glm::uvec3 node, const std::map<std::uint32_t, glm::dvec4>& cellValues) {
    std::array<glm::dvec4, 8> cells{};  // V of cell 2n + b at bit b.x | b.y << 1 | b.z << 2; empty = 0
    for (int bit = 0; bit < 8; ++bit) {
        const auto cell = cellValues.find(packCell(2u * node + glm::uvec3(bit & 1, (bit >> 1) & 1, (bit >> 2) & 1)));
        if (cell != cellValues.end()) cells[bit] = cell->second;
    }
    Brick brick{};
    for (int s = 0; s < 27; ++s) {
        const glm::ivec3 sample(s % 3, (s / 3) % 3, s / 9);
        glm::dvec4 sum(0.0);
        for (int bit = 0; bit < 8; ++bit) {  // cells in packed (z, y, x) order
            const glm::ivec3 b(bit & 1, (bit >> 1) & 1, (bit >> 2) & 1);
            if (glm::any(glm::lessThan(sample, b)) || glm::any(glm::greaterThan(sample, b + 1))) continue;
            sum += cells[bit];
        }
        brick[s] = sum / 8.0;
    }
    return brick;
}

// Parents: P_n(Q) = Σ over children c of n, Σ over d ∈ {−1,0,1}³ with Q + d·h/2 inside c's closed
// cube: w(d) · P_c(Q + d·h/2), w(d) = Π (d = 0 ? 1/2 : 1/4). With Q = n·2h + s·h and
// c = 2n + b (min corner n·2h + b·h, child spacing h/2), the child sample index of Q + d·h/2 is
// 2s + d − 2b, which must lie in {0,1,2}³. Missing children have P_c = 0 and are skipped.
Brick parentPartial(glm::uvec3 node, const std::map<std::uint32_t, Brick>& childPartials) {
    Brick brick{};
    for (int s = 0; s < 27; ++s) {
        const glm::ivec3 sample(s % 3, (s / 3) % 3, s / 9);
        glm::dvec4 sum(0.0);
        for (int bit = 0; bit < 8; ++bit) {  // children in packed (z, y, x) order
            const glm::ivec3 b(bit & 1, (bit >> 1) & 1, (bit >> 2) & 1);
            const auto child = childPartials.find(packCell(2u * node + glm::uvec3(b)));
            if (child == childPartials.end()) continue;
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const glm::ivec3 d(dx, dy, dz);
                        const glm::ivec3 t = 2 * sample + d - 2 * b;
                        if (glm::any(glm::lessThan(t, glm::ivec3(0))) || glm::any(glm::greaterThan(t, glm::ivec3(2))))
                            continue;  // Q + d·h/2 is outside this child's closed cube
                        const double w = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25) * (dz == 0 ? 0.5 : 0.25);
                        sum += w * child->second[sampleIndex(t)];
                    }
        }
        brick[s] = sum;
    }
    return brick;
}

// S_n(q) = Σ P_m(q) over the nodes m of the level whose closed cube contains q, in canonical order
// (m by min corner z, then y, then x = ascending packed coordinate). Computed independently for
// every node that stores q, so that equal results across nodes are a property of the canonical
// order, not of sharing one computation.
Brick completeBrick(glm::uvec3 node, int level, const std::map<std::uint32_t, Brick>& partials) {
    const int extent = 1 << level;  // nodes per axis
    // The partials of the 3³ neighbourhood n + o, o ∈ {−1,0,1}³, looked up once (null: no node).
    std::array<const Brick*, 27> around{};
    for (int o = 0; o < 27; ++o) {
        const glm::ivec3 m = glm::ivec3(node) + glm::ivec3(o % 3 - 1, (o / 3) % 3 - 1, o / 9 - 1);
        if (glm::any(glm::lessThan(m, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(m, glm::ivec3(extent)))) continue;
        const auto it = partials.find(packCell(glm::uvec3(m)));
        if (it != partials.end()) around[o] = &it->second;
    }
    Brick brick{};
    for (int s = 0; s < 27; ++s) {
        const glm::ivec3 sample(s % 3, (s / 3) % 3, s / 9);
        // Node m = n + o holds q iff q's index in m, sample − 2o, is in {0,1,2}³ (per axis: sample 0
        // is also sample 2 of the node before, sample 2 also sample 0 of the node after). Looping
        // o with z outermost and x innermost visits the holders in ascending packed order, i.e.
        // the canonical order (min corner z, then y, then x).
        glm::dvec4 sum(0.0);
        for (int o = 0; o < 27; ++o) {
            const glm::ivec3 local = sample - 2 * glm::ivec3(o % 3 - 1, (o / 3) % 3 - 1, o / 9 - 1);
            if (!around[o] || glm::any(glm::lessThan(local, glm::ivec3(0))) || glm::any(glm::greaterThan(local, glm::ivec3(2))))
                continue;
            sum += (*around[o])[sampleIndex(local)];
        }
        brick[s] = sum;
    }
    return brick;
}

}  // namespace

CpuBricks computeCpuBricks(const std::map<std::uint32_t, glm::dvec4>& cellValues, int levels) {
    const CpuOctree tree = buildCpuOctree(cellValues, levels);  // validates levels and cells

    CpuBricks bricks;
    bricks.levels = levels;
    bricks.partial.resize(levels);
    bricks.complete.resize(levels);
    bricks.raw.resize(levels);

    // Partials bottom-up: leaves from the cells, each parent level from the level below.
    for (int l = levels - 1; l >= 0; --l)
        for (std::uint32_t packed : tree.nodes[l])
            bricks.partial[l][packed] = l == levels - 1 ? leafPartial(unpackCell(packed), cellValues)
                                                        : parentPartial(unpackCell(packed), bricks.partial[l + 1]);

    for (int l = 0; l < levels; ++l)
        for (std::uint32_t packed : tree.nodes[l])
            bricks.complete[l][packed] = completeBrick(unpackCell(packed), l, bricks.partial[l]);

    // Raw: Σ V over the occupied cells of the node (empty cells add 0), in packed cell order,
    // divided by the e_l³ cells of the node.
    for (int l = 0; l < levels; ++l) {
        const int shift = levels - l;
        for (std::uint32_t packed : tree.nodes[l]) bricks.raw[l][packed] = glm::dvec4(0.0);
        for (const auto& [cell, value] : cellValues)
            bricks.raw[l][packCell(unpackCell(cell) >> glm::uvec3(shift))] += value;
        const double cellsPerNode = double(1ull << (3 * shift));
        for (auto& [packed, value] : bricks.raw[l]) value /= cellsPerNode;
    }
    return bricks;
}

}  // namespace vct::reference
