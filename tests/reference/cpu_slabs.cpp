#include "reference/cpu_slabs.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "reference/cpu_octree.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct::reference {

namespace {

const double kMaxOpacity = 0.999;                   // MAX_OPACITY (shaders/voxel_common.glsl)
const double kMaxDensity = -std::log(1.0 - 0.999);  // τ cap: −ln 0.001 per voxel

int sampleIndex(glm::ivec3 s) { return s.x + 3 * s.y + 9 * s.z; }

// Entry 0..2: +x, +y, +z; 3..5: −x, −y, −z.
int slot(int axis, bool plus) { return plus ? axis : 3 + axis; }

// τ = min(−ln T / h, −ln 0.001).
double density(double transmittance, double spacing) {
    return std::min(-std::log(transmittance) / spacing, kMaxDensity);
}

// The value at lattice point p, or null where p does not exist (also for negative coordinates,
// which packLatticePoint cannot represent).
const SlabDensities* find(const std::map<std::uint64_t, SlabDensities>& points, glm::ivec3 p) {
    if (glm::any(glm::lessThan(p, glm::ivec3(0)))) return nullptr;
    const auto it = points.find(packLatticePoint(p));
    return it == points.end() ? nullptr : &it->second;
}

// Leaf level (h = 1), lattice point q (= voxel position). For each axis a and side: the 4 cells
// with a-coordinate q_a (+a) or q_a − 1 (−a) and b-, c-coordinates q_b − 1 or q_b, q_c − 1 or q_c;
// T = mean of (1 − min(α_a, 0.999)), missing cells α_a = 0.
SlabDensities leafPoint(glm::ivec3 q, const std::map<std::uint32_t, glm::dvec3>& cellOpacity, int levels) {
    const int n = 1 << levels;
    SlabDensities out{};
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (bool plus : {true, false}) {
            double transmittance = 0.0;
            for (int ob = -1; ob <= 0; ++ob)
                for (int oc = -1; oc <= 0; ++oc) {
                    glm::ivec3 cell = q;
                    cell[a] = plus ? q[a] : q[a] - 1;
                    cell[b] += ob;
                    cell[c] += oc;
                    double alpha = 0.0;
                    if (glm::all(glm::greaterThanEqual(cell, glm::ivec3(0))) && glm::all(glm::lessThan(cell, glm::ivec3(n)))) {
                        const auto it = cellOpacity.find(packCell(glm::uvec3(cell)));
                        if (it != cellOpacity.end()) alpha = it->second[a];
                    }
                    transmittance += 0.25 * (1.0 - std::min(alpha, kMaxOpacity));
                }
            out[slot(a, plus)] = density(transmittance, 1.0);
        }
    }
    return out;
}

// Parent level, lattice point Q; `children` the child level's points, child spacing hChild voxels.
// T_{±a}(Q) = Σ_{d_b, d_c} w(d_b) w(d_c) · T_c(2Q + d) · T_c(2Q + d ± e_a), T_c(p) = exp(−τ_c(p)·h_c)
// of the child slab in the same direction, 1 where p does not exist; τ = min(−ln T / (2 h_c), cap).
SlabDensities parentPoint(glm::ivec3 Q, const std::map<std::uint64_t, SlabDensities>& children, double hChild) {
    const double w[3] = {0.25, 0.5, 0.25};
    auto childTransmittance = [&](glm::ivec3 p, int entry) {
        const SlabDensities* child = find(children, p);
        return child ? std::exp(-(*child)[entry] * hChild) : 1.0;
    };
    SlabDensities out{};
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        glm::ivec3 ea(0);
        ea[a] = 1;
        for (bool plus : {true, false}) {
            const int entry = slot(a, plus);
            double transmittance = 0.0;
            for (int db = -1; db <= 1; ++db)
                for (int dc = -1; dc <= 1; ++dc) {
                    glm::ivec3 p = 2 * Q;
                    p[b] += db;
                    p[c] += dc;
                    const glm::ivec3 next = plus ? p + ea : p - ea;  // the slab's second child slab
                    transmittance += w[db + 1] * w[dc + 1] * childTransmittance(p, entry) * childTransmittance(next, entry);
                }
            out[entry] = density(transmittance, 2.0 * hChild);
        }
    }
    return out;
}

}  // namespace

CpuSlabOpacity computeCpuSlabOpacity(const std::map<std::uint32_t, glm::dvec3>& cellOpacity, int levels) {
    const CpuOctree tree = buildCpuOctree(cellOpacity, levels);  // validates levels and cells

    CpuSlabOpacity result;
    result.levels = levels;
    result.nodes.resize(levels);
    result.points.resize(levels);
    for (int l = levels - 1; l >= 0; --l) {
        // The existing lattice points: the 27 samples 2n + s of every existing node n.
        std::set<std::uint64_t> seen;
        std::vector<glm::ivec3> points;
        for (std::uint32_t packed : tree.nodes[l])
            for (int s = 0; s < 27; ++s) {
                const glm::ivec3 p = 2 * glm::ivec3(unpackCell(packed)) + glm::ivec3(s % 3, (s / 3) % 3, s / 9);
                if (seen.insert(packLatticePoint(p)).second) points.push_back(p);
            }
        const double hChild = double(1 << std::max(0, levels - l - 2));  // the child level's spacing (l < levels − 1)
        for (const glm::ivec3& p : points)
            result.points[l][packLatticePoint(p)] =
                l == levels - 1 ? leafPoint(p, cellOpacity, levels) : parentPoint(p, result.points[l + 1], hChild);
        for (std::uint32_t packed : tree.nodes[l]) {
            SlabBrick& brick = result.nodes[l][packed];
            for (int s = 0; s < 27; ++s) {
                const glm::ivec3 sample(s % 3, (s / 3) % 3, s / 9);
                brick[sampleIndex(sample)] = result.points[l].at(packLatticePoint(2 * glm::ivec3(unpackCell(packed)) + sample));
            }
        }
    }
    return result;
}

}  // namespace vct::reference
