// Tests of the CPU references themselves (cpu_voxelizer, cpu_octree, cpu_bricks): they are the
// ground truth for the GPU passes, so each property is checked against an independent oracle
// (exact integer LP, brute force, direct lattice filters) or a hand-computed value.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <queue>
#include <random>
#include <set>

#include "reference/cpu_bricks.hpp"
#include "reference/cpu_octree.hpp"
#include "reference/cpu_voxelizer.hpp"
#include "scene/scene_loader.hpp"
#include "voxel/voxel_grid.hpp"

namespace {

using glm::dvec3;
using glm::dvec4;
using glm::uvec3;
using namespace vct::reference;

// Portable random numbers (the std distributions are implementation-defined).
double uniform(std::mt19937_64& rng, double lo, double hi) { return lo + (hi - lo) * double(rng() >> 11) * 0x1p-53; }
int uniformInt(std::mt19937_64& rng, int lo, int hi) { return lo + int(rng() % std::uint64_t(hi - lo + 1)); }

// ---- An independent, exact triangle/box oracle for integer coordinates --------------------------
// The closed triangle meets the closed box iff the 2D LP "P(u,v) = a + u(b−a) + v(c−a) in the box,
// u ≥ 0, v ≥ 0, u + v ≤ 1" is feasible. The feasible set is a bounded convex polygon (possibly a
// segment or point); if non-empty it has a vertex where two constraints with independent normals
// are tight. So: intersect every pair of constraint lines exactly (Cramer, integers) and check all
// constraints exactly. Works unchanged for degenerate triangles.
bool exactOverlapOracle(glm::i64vec3 a, glm::i64vec3 b, glm::i64vec3 c, glm::i64vec3 lo, glm::i64vec3 hi) {
    struct Constraint { std::int64_t alpha, beta, gamma; };  // alpha·u + beta·v ≤ gamma
    const glm::i64vec3 e1 = b - a, e2 = c - a;
    std::vector<Constraint> cs = {{-1, 0, 0}, {0, -1, 0}, {1, 1, 1}};
    for (int k = 0; k < 3; ++k) {
        cs.push_back({e1[k], e2[k], hi[k] - a[k]});
        cs.push_back({-e1[k], -e2[k], a[k] - lo[k]});
    }
    for (std::size_t p = 0; p < cs.size(); ++p)
        for (std::size_t q = p + 1; q < cs.size(); ++q) {
            const std::int64_t det = cs[p].alpha * cs[q].beta - cs[q].alpha * cs[p].beta;
            if (det == 0) continue;
            const std::int64_t nu = cs[p].gamma * cs[q].beta - cs[q].gamma * cs[p].beta;  // u = nu / det
            const std::int64_t nv = cs[p].alpha * cs[q].gamma - cs[q].alpha * cs[p].gamma; // v = nv / det
            const bool feasible = std::all_of(cs.begin(), cs.end(), [&](const Constraint& k) {
                const std::int64_t lhs = k.alpha * nu + k.beta * nv, rhs = k.gamma * det;
                return det > 0 ? lhs <= rhs : lhs >= rhs;
            });
            if (feasible) return true;
        }
    return false;
}

bool parallel(dvec3 x, dvec3 y) { return glm::length(x) > 0 && glm::length(glm::cross(x, y)) == 0.0; }

const dvec3 kCentre(0.0), kHalf(1.0);  // the box [−1, 1]³ of the SAT tests

// ---- SAT ------------------------------------------------------------------------------------------

TEST(ReferenceSat, TriangleInsideBoxOverlaps) {
    EXPECT_TRUE(triangleOverlapsBox({-0.5, -0.5, 0.1}, {0.5, -0.2, 0.0}, {0.0, 0.6, -0.3}, kCentre, kHalf));
    // A huge triangle containing the whole box also overlaps (no vertex inside).
    EXPECT_TRUE(triangleOverlapsBox({-100, -100, 0.3}, {100, -100, 0.3}, {0, 100, 0.3}, kCentre, kHalf));
}

TEST(ReferenceSat, SeparatedByEachBoxAxis) {
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            dvec3 a(0.0, 0.1, 0.2), b(0.3, -0.4, 0.1), c(-0.2, 0.2, -0.5);
            a[axis] = b[axis] = c[axis] = sign * 1.25;
            b[axis] += sign * 0.5;
            const auto found = findSeparatingAxis(a, b, c, kCentre, kHalf);
            ASSERT_TRUE(found) << "axis " << axis << " sign " << sign;
            dvec3 expected(0.0);
            expected[axis] = 1.0;
            EXPECT_EQ(*found, expected);
        }
}

TEST(ReferenceSat, SeparatedOnlyByTheNormal) {
    // A big triangle in the plane x + y + z = 3.1, just beyond the box corner (1,1,1) (x+y+z = 3).
    // Its AABB contains the box and its edges are far away: only the normal separates.
    // (findSeparatingAxis tries the box axes first, so getting the normal back shows they do not
    // separate; each edge × axis projects the triangle onto an interval around 0, e.g. for
    // AB × z ∥ (1,1,0): [−20, 13.1] against the box's [−2, 2].)
    const dvec3 a(23.1, -10, -10), b(-10, 23.1, -10), c(-10, -10, 23.1);
    const auto found = findSeparatingAxis(a, b, c, kCentre, kHalf);
    ASSERT_TRUE(found);
    EXPECT_TRUE(parallel(*found, dvec3(1, 1, 1))) << found->x << " " << found->y << " " << found->z;
    // The same triangle in the plane x + y + z = 3 touches the corner (closed box): overlap.
    EXPECT_TRUE(triangleOverlapsBox({23, -10, -10}, {-10, 23, -10}, {-10, -10, 23}, kCentre, kHalf));
}

