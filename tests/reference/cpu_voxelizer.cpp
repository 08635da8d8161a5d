#include "reference/cpu_voxelizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace vct::reference {

std::optional<glm::dvec3> findSeparatingAxis(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 boxCentre,
                                             glm::dvec3 boxHalfSize) {
    // Work relative to the box centre so the box projects onto the axis as [−r, r].
    const std::array<glm::dvec3, 3> v = {a - boxCentre, b - boxCentre, c - boxCentre};
    const std::array<glm::dvec3, 3> edges = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    const std::array<glm::dvec3, 3> boxAxes = {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};

    // Disjoint projections of two closed sets: strictly apart. Touching (equal end points) is an
    // overlap. A zero axis gives p = 0 and r = 0 and so never separates.
    const auto separates = [&](const glm::dvec3& axis) {
        const double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
        const double r = boxHalfSize.x * std::abs(axis.x) + boxHalfSize.y * std::abs(axis.y) +
                         boxHalfSize.z * std::abs(axis.z);
        return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
    };

    for (const glm::dvec3& axis : boxAxes)
        if (separates(axis)) return axis;
    const glm::dvec3 normal = glm::cross(edges[0], edges[1]);
    if (separates(normal)) return normal;
    for (const glm::dvec3& edge : edges)
        for (const glm::dvec3& boxAxis : boxAxes) {
            const glm::dvec3 axis = glm::cross(edge, boxAxis);
            if (separates(axis)) return axis;
        }
    return std::nullopt;
}

bool triangleOverlapsBox(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 boxCentre, glm::dvec3 boxHalfSize) {
    return !findSeparatingAxis(a, b, c, boxCentre, boxHalfSize).has_value();
}

std::vector<std::uint32_t> voxelizeTriangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, int levels) {
    std::vector<std::uint32_t> cells;
    // A NaN compares false everywhere, so the SAT would call it overlapping everything.
    for (const glm::dvec3& v : {a, b, c})
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return cells;
    const glm::dvec3 lo = glm::min(a, glm::min(b, c));
    const glm::dvec3 hi = glm::max(a, glm::max(b, c));

    // The closed cell [x, x+1] meets [lo, hi] iff ceil(lo) − 1 ≤ x ≤ floor(hi). Clamp in double
    // before converting so that far-away coordinates cannot overflow an int.
    const double n = double(1 << levels);
    glm::ivec3 first, last;
    for (int axis = 0; axis < 3; ++axis) {
        first[axis] = int(std::clamp(std::ceil(lo[axis]) - 1.0, 0.0, n));
        last[axis] = int(std::clamp(std::floor(hi[axis]), -1.0, n - 1.0));
    }
    const glm::dvec3 half(0.5);
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x)
                if (triangleOverlapsBox(a, b, c, glm::dvec3(x, y, z) + half, half))
                    cells.push_back(packCell(glm::uvec3(x, y, z)));
    std::sort(cells.begin(), cells.end());  // z-major loops already give packed order; keep it explicit
    return cells;
}

std::vector<std::uint32_t> voxelizeScene(const Scene& scene, const VoxelGrid& grid) {
    std::vector<std::uint32_t> cells;
    const auto voxel = [&](std::uint32_t index) {
        return grid.toVoxel(glm::dvec3(scene.vertices.at(index).position));
    };
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        const std::vector<std::uint32_t> triangleCells =
            voxelizeTriangle(voxel(scene.indices[3 * t]), voxel(scene.indices[3 * t + 1]),
                             voxel(scene.indices[3 * t + 2]), grid.levels);
        cells.insert(cells.end(), triangleCells.begin(), triangleCells.end());
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

}  // namespace vct::reference
