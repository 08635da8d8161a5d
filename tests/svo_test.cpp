// The GPU sparse voxel octree against the CPU reference (tests/reference/): coverage of the
// voxelization, structure of the octree, leaf values, bricks and MIP, determinism.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "reference/cpu_bricks.hpp"
#include "reference/cpu_octree.hpp"
#include "reference/cpu_voxelizer.hpp"
#include "scene/scene_loader.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;

namespace {

constexpr std::uint32_t kNone = 0xFFFFFFFFu;

// GPU cells ⊇ CPU cells; returns the over-coverage (extra / CPU).
double checkCoverage(const GpuOctreeData& gpu, const std::vector<std::uint32_t>& cpuCells, const std::string& what) {
    const std::set<std::uint32_t> gpuCells = gpu.cellSet();
    std::size_t holes = 0;
    for (std::uint32_t cell : cpuCells)
        if (!gpuCells.count(cell)) {
            if (holes < 5) {
                const glm::uvec3 c = unpackCell(cell);
                ADD_FAILURE() << what << ": hole at cell " << c.x << "," << c.y << "," << c.z;
            }
            ++holes;
        }
    EXPECT_EQ(holes, 0u) << what;
    return cpuCells.empty() ? 0.0 : double(gpuCells.size() - std::min(gpuCells.size(), cpuCells.size())) / cpuCells.size();
}

// Every node, child pointer, parent and neighbour link against a CPU octree of the same cells.
void checkStructure(const GpuOctreeData& gpu) {
    const std::set<std::uint32_t> cellSet = gpu.cellSet();
    const reference::CpuOctree cpu = reference::buildCpuOctree({cellSet.begin(), cellSet.end()}, gpu.levels);
    for (int level = 0; level < gpu.levels; ++level) {
        ASSERT_EQ(gpu.levelCount[level], cpu.nodes[level].size()) << "nodes at level " << level;
        std::map<std::uint32_t, std::uint32_t> nodeOf;  // coordinate → GPU node at this level
        for (std::uint32_t i = 0; i < gpu.levelCount[level]; ++i) nodeOf[gpu.coord[gpu.levelStart[level] + i]] = gpu.levelStart[level] + i;
        ASSERT_EQ(nodeOf.size(), cpu.nodes[level].size()) << "duplicate coordinates at level " << level;
        for (std::uint32_t i = 0; i < gpu.levelCount[level]; ++i) {
            const std::uint32_t node = gpu.levelStart[level] + i;
            const glm::uvec3 c = unpackCell(gpu.coord[node]);
            ASSERT_TRUE(cpu.hasNode(level, c)) << "level " << level;
            ASSERT_EQ(gpu.mask[node], cpu.childMask(level, c)) << "child mask, level " << level;
            // Children: contiguous from child[node], in slot order, pointing back to node.
            std::uint32_t child = gpu.child[node];
            for (std::uint32_t slot = 0; slot < 8; ++slot) {
                if (!(gpu.mask[node] & (1u << slot))) continue;
                const glm::uvec3 expected = c * 2u + glm::uvec3(slot & 1, (slot >> 1) & 1, (slot >> 2) & 1);
                ASSERT_EQ(gpu.coord[child], packCell(expected)) << "child coordinate, level " << level;
                ASSERT_EQ(gpu.parent[child], node);
                ASSERT_GE(child, gpu.levelStart[level + 1]);
                ASSERT_LT(child, gpu.levelStart[level + 1] + gpu.levelCount[level + 1]);
                ++child;
            }
            for (int direction = 0; direction < 6; ++direction) {
                const auto expected = cpu.neighbour(level, c, direction / 2, direction % 2 ? 1 : -1);
                const std::uint32_t link = gpu.neighbours[std::size_t(node) * 6 + direction];
                if (!expected) {
                    ASSERT_EQ(link, kNone) << "level " << level << " direction " << direction;
                } else {
                    ASSERT_NE(link, kNone) << "level " << level << " direction " << direction;
                    ASSERT_EQ(gpu.coord[link], packCell(*expected));
                    ASSERT_EQ(link, nodeOf.at(packCell(*expected)));
                }
            }
        }
    }
}

// Leaf albedo = CPU mean of the fragments' colours (texture colour × material colour, as 8-bit
// values) within 1/255, area = CPU sum.
void checkLeaves(const GpuOctreeData& gpu, const Scene& scene) {
    std::map<std::uint32_t, glm::dvec4> sums;  // cell → (Σ rgb, count)
    std::map<std::uint32_t, double> areas;
    for (std::size_t f = 0; f < gpu.fragmentCell.size(); ++f) {
        const std::uint32_t a = gpu.fragmentAlbedo[f];
        const glm::dvec3 factor(scene.materials.at(gpu.fragmentMaterial[f]).baseColor);
        const glm::dvec3 texture(a & 255, (a >> 8) & 255, (a >> 16) & 255);
        const glm::dvec3 colour = glm::round(glm::clamp(texture / 255.0 * factor, 0.0, 1.0) * 255.0);
        sums[gpu.fragmentCell[f]] += glm::dvec4(colour, 1.0);
        areas[gpu.fragmentCell[f]] += gpu.fragmentArea[f];
    }
    for (std::uint32_t i = 0; i < gpu.levelCount[gpu.levels]; ++i) {
        const std::uint32_t node = gpu.levelStart[gpu.levels] + i;
        const glm::dvec4 s = sums.at(gpu.coord[node]);
        ASSERT_EQ(gpu.cellFragments[i], std::uint32_t(s.w));
        const std::uint32_t a = gpu.cellAlbedo[i];
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(double((a >> (8 * c)) & 255) / 255.0, s[c] / s.w / 255.0, 1.0 / 255.0) << "channel " << c;
        const double area = areas.at(gpu.coord[node]);
        ASSERT_NEAR(gpu.cellArea[i], area, 1e-5 + 1e-3 * area);  // fragments hold the area as half floats
        // Half a step of the 8-bit opacity, plus half a step of a half float below 1: NVIDIA's
        // packUnorm4x8 rounds its input to half precision first, so an area within that of a
        // rounding boundary may round either way.
        ASSERT_NEAR(double((a >> 24) & 255) / 255.0, std::min(1.0, area), 0.5 / 255.0 + 0.5 / 2048.0) << "opacity";
    }
}

// Brick pool and raw values against the CPU filters applied to the GPU's own cell values.
void checkBricks(const GpuOctreeData& gpu) {
    std::map<std::uint32_t, glm::dvec4> cellValues;
    for (std::uint32_t i = 0; i < gpu.levelCount[gpu.levels]; ++i) {
        const std::uint32_t a = gpu.cellAlbedo[i];
        const double alpha = double((a >> 24) & 255) / 255.0;
        const double tau = -std::log(1.0 - std::min(alpha, 0.999));  // optical depth (brick_layout.hpp)
        const glm::dvec3 rho(double(a & 255) / 255.0, double((a >> 8) & 255) / 255.0, double((a >> 16) & 255) / 255.0);
        cellValues[gpu.coord[gpu.levelStart[gpu.levels] + i]] = glm::dvec4(rho * tau, tau);
    }
    const reference::CpuBricks cpu = reference::computeCpuBricks(cellValues, gpu.levels);
    double worst = 0.0;
    for (int level = 0; level < gpu.levels; ++level) {
        for (std::uint32_t i = 0; i < gpu.levelCount[level]; ++i) {
            const std::uint32_t node = gpu.levelStart[level] + i;
            const auto& brick = cpu.complete[level].at(gpu.coord[node]);
            for (int s = 0; s < 27; ++s) {
                const glm::vec4 g = gpu.brickSample(node, s);
                for (int c = 0; c < 4; ++c) {
                    const double expected = brick[s][c];
                    const double error = std::abs(double(g[c]) - expected);
                    worst = std::max(worst, error);
                    // RGBA16F storage: 11 significant bits.
                    ASSERT_LE(error, 1e-6 + expected * 1.0 / 1024.0)
                        << "level " << level << " sample " << s << " channel " << c;
                }
            }
            const glm::dvec4 raw = cpu.raw[level].at(gpu.coord[node]);
            for (int c = 0; c < 4; ++c)  // float log on the GPU: relative 1e-5
                ASSERT_NEAR(gpu.rawValue[node][c], raw[c], 1e-5 * std::max(1.0, std::abs(raw[c]))) << "raw, level " << level;
        }
    }
    std::printf("[ bricks   ] %d levels, largest |GPU − CPU| = %.3g\n", gpu.levels, worst);
}

Scene unitBoxScene(const std::vector<glm::dvec3>& triangles) {
    return makeTriangleScene(triangles, Bounds{glm::dvec3(0.0), glm::dvec3(1.0)});
}

}  // namespace