TEST(ReferenceSat, SeparatedOnlyByAnEdgeCrossProduct) {
    // Edge AB runs along x + y = 2.1 beside the box edge x = y = 1 (x + y = 2); C rises away from
    // the box. The triangle's AABB overlaps the box and its plane cuts the box, but the whole
    // triangle has x + y ≥ 2.1: the separating axis is AB × z ∥ (1, 1, 0). Getting it back shows
    // the box axes and the normal (5.5, 5.5, −4.29) (triangle at 11.55, box radius 15.29) fail.
    const dvec3 a(1.6, 0.5, 0.0), b(0.5, 1.6, 0.0), c(3.0, 3.0, 5.0);
    const dvec3 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    ASSERT_TRUE(glm::all(glm::lessThanEqual(lo, kCentre + kHalf)) && glm::all(glm::greaterThanEqual(hi, kCentre - kHalf)));
    const auto found = findSeparatingAxis(a, b, c, kCentre, kHalf);
    ASSERT_TRUE(found);
    EXPECT_TRUE(parallel(*found, dvec3(1, 1, 0))) << found->x << " " << found->y << " " << found->z;
    // The same triangle pushed to x + y = 2 touches the box edge at (1, 1, 0): overlap.
    EXPECT_TRUE(triangleOverlapsBox({1.5, 0.5, 0}, {0.5, 1.5, 0}, {3, 3, 5}, kCentre, kHalf));
}

TEST(ReferenceSat, TouchingCountsAsOverlap) {
    const double eps = 0x1p-30;
    struct Case { const char* what; dvec3 a, b, c, outward; };
    const Case cases[] = {
        {"vertex on a face", {1, 0.2, 0.3}, {2, 0.5, 0.1}, {2.5, -0.3, 0.4}, {1, 0, 0}},
        {"vertex on a corner", {1, 1, 1}, {2, 1.5, 1.2}, {1.3, 2, 1.7}, {1, 1, 1}},
        {"edge through a box edge", {2, 0, 0.25}, {0, 2, 0.25}, {3, 3, 0.25}, {1, 1, 0}},
        {"edge along a box edge", {1, 1, -3}, {1, 1, 3}, {2, 3, 0}, {1, 1, 0}},
        {"edge crossing a face diagonal", {1, -3, 0.5}, {1, 3, -0.5}, {4, 0, 0}, {1, 0, 0}},
        {"lying in a face plane", {-1, -0.5, -3}, {-1, 3, 0.5}, {-1, -3, 2}, {-1, 0, 0}},
        {"flat below the bottom face", {-5, -5, -1}, {5, -5, -1}, {0, 5, -1}, {0, 0, -1}},
    };
    for (const Case& t : cases) {
        EXPECT_TRUE(triangleOverlapsBox(t.a, t.b, t.c, kCentre, kHalf)) << t.what;
        const dvec3 d = eps * t.outward;
        EXPECT_FALSE(triangleOverlapsBox(t.a + d, t.b + d, t.c + d, kCentre, kHalf)) << t.what << ", moved out";
    }
}

TEST(ReferenceSat, DegenerateSegmentsAndPoints) {
    // Segments (two equal vertices, or three collinear ones).
    EXPECT_TRUE(triangleOverlapsBox({-3, 0.2, 0.1}, {3, 0.4, -0.2}, {3, 0.4, -0.2}, kCentre, kHalf));
    EXPECT_TRUE(triangleOverlapsBox({-3, -3, -3}, {0, 0, 0}, {3, 3, 3}, kCentre, kHalf));  // collinear, through
    EXPECT_TRUE(triangleOverlapsBox({2, 0, 0.5}, {0, 2, 0.5}, {0, 2, 0.5}, kCentre, kHalf));   // touches edge x=y=1
    // Beside the box edge x = y = 1 (only the direction × z axis separates it).
    const auto found = findSeparatingAxis({2.25, 0, 0.5}, {0, 2.25, 0.5}, {0, 2.25, 0.5}, kCentre, kHalf);
    ASSERT_TRUE(found);
    EXPECT_TRUE(parallel(*found, dvec3(1, 1, 0)));
    EXPECT_FALSE(triangleOverlapsBox({-3, 1.5, 0}, {3, 1.5, 0}, {0, 1.5, 0}, kCentre, kHalf));  // collinear, above
    // Points (all three vertices equal).
    EXPECT_TRUE(triangleOverlapsBox(dvec3(0.3), dvec3(0.3), dvec3(0.3), kCentre, kHalf));
    EXPECT_TRUE(triangleOverlapsBox(dvec3(1), dvec3(1), dvec3(1), kCentre, kHalf));  // a corner
    EXPECT_TRUE(triangleOverlapsBox({1, 0, -1}, {1, 0, -1}, {1, 0, -1}, kCentre, kHalf));
    EXPECT_FALSE(triangleOverlapsBox({1, 0, -1.5}, {1, 0, -1.5}, {1, 0, -1.5}, kCentre, kHalf));
    EXPECT_FALSE(triangleOverlapsBox(dvec3(1.0 + 0x1p-40), dvec3(1.0 + 0x1p-40), dvec3(1.0 + 0x1p-40), kCentre, kHalf));
}

TEST(ReferenceSat, MatchesExactOracleOnRandomIntegerTriangles) {
    // Small integer coordinates make touching, coplanar and degenerate configurations common and
    // keep every product in the SAT exact in double, so the two must agree exactly.
    std::mt19937_64 rng(12345);
    int overlapping = 0, separated = 0, degenerate = 0;
    const int count = 40000;
    for (int n = 0; n < count; ++n) {
        glm::i64vec3 lo, hi, v[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = uniformInt(rng, -2, 1);
            hi[k] = lo[k] + uniformInt(rng, 0, 3);  // zero-thickness boxes too
            for (auto& p : v) p[k] = uniformInt(rng, -4, 4);
        }
        const int kind = uniformInt(rng, 0, 9);
        if (kind == 0) v[2] = v[1];                                     // segment
        if (kind == 1) v[2] = v[0] + std::int64_t(2) * (v[1] - v[0]);                 // collinear
        if (kind == 2) v[1] = v[2] = v[0];                              // point
        const bool isDegenerate = glm::all(glm::equal(glm::cross(dvec3(v[1] - v[0]), dvec3(v[2] - v[0])), dvec3(0)));
        const bool expected = exactOverlapOracle(v[0], v[1], v[2], lo, hi);
        const bool actual = triangleOverlapsBox(dvec3(v[0]), dvec3(v[1]), dvec3(v[2]), 0.5 * dvec3(lo + hi),
                                                0.5 * dvec3(hi - lo));
        ASSERT_EQ(actual, expected) << "triangle " << n << ": (" << v[0].x << "," << v[0].y << "," << v[0].z << ") ("
                                    << v[1].x << "," << v[1].y << "," << v[1].z << ") (" << v[2].x << "," << v[2].y
                                    << "," << v[2].z << ") box lo (" << lo.x << "," << lo.y << "," << lo.z
                                    << ") hi (" << hi.x << "," << hi.y << "," << hi.z << ")";
        (expected ? overlapping : separated) += 1;
        degenerate += isDegenerate;
    }
    std::printf("[ reference ] SAT vs exact LP oracle: %d triangles, %d overlapping, %d separated, %d degenerate\n",
                count, overlapping, separated, degenerate);
    EXPECT_GT(overlapping, count / 10);
    EXPECT_GT(separated, count / 10);
}

// ---- voxelizeTriangle / voxelizeScene ---------------------------------------------------------

std::set<std::uint32_t> cellSet(int zFirst, int zLast, int xyFirst, int xyLast) {
    std::set<std::uint32_t> s;
    for (int z = zFirst; z <= zLast; ++z)
        for (int y = xyFirst; y <= xyLast; ++y)
            for (int x = xyFirst; x <= xyLast; ++x) s.insert(vct::packCell(uvec3(x, y, z)));
    return s;
}

std::set<std::uint32_t> squareCells(double z, int levels) {
    std::set<std::uint32_t> s;
    for (auto cells : {voxelizeTriangle({1.5, 1.5, z}, {4.5, 1.5, z}, {4.5, 4.5, z}, levels),
                       voxelizeTriangle({1.5, 1.5, z}, {4.5, 4.5, z}, {1.5, 4.5, z}, levels)})
        s.insert(cells.begin(), cells.end());
    return s;
}

TEST(ReferenceVoxelizer, SquareInsideACellLayer) {
    EXPECT_EQ(squareCells(3.2, 5), cellSet(3, 3, 1, 4));  // 16 cells
}

TEST(ReferenceVoxelizer, SquareOnACellBoundaryOccupiesBothLayers) {
    const auto cells = squareCells(3.0, 5);
    EXPECT_EQ(cells.size(), 32u);
    EXPECT_EQ(cells, cellSet(2, 3, 1, 4));
}

TEST(ReferenceVoxelizer, SubVoxelTriangleIsOneCell) {
    const auto cells = voxelizeTriangle({3.2, 4.3, 5.4}, {3.3, 4.35, 5.5}, {3.25, 4.4, 5.45}, 5);
    EXPECT_EQ(cells, std::vector<std::uint32_t>{vct::packCell(uvec3(3, 4, 5))});
    // A tiny triangle with a vertex exactly on a cell corner touches all 8 cells around it.
    EXPECT_EQ(voxelizeTriangle({4, 4, 4}, {4.1, 4.05, 4.2}, {4.2, 4.1, 4.05}, 5).size(), 8u);
}