TEST(Svo, CornellVoxelizationHasNoHolesAtSeveralResolutions) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    for (int levels : {5, 6, 7}) {
        const GpuOctreeData gpu = harness.build(levels);
        const auto cpuCells = reference::voxelizeScene(scene, makeVoxelGrid(scene, levels));
        const double over = checkCoverage(gpu, cpuCells, "cornell " + std::to_string(levels));
        std::printf("[ coverage ] cornell %d³: CPU %zu voxels, GPU %zu, over-coverage %.2f %%\n", 1 << levels,
                    cpuCells.size(), gpu.cellSet().size(), 100.0 * over);
        EXPECT_LT(over, 0.10) << "levels " << levels;
    }
}

TEST(Svo, AwkwardTrianglesHaveNoHoles) {
    // In the unit cube; the grid maps it to [1.5, N − 1.5]. Positions given in voxel units of the
    // 32³ grid are placed exactly on voxel boundaries.
    const Scene probe = unitBoxScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const VoxelGrid grid32 = makeVoxelGrid(probe, 5);
    auto at = [&](double x, double y, double z) { return grid32.toLocal({x, y, z}) + probe.origin; };
    std::vector<glm::dvec3> t = {
        // thin sliver along a diagonal
        {0.05, 0.1, 0.2}, {0.95, 0.9, 0.8}, {0.95, 0.9005, 0.8},
        // steep (almost edge-on to every axis)
        {0.2, 0.2, 0.2}, {0.25, 0.8, 0.7}, {0.21, 0.22, 0.9},
        // axis-aligned, exactly on voxel boundaries
        at(4, 4, 10), at(12, 4, 10), at(4, 12, 10),
        // tiny, inside one voxel
        at(20.3, 20.3, 20.3), at(20.35, 20.3, 20.31), at(20.3, 20.36, 20.32),
        // tiny, straddling a voxel corner
        at(7.999, 7.999, 7.999), at(8.001, 7.999, 8.0), at(7.999, 8.001, 8.001),
        // huge: across the whole volume
        {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.5},
        // on the volume's boundary layer (bounds face)
        {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 0.0, 1.0},
        // edge exactly along a voxel edge line
        at(3, 3, 3), at(3, 3, 20), at(9, 14, 11),
    };
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 60; ++i) t.push_back({unit(random), unit(random), unit(random)});
    const Scene scene = unitBoxScene(t);
    SvoHarness harness(scene);
    for (int levels : {5, 6, 7}) {
        const GpuOctreeData gpu = harness.build(levels);
        const VoxelGrid grid = makeVoxelGrid(scene, levels);
        for (std::size_t i = 0; i < t.size(); i += 3) {
            auto voxel = [&](std::size_t k) { return grid.toVoxel(glm::dvec3(scene.vertices[k].position)); };
            const auto cells = reference::voxelizeTriangle(voxel(i), voxel(i + 1), voxel(i + 2), levels);
            checkCoverage(gpu, cells, "triangle " + std::to_string(i / 3) + " at levels " + std::to_string(levels));
        }
        const auto all = reference::voxelizeScene(scene, grid);
        const double over = checkCoverage(gpu, all, "all");
        std::printf("[ coverage ] awkward triangles %d³: CPU %zu voxels, over-coverage %.2f %%\n", 1 << levels, all.size(),
                    100.0 * over);
    }
}