TEST(ReferenceVoxelizer, ResultIsSortedAndClampedToTheGrid) {
    // A triangle sticking out of the 32³ grid on every side.
    const auto cells = voxelizeTriangle({-10, -10, 16.5}, {50, -5, 16.5}, {10, 60, 16.5}, 5);
    EXPECT_TRUE(std::is_sorted(cells.begin(), cells.end()));
    EXPECT_EQ(std::adjacent_find(cells.begin(), cells.end()), cells.end());
    for (std::uint32_t c : cells) EXPECT_TRUE(glm::all(glm::lessThan(vct::unpackCell(c), uvec3(32))));
    EXPECT_GT(cells.size(), 100u);
    EXPECT_TRUE(voxelizeTriangle({-5, -5, -5}, {-3, -1, -2}, {-1, -4, -0.5}, 5).empty());  // outside
    EXPECT_TRUE(voxelizeTriangle({40, 1, 1}, {41, 2, 1}, {40, 3, 2}, 5).empty());
    EXPECT_TRUE(voxelizeTriangle({1, 1, 1}, {2, 2, 2}, {NAN, 1, 1}, 5).empty());
    // Touching the grid's outer faces from outside still counts (closed cells).
    EXPECT_EQ(voxelizeTriangle({32, 3.5, 3.5}, {33, 3.5, 3.5}, {32.5, 4.5, 3.5}, 5),
              std::vector<std::uint32_t>{vct::packCell(uvec3(31, 3, 3))});  // a vertex on x = 32
    EXPECT_EQ(voxelizeTriangle({32, 3.5, 3.5}, {32, 4.5, 3.5}, {33, 4, 3.5}, 5),
              (std::vector<std::uint32_t>{vct::packCell(uvec3(31, 3, 3)), vct::packCell(uvec3(31, 4, 3))}));  // an edge
}

// Cells reachable from `start` through 26-neighbours inside `cells`.
std::set<std::uint32_t> reachable(const std::vector<std::uint32_t>& cells, std::uint32_t start) {
    const std::set<std::uint32_t> all(cells.begin(), cells.end());
    std::set<std::uint32_t> seen = {start};
    std::queue<std::uint32_t> todo;
    todo.push(start);
    while (!todo.empty()) {
        const glm::ivec3 c(vct::unpackCell(todo.front()));
        todo.pop();
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 n = c + glm::ivec3(dx, dy, dz);
                    if (glm::any(glm::lessThan(n, glm::ivec3(0)))) continue;
                    const std::uint32_t p = vct::packCell(uvec3(n));
                    if (all.count(p) && seen.insert(p).second) todo.push(p);
                }
    }
    return seen;
}

TEST(ReferenceVoxelizer, ThinDiagonalSliverIsAConnectedChain) {
    const dvec3 a(1.3, 2.7, 0.6), b(60.2, 41.9, 55.3);
    for (const dvec3 c : {a + dvec3(1e-4, -2e-4, 1e-4), b + dvec3(0, 1e-3, 0), a}) {  // slivers and a segment
        const auto cells = voxelizeTriangle(a, b, c, 6);
        const std::uint32_t first = vct::packCell(uvec3(glm::floor(a))), last = vct::packCell(uvec3(glm::floor(b)));
        ASSERT_TRUE(std::binary_search(cells.begin(), cells.end(), first));
        ASSERT_TRUE(std::binary_search(cells.begin(), cells.end(), last));
        const auto connected = reachable(cells, first);
        EXPECT_TRUE(connected.count(last));
        EXPECT_EQ(connected.size(), cells.size()) << "cells not connected to the start";
        EXPECT_GE(cells.size(), 60u);  // at least one per x step
        EXPECT_LE(cells.size(), 60u * 9u);
    }
}

TEST(ReferenceVoxelizer, MatchesBruteForceOverEveryCell) {
    // 200 random triangles on an 8³ grid: 100 with arbitrary coordinates (many leave the grid), 100
    // with coordinates on a half-voxel grid (vertices, edges and faces on cell boundaries, many
    // degenerate). The AABB-restricted loop must give exactly what testing all 512 cells gives; the
    // half-voxel ones are also checked cell by cell against the exact oracle (coordinates × 2).
    std::mt19937_64 rng(777);
    const int levels = 3, n = 8;
    std::size_t totalCells = 0, oracleChecks = 0;
    for (int t = 0; t < 200; ++t) {
        const bool halfGrid = t >= 100;
        dvec3 v[3];
        for (auto& p : v)
            for (int k = 0; k < 3; ++k) p[k] = halfGrid ? 0.5 * uniformInt(rng, -2, 18) : uniform(rng, -2.0, 10.0);
        if (halfGrid && t % 10 == 0) v[2] = v[1];
        std::vector<std::uint32_t> brute;
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const bool hit = triangleOverlapsBox(v[0], v[1], v[2], dvec3(x, y, z) + 0.5, dvec3(0.5));
                    if (hit) brute.push_back(vct::packCell(uvec3(x, y, z)));
                    if (halfGrid) {
                        const glm::i64vec3 lo = std::int64_t(2) * glm::i64vec3(x, y, z);
                        ASSERT_EQ(hit, exactOverlapOracle(glm::i64vec3(2.0 * v[0]), glm::i64vec3(2.0 * v[1]),
                                                          glm::i64vec3(2.0 * v[2]), lo, lo + std::int64_t(2)))
                            << "triangle " << t << " cell " << x << " " << y << " " << z;
                        ++oracleChecks;
                    }
                }
        std::sort(brute.begin(), brute.end());
        ASSERT_EQ(voxelizeTriangle(v[0], v[1], v[2], levels), brute) << "triangle " << t;
        totalCells += brute.size();
    }
    std::printf("[ reference ] voxelizeTriangle vs brute force: 200 triangles, %zu cells; %zu cell tests vs exact oracle\n",
                totalCells, oracleChecks);
    EXPECT_GT(totalCells, 2000u);
}

TEST(ReferenceVoxelizer, CornellBoxScene) {
    const vct::Scene scene = vct::makeCornellBox();
    const vct::VoxelGrid grid = vct::makeVoxelGrid(scene, 7);
    const auto start = std::chrono::steady_clock::now();
    const auto cells = voxelizeScene(scene, grid);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ reference ] voxelizeScene: Cornell box, %zu triangles, 128^3: %zu cells in %.1f ms\n",
                scene.triangleCount(), cells.size(), ms);
    ASSERT_FALSE(cells.empty());
    EXPECT_TRUE(std::is_sorted(cells.begin(), cells.end()));
    EXPECT_EQ(std::adjacent_find(cells.begin(), cells.end()), cells.end());
    // Same as the union of the per-triangle sets, and every vertex's cell is in it.
    std::set<std::uint32_t> united;
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        dvec3 v[3];
        for (int k = 0; k < 3; ++k) v[k] = grid.toVoxel(dvec3(scene.vertices[scene.indices[3 * t + k]].position));
        for (std::uint32_t c : voxelizeTriangle(v[0], v[1], v[2], grid.levels)) united.insert(c);
        for (const dvec3& p : v) {
            ASSERT_TRUE(glm::all(glm::greaterThan(p, dvec3(1.0))) && glm::all(glm::lessThan(p, dvec3(127.0))));
            EXPECT_TRUE(std::binary_search(cells.begin(), cells.end(), vct::packCell(uvec3(glm::floor(p)))));
        }
    }
    EXPECT_EQ(std::vector<std::uint32_t>(united.begin(), united.end()), cells);

    // The octree and bricks of a whole scene also fit in a test's time (informational timing).
    const auto bricksStart = std::chrono::steady_clock::now();
    std::map<std::uint32_t, dvec4> values;
    for (std::uint32_t c : cells) values[c] = dvec4(0.25, 0.25, 0.25, 0.5);
    const CpuBricks bricks = computeCpuBricks(values, grid.levels);
    const double bricksMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - bricksStart).count();
    std::printf("[ reference ] computeCpuBricks: Cornell box, 128^3: %zu leaf nodes, %.1f ms\n",
                bricks.complete[grid.levels - 1].size(), bricksMs);
    EXPECT_EQ(bricks.complete[grid.levels - 1].size(), buildCpuOctree(cells, grid.levels).nodes[grid.levels - 1].size());
}

// ---- Octree -------------------------------------------------------------------------------------

std::vector<std::uint32_t> randomCells(std::mt19937_64& rng, int levels, int count) {
    // Half uniform, half in a clump (so that some nodes have many children, some one).
    std::vector<std::uint32_t> cells;
    const int n = 1 << levels;
    for (int i = 0; i < count; ++i) {
        const int hi = i % 2 ? n - 1 : n / 4 - 1;
        cells.push_back(vct::packCell(uvec3(uniformInt(rng, 0, hi), uniformInt(rng, 0, hi), uniformInt(rng, 0, hi))));
    }
    return cells;
}

TEST(ReferenceOctree, NodesChildMasksAndNeighboursMatchBruteForce) {
    std::mt19937_64 rng(99);
    const int levels = 5;
    const auto cells = randomCells(rng, levels, 400);
    const CpuOctree tree = buildCpuOctree(cells, levels);
    ASSERT_EQ(tree.nodes.size(), std::size_t(levels));
    EXPECT_EQ(tree.nodes[0], std::vector<std::uint32_t>{0});
    std::printf("[ reference ] octree of %zu random cells (%zu distinct), nodes per level:", cells.size(), tree.cells.size());
    for (int l = 0; l < levels; ++l) {
        std::set<std::tuple<unsigned, unsigned, unsigned>> tuples;  // not packed: independent of packCell
        for (std::uint32_t c : cells) {
            const uvec3 u = vct::unpackCell(c);
            const unsigned s = unsigned(levels - l);
            tuples.insert({u.x >> s, u.y >> s, u.z >> s});
        }
        std::printf(" %zu", tree.nodes[l].size());
        ASSERT_EQ(tree.nodes[l].size(), tuples.size()) << "level " << l;
        EXPECT_TRUE(std::is_sorted(tree.nodes[l].begin(), tree.nodes[l].end()));
        for (const auto& [x, y, z] : tuples) EXPECT_TRUE(tree.hasNode(l, uvec3(x, y, z)));

        const unsigned extent = 1u << l;
        for (std::uint32_t packed : tree.nodes[l]) {
            const uvec3 node = vct::unpackCell(packed);
            const std::uint8_t mask = tree.childMask(l, node);
            EXPECT_NE(mask, 0) << "an existing node has at least one child";
            for (unsigned bit = 0; bit < 8; ++bit) {
                const uvec3 child = 2u * node + uvec3(bit & 1u, (bit >> 1) & 1u, (bit >> 2) & 1u);
                const bool exists = l + 1 < levels ? tree.hasNode(l + 1, child)
                                                   : std::count(cells.begin(), cells.end(), vct::packCell(child)) > 0;
                EXPECT_EQ(bool(mask & (1u << bit)), exists) << "level " << l << " bit " << bit;
            }
            for (int axis = 0; axis < 3; ++axis)
                for (int sign : {-1, 1}) {
                    const long other = long(node[axis]) + sign;
                    uvec3 o = node;
                    o[axis] = unsigned(other);
                    const bool exists = other >= 0 && other < long(extent) &&
                                        tuples.count({o.x, o.y, o.z}) > 0;
                    const auto found = tree.neighbour(l, node, axis, sign);
                    ASSERT_EQ(found.has_value(), exists);
                    if (found) {
                        EXPECT_EQ(*found, o);
                    }
                }
        }
        // Every node's parent records it.
        if (l > 0)
            for (std::uint32_t packed : tree.nodes[l]) {
                const uvec3 node = vct::unpackCell(packed);
                const uvec3 bit = node & 1u;
                EXPECT_TRUE(tree.childMask(l - 1, node >> 1u) & (1u << (bit.x | bit.y << 1 | bit.z << 2)));
            }
    }
    std::printf("\n");
    EXPECT_FALSE(tree.hasNode(3, uvec3(8, 0, 0)));  // outside the level's extent
    EXPECT_EQ(tree.childMask(2, uvec3(4, 0, 0)), 0);
}