TEST(Svo, OctreeStructureMatchesCpu) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    for (int levels : {5, 7}) {
        const GpuOctreeData gpu = harness.build(levels);
        checkStructure(gpu);
        // Exact sizing: levels 0..L−1 plus the occupied cells, nothing else.
        std::uint32_t total = 0;
        for (int l = 0; l <= levels; ++l) total += gpu.levelCount[l];
        EXPECT_EQ(gpu.coord.size(), total);
    }
}

TEST(Svo, LeafValuesAreExactMeansOfTheirFragments) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    checkLeaves(harness.build(6), scene);
}

TEST(Svo, TenThousandFragmentsInOneVoxelAverageExactly) {
    // 10 000 tiny triangles inside one voxel: 7 000 red, 2 000 green, 1 000 blue. The mean is
    // (0.7, 0.2, 0.1); an 8-bit compare-and-swap running average cannot get this.
    const Scene probe = unitBoxScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const VoxelGrid grid = makeVoxelGrid(probe, 5);
    std::vector<glm::dvec3> t;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> jitter(0.3, 0.7);
    for (int i = 0; i < 10000; ++i) {
        const glm::dvec3 base(16 + jitter(random), 16 + jitter(random), 16 + jitter(random));
        for (const glm::dvec3 d : {glm::dvec3(0), glm::dvec3(0.05, 0, 0), glm::dvec3(0, 0.05, 0.01)})
            t.push_back(grid.toLocal(base + d) + probe.origin);
    }
    const Scene scene = makeTriangleScene(t, Bounds{glm::dvec3(0.0), glm::dvec3(1.0)},
                                          {{7000, {1, 0, 0}}, {2000, {0, 1, 0}}, {1000, {0, 0, 1}}});
    SvoHarness harness(scene);
    const GpuOctreeData gpu = harness.build(5);
    ASSERT_EQ(gpu.levelCount[5], 1u) << "all triangles lie in one voxel";
    EXPECT_EQ(gpu.cellFragments[0], 10000u);
    const std::uint32_t a = gpu.cellAlbedo[0];
    EXPECT_NEAR((a & 255) / 255.0, 0.7, 0.5 / 255.0 + 1e-9);
    EXPECT_NEAR(((a >> 8) & 255) / 255.0, 0.2, 0.5 / 255.0 + 1e-9);
    EXPECT_NEAR(((a >> 16) & 255) / 255.0, 0.1, 0.5 / 255.0 + 1e-9);
    checkLeaves(gpu, scene);
}

TEST(Svo, BricksAndMipMatchCpuFilters) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    checkBricks(harness.build(5));
    checkBricks(harness.build(6));
}

TEST(Svo, ThreeBuildsAreBitIdentical) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    const GpuOctreeData first = harness.build(6);
    for (int run = 0; run < 2; ++run) {
        const GpuOctreeData again = harness.build(6);
        EXPECT_EQ(again.levelCount, first.levelCount);
        EXPECT_EQ(again.child, first.child);
        EXPECT_EQ(again.mask, first.mask);
        EXPECT_EQ(again.coord, first.coord);
        EXPECT_EQ(again.parent, first.parent);
        EXPECT_EQ(again.neighbours, first.neighbours);
        EXPECT_EQ(again.cellAlbedo, first.cellAlbedo);
        EXPECT_EQ(again.cellArea, first.cellArea);
        EXPECT_EQ(again.brickPool, first.brickPool);
        EXPECT_TRUE(std::equal(again.rawValue.begin(), again.rawValue.end(), first.rawValue.begin(),
                               [](const glm::vec4& a, const glm::vec4& b) { return a == b; }));
    }
}