TEST(ReferenceOctree, EmptyAndInvalidInput) {
    const CpuOctree empty = buildCpuOctree({}, 5);
    for (const auto& level : empty.nodes) EXPECT_TRUE(level.empty());
    EXPECT_THROW(buildCpuOctree({vct::packCell(uvec3(32, 0, 0))}, 5), std::invalid_argument);
    EXPECT_THROW(buildCpuOctree({0}, 11), std::invalid_argument);
}

// ---- Bricks -------------------------------------------------------------------------------------

// Lattice point of sample s of node `packed` at level l, as a key (11 bits per axis: 0..1024).
std::uint64_t latticeKey(int levels, int l, std::uint32_t packed, int s) {
    const int h = 1 << (levels - l - 1);
    const glm::ivec3 p = glm::ivec3(vct::unpackCell(packed)) * (2 * h) + glm::ivec3(s % 3, (s / 3) % 3, s / 9) * h;
    return std::uint64_t(p.x) | std::uint64_t(p.y) << 11 | std::uint64_t(p.z) << 22;
}
glm::ivec3 latticePoint(std::uint64_t key) { return {int(key & 2047), int((key >> 11) & 2047), int(key >> 22)}; }

// The complete lattice function of level l: one value per distinct lattice point. Fails the test
// if nodes sharing a point disagree (not even by one bit).
std::map<std::uint64_t, dvec4> latticeFunction(const CpuBricks& bricks, int l, int* sharedPoints = nullptr) {
    std::map<std::uint64_t, dvec4> values;
    std::map<std::uint64_t, int> holders;
    for (const auto& [packed, brick] : bricks.complete[l])
        for (int s = 0; s < 27; ++s) {
            const std::uint64_t key = latticeKey(bricks.levels, l, packed, s);
            const auto [it, inserted] = values.emplace(key, brick[s]);
            if (!inserted) {
                EXPECT_EQ(std::memcmp(&it->second, &brick[s], sizeof(dvec4)), 0)
                    << "level " << l << " lattice point shared by nodes differs";
            }
            ++holders[key];
        }
    if (sharedPoints) *sharedPoints = int(std::count_if(holders.begin(), holders.end(), [](auto& h) { return h.second > 1; }));
    return values;
}

dvec4 sumOf(const std::map<std::uint64_t, dvec4>& f) {
    dvec4 sum(0.0);
    for (const auto& [key, v] : f) sum += v;
    return sum;
}

TEST(ReferenceBricks, SingleCell) {
    const int levels = 5;
    const dvec4 v(0.5, 0.5, 0.5, 1.0);
    const uvec3 cell(5, 9, 12);  // offset (1, 1, 0) inside leaf node (2, 4, 6)
    const CpuBricks bricks = computeCpuBricks({{vct::packCell(cell), v}}, levels);
    const std::uint32_t leaf = vct::packCell(cell >> 1u);
    ASSERT_EQ(bricks.complete[levels - 1].size(), 1u);
    const Brick& brick = bricks.complete[levels - 1].at(leaf);
    for (int s = 0; s < 27; ++s) {
        const glm::ivec3 i(s % 3, (s / 3) % 3, s / 9);
        const bool corner = i.x >= 1 && i.y >= 1 && i.z <= 1;  // the cell spans samples 1..2, 1..2, 0..1
        EXPECT_EQ(brick[s], corner ? v / 8.0 : dvec4(0.0)) << "sample " << s;
    }
    EXPECT_EQ(bricks.raw[levels - 1].at(leaf), v / 8.0);
    EXPECT_EQ(bricks.raw[0].at(0), v / 32768.0);
    for (int l = 0; l < levels; ++l) EXPECT_EQ(bricks.complete[l].size(), 1u);
}

TEST(ReferenceBricks, FilledRegionIsOneInside) {
    // Cells 8..15 on every axis, V = 1. The level-l value at Q depends on leaf samples within
    // h_l − 1 of Q and the leaf value is 1 at 9..15, so S = 1 exactly where Q is ≥ h_l (half a node
    // edge) inside the region — a superset of the "one node edge" points — and < 1 on its border.
    const int levels = 5;
    std::map<std::uint32_t, dvec4> values;
    for (unsigned z = 8; z < 16; ++z)
        for (unsigned y = 8; y < 16; ++y)
            for (unsigned x = 8; x < 16; ++x) values[vct::packCell(uvec3(x, y, z))] = dvec4(1.0);
    const CpuBricks bricks = computeCpuBricks(values, levels);
    std::printf("[ reference ] filled 8^3 region, samples checked == 1 (>= h_l inside / >= e_l inside) and < 1 on the border, per level:");
    for (int l = 0; l < levels; ++l) {
        const int h = 1 << (levels - l - 1);
        int inside = 0, nodeEdgeInside = 0, border = 0;
        for (const auto& [key, s] : latticeFunction(bricks, l)) {
            const glm::ivec3 q = latticePoint(key);
            if (glm::all(glm::greaterThanEqual(q, glm::ivec3(8 + h))) && glm::all(glm::lessThanEqual(q, glm::ivec3(16 - h)))) {
                for (int c = 0; c < 4; ++c) EXPECT_NEAR(s[c], 1.0, 1e-12) << "level " << l;
                ++inside;
                nodeEdgeInside += glm::all(glm::greaterThanEqual(q, glm::ivec3(8 + 2 * h))) &&
                                  glm::all(glm::lessThanEqual(q, glm::ivec3(16 - 2 * h)));
            } else if (glm::all(glm::greaterThanEqual(q, glm::ivec3(8))) && glm::all(glm::lessThanEqual(q, glm::ivec3(16)))) {
                EXPECT_LT(s.w, 1.0 - 1e-3) << "level " << l;  // on the region's border
                ++border;
            }
        }
        std::printf(" L%d %d/%d/%d", l, inside, nodeEdgeInside, border);
        if (l >= 2) {
            EXPECT_GT(inside, 0);
        }
    }
    std::printf("\n");
    // Raw: leaf and level-2 nodes inside the region are full, the level-1 node holding it is 1/8 full.
    EXPECT_EQ(bricks.raw[4].at(vct::packCell(uvec3(5, 6, 7))), dvec4(1.0));
    EXPECT_EQ(bricks.raw[2].at(vct::packCell(uvec3(1))), dvec4(1.0));
    EXPECT_EQ(bricks.raw[1].at(vct::packCell(uvec3(0))), dvec4(0.125));
    EXPECT_EQ(bricks.raw[0].at(0), dvec4(1.0 / 64.0));
}

TEST(ReferenceBricks, LatticeSumShrinksByAnEighthPerLevel) {
    // Each ¼ ½ ¼ tent step hands every child sample on to parent samples with total weight 1/2 per
    // axis (on-lattice: ½ to one point; off-lattice: ¼ + ¼ to two), so Σ_q S_l(q) = Σ S_{l+1} / 8,
    // i.e. Σ_q S_l(q)·h_l³ = Σ_c V(c) is the same at every level (the integral is preserved). The
    // leaf level gives each cell's V/8 to its 8 corners: Σ_q S_{L−1}(q) = Σ_c V(c).
    std::mt19937_64 rng(5);
    const int levels = 5;
    std::map<std::uint32_t, dvec4> single = {{vct::packCell(uvec3(5, 9, 12)), dvec4(0.5, 0.5, 0.5, 1.0)}};
    std::map<std::uint32_t, dvec4> random;
    for (std::uint32_t c : randomCells(rng, levels, 300))
        random[c] = dvec4(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1));
    for (const auto* values : {&single, &random}) {
        dvec4 total(0.0);
        for (const auto& [c, v] : *values) total += v;
        const CpuBricks bricks = computeCpuBricks(*values, levels);
        std::printf("[ reference ] %s: sum of V = %.6f; level: sum of S, sum of S*h^3:", values == &single ? "one cell" : "300 random cells", total.w);
        for (int l = levels - 1; l >= 0; --l) {
            const double h = double(1 << (levels - l - 1));
            const dvec4 sum = sumOf(latticeFunction(bricks, l));
            std::printf("  L%d %.9g, %.9g", l, sum.w, sum.w * h * h * h);
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(sum[c] * h * h * h, total[c], 1e-12 * total[c]) << "level " << l;
        }
        std::printf("\n");
    }
}

TEST(ReferenceBricks, SharedSamplesAreBitIdenticalInEveryNode) {
    // Random non-dyadic values so that the summation order matters; every node computes its own
    // complete sums, and all nodes sharing a lattice point must hold the same bits.
    std::mt19937_64 rng(2024);
    const int levels = 5;
    std::map<std::uint32_t, dvec4> values;
    for (std::uint32_t c : randomCells(rng, levels, 1500))
        values[c] = dvec4(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)) / 3.0;
    const CpuBricks bricks = computeCpuBricks(values, levels);
    // How often a different summation order (reversed canonical order) changes the bits, to show
    // the check above is not vacuous.
    int orderSensitive = 0, sharedTotal = 0;
    for (int l = 0; l < levels; ++l) {
        int shared = 0;
        latticeFunction(bricks, l, &shared);
        sharedTotal += shared;
        for (const auto& [packed, brick] : bricks.complete[l])
            for (int s = 0; s < 27; ++s) {
                std::vector<std::pair<std::uint32_t, int>> holders;  // (node, index) in canonical order
                const glm::ivec3 i(s % 3, (s / 3) % 3, s / 9);
                for (int o = 0; o < 27; ++o) {
                    const glm::ivec3 off(o % 3 - 1, (o / 3) % 3 - 1, o / 9 - 1);
                    const glm::ivec3 local = i - 2 * off, m = glm::ivec3(vct::unpackCell(packed)) + off;
                    if (glm::any(glm::lessThan(local, glm::ivec3(0))) || glm::any(glm::greaterThan(local, glm::ivec3(2))) ||
                        glm::any(glm::lessThan(m, glm::ivec3(0))))
                        continue;
                    const auto it = bricks.partial[l].find(vct::packCell(uvec3(m)));
                    if (it != bricks.partial[l].end()) holders.push_back({it->first, local.x + 3 * local.y + 9 * local.z});
                }
                dvec4 forward(0.0), backward(0.0);
                for (auto it = holders.begin(); it != holders.end(); ++it) forward += bricks.partial[l].at(it->first)[it->second];
                for (auto it = holders.rbegin(); it != holders.rend(); ++it) backward += bricks.partial[l].at(it->first)[it->second];
                EXPECT_EQ(std::memcmp(&forward, &brick[s], sizeof(dvec4)), 0) << "not the canonical-order sum";
                orderSensitive += std::memcmp(&forward, &backward, sizeof(dvec4)) != 0;
            }
    }
    std::printf("[ reference ] %d lattice points shared by several nodes; %d stored samples would change bits in reversed order\n",
                sharedTotal, orderSensitive);
    EXPECT_GT(sharedTotal, 100);
}

TEST(ReferenceBricks, CompleteSamplesAreTheBoxThenTentFilteredLattice) {
    // Independent of the partial decomposition: leaf S(q) = 1/8 Σ V over the (up to 8) cells
    // around q; coarser S_l(Q) = Σ_d w(d) S_{l+1}(Q + d·h_l/2), with S_{l+1} = 0 where no node
    // holds the point. Raw = brute-force mean over the node's cells.
    std::mt19937_64 rng(31);
    const int levels = 5;
    std::map<std::uint32_t, dvec4> values;
    for (std::uint32_t c : randomCells(rng, levels, 800))
        values[c] = dvec4(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1));
    const CpuBricks bricks = computeCpuBricks(values, levels);
    const auto V = [&](glm::ivec3 c) {
        if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(32)))) return dvec4(0.0);
        const auto it = values.find(vct::packCell(uvec3(c)));
        return it == values.end() ? dvec4(0.0) : it->second;
    };
    std::map<std::uint64_t, dvec4> finer;
    for (int l = levels - 1; l >= 0; --l) {
        const int h = 1 << (levels - l - 1);
        const auto f = latticeFunction(bricks, l);
        for (const auto& [key, s] : f) {
            const glm::ivec3 q = latticePoint(key);
            dvec4 expected(0.0);
            for (int d = 0; d < 27; ++d) {
                const glm::ivec3 o(d % 3 - 1, (d / 3) % 3 - 1, d / 9 - 1);
                if (l == levels - 1) {
                    if (glm::all(glm::lessThanEqual(o, glm::ivec3(0)))) expected += V(q + o) / 8.0;  // cells q−1..q
                } else {
                    const glm::ivec3 p = q + o * (h / 2);
                    if (glm::any(glm::lessThan(p, glm::ivec3(0)))) continue;
                    const auto it = finer.find(std::uint64_t(p.x) | std::uint64_t(p.y) << 11 | std::uint64_t(p.z) << 22);
                    const double w = (o.x ? 0.25 : 0.5) * (o.y ? 0.25 : 0.5) * (o.z ? 0.25 : 0.5);
                    if (it != finer.end()) expected += w * it->second;
                }
            }
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(s[c], expected[c], 1e-14) << "level " << l;
        }
        // Nodes that do not exist would hold only zeros: the lattice function is complete.
        finer = f;

        const int e = 2 * h;
        for (const auto& [packed, raw] : bricks.raw[l]) {
            const glm::ivec3 n = glm::ivec3(vct::unpackCell(packed)) * e;
            dvec4 sum(0.0);
            for (int z = 0; z < e; ++z)
                for (int y = 0; y < e; ++y)
                    for (int x = 0; x < e; ++x) sum += V(n + glm::ivec3(x, y, z));
            for (int c = 0; c < 4; ++c) ASSERT_NEAR(raw[c], sum[c] / double(e * e * e), 1e-14);
        }
        EXPECT_EQ(bricks.raw[l].size(), bricks.complete[l].size());
        EXPECT_EQ(bricks.partial[l].size(), bricks.complete[l].size());
    }
}

TEST(ReferenceBricks, ZeroValuedCellsStillCreateNodes) {
    const CpuBricks bricks = computeCpuBricks({{vct::packCell(uvec3(20, 3, 7)), dvec4(0.0)}}, 5);
    for (int l = 0; l < 5; ++l) {
        ASSERT_EQ(bricks.complete[l].size(), 1u);
        for (const dvec4& s : bricks.complete[l].begin()->second) EXPECT_EQ(s, dvec4(0.0));
    }
    EXPECT_TRUE(bricks.complete[4].count(vct::packCell(uvec3(10, 1, 3))));
}

TEST(ReferenceBricks, Deterministic) {
    std::mt19937_64 rng(8);
    std::map<std::uint32_t, dvec4> values;
    for (std::uint32_t c : randomCells(rng, 6, 2000))
        values[c] = dvec4(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)) / 7.0;
    const CpuBricks a = computeCpuBricks(values, 6), b = computeCpuBricks(values, 6);
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const auto& p, const auto& q) {
                   return p.first == q.first && std::memcmp(&p.second, &q.second, sizeof p.second) == 0;
               });
    };
    for (int l = 0; l < 6; ++l) {
        EXPECT_TRUE(same(a.complete[l], b.complete[l])) << l;
        EXPECT_TRUE(same(a.partial[l], b.partial[l])) << l;
        EXPECT_TRUE(same(a.raw[l], b.raw[l])) << l;
    }
}

}  // namespace
