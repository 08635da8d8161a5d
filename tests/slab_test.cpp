// Slab bricks (engine/voxel/brick_layout.hpp, "Slabs"): the GPU opacity slabs against the CPU
// reference (tests/reference/cpu_slabs.*), and the properties the slabs exist for: a one-voxel
// wall stays opaque along its normal at every level (and its cells block every ray across it,
// also where it lies on a cell face or crosses two cells), a pillar covering a quarter of a slab
// passes three quarters of the light, and the dark side of a lit wall looks dark.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include <glm/gtc/constants.hpp>

#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "reference/cpu_slabs.hpp"
#include "scene/scene_loader.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;

namespace {

const char* const kDirectionName[6] = {"+x", "+y", "+z", "-x", "-y", "-z"};  // the CPU reference's order

// Sample spacing of level l in voxels: h_l = 2^(L − l − 1).
int spacing(int levels, int level) { return 1 << (levels - level - 1); }

// Voxel position of sample s of `node` at `level`: node.min + (i, j, k)·h.
glm::ivec3 samplePosition(glm::uvec3 node, int s, int h) {
    return 2 * h * glm::ivec3(node) + h * glm::ivec3(s % 3, (s / 3) % 3, s / 9);
}

// The GPU's six densities of sample s of `node` in the CPU reference's order (τ+x, τ+y, τ+z, τ−x, τ−y, τ−z).
std::array<double, 6> gpuDensities(const GpuOctreeData& gpu, std::uint32_t node, int s) {
    const glm::vec4 plus = gpu.poolSample(gpu.opacityPlus, node, s), minus = gpu.poolSample(gpu.opacityMinus, node, s);
    return {plus.x, plus.y, plus.z, minus.x, minus.y, minus.z};
}

// packed cell → (α_x, α_y, α_z): byte a of the cell's RGBA8 cellOpacity / 255.
std::map<std::uint32_t, glm::dvec3> cellOpacityOf(const GpuOctreeData& gpu) {
    std::map<std::uint32_t, glm::dvec3> cells;
    for (std::uint32_t i = 0; i < gpu.levelCount[gpu.levels]; ++i) {
        const std::uint32_t a = gpu.cellOpacity.at(i);
        cells[gpu.coord[gpu.levelStart[gpu.levels] + i]] =
            glm::dvec3(a & 255, (a >> 8) & 255, (a >> 16) & 255) / 255.0;
    }
    return cells;
}

// Every sample of every node, six directions and the two mean channels, against the CPU
// reference computed from the GPU's own cell opacities. RGBA16F storage: 11 significant bits,
// and each level starts from the half-float values of the level below.
void checkSlabOpacity(const GpuOctreeData& gpu, const std::string& what) {
    const reference::CpuSlabOpacity cpu = reference::computeCpuSlabOpacity(cellOpacityOf(gpu), gpu.levels);
    double worst = 0.0, worstCpu = 0.0, largest = 0.0;
    std::size_t samples = 0, opaque = 0, failures = 0;
    auto compare = [&](double g, double expected, int level, glm::uvec3 n, int s, const char* direction) {
        const double error = std::abs(g - expected);
        if (error > worst) worst = error, worstCpu = expected;
        if (error > 2e-3 * std::max(1.0, std::abs(expected)) && failures++ < 10)
            ADD_FAILURE() << what << ": level " << level << " node " << n.x << "," << n.y << "," << n.z << " sample " << s
                          << " (" << s % 3 << "," << (s / 3) % 3 << "," << s / 9 << ") direction " << direction << ": GPU " << g
                          << ", CPU " << expected;
    };
    for (int level = 0; level < gpu.levels; ++level) {
        ASSERT_EQ(cpu.nodes[level].size(), gpu.levelCount[level]) << what << ": nodes at level " << level;
        for (std::uint32_t i = 0; i < gpu.levelCount[level]; ++i) {
            const std::uint32_t node = gpu.levelStart[level] + i;
            const auto it = cpu.nodes[level].find(gpu.coord[node]);
            ASSERT_NE(it, cpu.nodes[level].end()) << what << ": GPU node the CPU octree lacks, level " << level;
            const glm::uvec3 n = unpackCell(gpu.coord[node]);
            for (int s = 0; s < 27; ++s) {
                const std::array<double, 6> g = gpuDensities(gpu, node, s);
                const reference::SlabDensities& c = it->second[s];
                for (int d = 0; d < 6; ++d) {
                    compare(g[d], c[d], level, n, s, kDirectionName[d]);
                    largest = std::max(largest, c[d]);
                    opaque += c[d] > 1.0;
                }
                // The fourth channel of each pool: the mean of its three.
                compare(gpu.poolSample(gpu.opacityPlus, node, s).w, (c[0] + c[1] + c[2]) / 3.0, level, n, s, "+mean");
                compare(gpu.poolSample(gpu.opacityMinus, node, s).w, (c[3] + c[4] + c[5]) / 3.0, level, n, s, "-mean");
                ++samples;
            }
        }
    }
    EXPECT_EQ(failures, 0u) << what << ": samples off the reference (first 10 listed)";
    std::printf("[ slabs    ] %s, %d levels: %zu samples × 6 directions, %zu values with τ > 1 (largest %.3f), "
                "largest |GPU − CPU| = %.3g (CPU %.4g there)\n",
                what.c_str(), gpu.levels, samples, opaque, largest, worst, worstCpu);
}

// Scenes in voxel units: a unit-box scene at `levels` maps [0,1]³ to voxels [1.5, N − 1.5];
// positions given in voxels of that grid land exactly where written (up to float rounding).
struct VoxelScene {
    int levels;
    Scene probe = makeTriangleScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Bounds{glm::dvec3(0.0), glm::dvec3(1.0)});
    VoxelGrid grid = makeVoxelGrid(probe, levels);
    std::vector<glm::dvec3> triangles;

    glm::dvec3 at(glm::dvec3 voxel) const { return grid.toLocal(voxel) + probe.origin; }
    void quad(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        for (const glm::dvec3& p : {a, b, c, a, c, d}) triangles.push_back(at(p));
    }
    // Axis-aligned closed box (6 quads).
    void box(glm::dvec3 lo, glm::dvec3 hi) {
        const glm::dvec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                                 {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
        const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
        for (const auto& f : faces) quad(c[f[0]], c[f[1]], c[f[2]], c[f[3]]);
    }
    // The scene, with each triangle's vertices given its geometric normal: makeTriangleScene gives
    // every vertex (0, 0, 1), and the voxelizer projects a fragment's area along the axes with the
    // (interpolated) vertex normal, so that placeholder would make every wall a floor (α_z = 1).
    Scene scene() const {
        Scene s = makeTriangleScene(triangles, Bounds{glm::dvec3(0.0), glm::dvec3(1.0)});
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            const glm::vec3 normal(glm::normalize(glm::cross(triangles[t + 1] - triangles[t], triangles[t + 2] - triangles[t])));
            for (std::size_t k = t; k < t + 3; ++k) s.vertices[k].normal = normal;
        }
        return s;
    }
};

// The wall of the wall tests: the plane x = 37.5 voxels at 64³ (through the middle of the cells
// x = 37, so it is one voxel thick), across y, z ∈ [0.25, 63.75] (nearly the whole volume, so
// that even the root's centre sample, whose slab reaches 32 voxels either side across, is
// covered). The wall is the only geometry; the volume is fixed by the scene's bounds, so the wall
// lies on no node boundary: cell 37 = 100101₂ is inside a node of every level, and the last
// sample before it is 0.5, 1.5, 1.5, 5.5, 5.5, 5.5 voxels from its plane (h = 1, 2, .., 32).
constexpr int kWallLevels = 6;
constexpr int kWallCell = 37;
VoxelScene wallScene() {
    VoxelScene v{kWallLevels};
    const double x = kWallCell + 0.5, lo = 0.25, hi = 63.75;
    v.quad({x, lo, lo}, {x, hi, lo}, {x, hi, hi}, {x, lo, hi});
    return v;
}

// The lattice x of the samples whose +x slab [x, x + h) holds the wall cell, and whose −x slab
// [x − h, x) does (the next one).
int plusSampleX(int h) { return kWallCell / h * h; }
int minusSampleX(int h) { return kWallCell / h * h + h; }

// Samples whose slab's cross-section (y, z within ±h of the sample) lies on the wall's fully
// covered cells 1..62 (cells 0 and 63 are three quarters covered). At the root no sample's does:
// there the volume's centre, whose cross-section reaches the outermost cells with 0.05 % of its
// weight on each side.
bool onTheWall(glm::ivec3 p, int h) {
    auto inside = [&](int c) { return h == (1 << kWallLevels) / 2 ? c == h : c - h >= 1 && c + h <= (1 << kWallLevels) - 1; };
    return inside(p.y) && inside(p.z);
}


}  // namespace

TEST(Slabs, OpacityMatchesCpuReference) {
    const Scene scene = makeCornellBox();
    SvoHarness harness(scene);
    for (int levels : {5, 6}) checkSlabOpacity(harness.build(levels), "cornell");
}

TEST(Slabs, OneVoxelWallStaysOpaqueAlongItsNormalAtEveryLevel) {
    // Along x every slab that holds the wall must stay opaque: T = exp(−τ·h) through one sample
    // spacing ≤ 0.01 at every level (the wall's cells have α_x = 1, so T ≈ 0.001). Across (±y,
    // ±z) the same samples must stay clear, T ≥ 0.9: the wall is edge-on to those slabs (α_y =
    // α_z = 0). A direction-blind opacity would fail this at the fine levels (at the leaves, a
    // ±y slab next to the wall holds the wall in half its cross-section: T ≈ 0.5).
    const VoxelScene v = wallScene();
    const Scene scene = v.scene();
    SvoHarness harness(scene);
    const GpuOctreeData gpu = harness.build(kWallLevels);
    for (int level = 0; level < kWallLevels; ++level) {
        const int h = spacing(kWallLevels, level);
        double worstAlong = 0.0, worstAcross = 1.0;  // largest T along x, smallest T across
        std::size_t checked = 0;
        for (std::uint32_t i = 0; i < gpu.levelCount[level]; ++i) {
            const std::uint32_t node = gpu.levelStart[level] + i;
            for (int s = 0; s < 27; ++s) {
                const glm::ivec3 p = samplePosition(unpackCell(gpu.coord[node]), s, h);
                const bool plus = p.x == plusSampleX(h), minus = p.x == minusSampleX(h);
                if (!(plus || minus) || !onTheWall(p, h)) continue;
                const std::array<double, 6> tau = gpuDensities(gpu, node, s);
                const double along = std::exp(-tau[plus ? 0 : 3] * h);
                EXPECT_LE(along, 0.01) << "level " << level << " sample at " << p.x << "," << p.y << "," << p.z << " along "
                                       << (plus ? "+x" : "-x") << ": τ = " << tau[plus ? 0 : 3];
                worstAlong = std::max(worstAlong, along);
                for (int d : {1, 2, 4, 5}) {
                    const double across = std::exp(-tau[d] * h);
                    EXPECT_GE(across, 0.9) << "level " << level << " sample at " << p.x << "," << p.y << "," << p.z << " along "
                                           << kDirectionName[d] << ": τ = " << tau[d];
                    worstAcross = std::min(worstAcross, across);
                }
                ++checked;
            }
        }
        EXPECT_GT(checked, 0u) << "level " << level << ": no sample's slab holds the wall";
        std::printf("[ slabs    ] one-voxel wall, level %d (h = %2d): %3zu samples beside it, T along x ≤ %.4f, "
                    "T across ≥ %.4f\n",
                    level, h, checked, worstAlong, worstAcross);
    }
    checkSlabOpacity(gpu, "wall");
}

// Transmittance along x of every row of cells (y, z) with 2 ≤ y, z ≤ 61 (rows the walls below
// cross in full): the product of (1 − α_x) over the row's cells; and the most cells of one row
// with α_x > 0.
struct RowTransmittance {
    double largest = 0.0;
    int thickest = 0;
    std::size_t rows = 0;
};
RowTransmittance rowTransmittanceAlongX(const GpuOctreeData& gpu) {
    std::map<std::pair<unsigned, unsigned>, std::pair<double, int>> rows;  // (y, z) → (T, cells with α_x > 0)
    for (const auto& [packed, alpha] : cellOpacityOf(gpu)) {
        const glm::uvec3 c = unpackCell(packed);
        if (c.y < 2 || c.y > 61 || c.z < 2 || c.z > 61) continue;
        auto& row = rows.try_emplace({c.y, c.z}, 1.0, 0).first->second;
        row.first *= 1.0 - alpha.x;
        row.second += alpha.x > 0.0 ? 1 : 0;
    }
    RowTransmittance result;
    for (const auto& [yz, row] : rows) {
        result.largest = std::max(result.largest, row.first);
        result.thickest = std::max(result.thickest, row.second);
        ++result.rows;
    }
    return result;
}

TEST(Slabs, WallsOnACellFaceOrAcrossCellsBlockEveryRow) {
    // A ray along a row of cells crosses a wall once, in one of the cells the wall passes
    // through: the row must be opaque along x (the cells hold α_x = 1 at 8 bits: T ≤ 0.01). A
    // wall lying on the cell face x = 37 stays one layer thick; a tilted wall crossing two cells
    // of a row blocks it in both (split by area, each would pass half: T = 0.25).
    struct Wall {
        const char* name;
        double x0, slope;  // the plane x = x0 + slope·y
        int thickest;      // most cells of a row that may block
    };
    for (const Wall& wall : {Wall{"on the cell face x = 37", 37.0, 0.0, 1}, Wall{"tilted, x = 20.1 + 0.3y", 20.1, 0.3, 2}}) {
        VoxelScene v{kWallLevels};
        const double lo = 0.25, hi = 63.75;
        auto x = [&](double y) { return wall.x0 + wall.slope * y; };
        v.quad({x(lo), lo, lo}, {x(hi), hi, lo}, {x(hi), hi, hi}, {x(lo), lo, hi});
        const Scene scene = v.scene();
        SvoHarness harness(scene);
        const RowTransmittance t = rowTransmittanceAlongX(harness.build(kWallLevels));
        std::printf("[ slabs    ] wall %s: %zu rows, T along x ≤ %.4f, at most %d blocking cells per row\n", wall.name,
                    t.rows, t.largest, t.thickest);
        EXPECT_EQ(t.rows, 60u * 60u) << wall.name;
        EXPECT_LE(t.largest, 0.01) << wall.name;
        EXPECT_LE(t.thickest, wall.thickest) << wall.name;
    }
}

TEST(Slabs, QuarterCoveredNodeTransmitsThreeQuarters) {
    // At 64³, level 2 has nodes of 16 voxels and samples h = 8 apart. A square pillar, a closed
    // box of side 8 (half a node) on x, y ∈ [16, 24] and z ∈ [25.5, 41.5], stands in the node
    // [16, 32]³ and above it. Seen along z from the node's centre sample Q = (24, 24, 24), it
    // covers the quadrant [16, 24]² of the slab's cross-section (the slab reaches ±h across with
    // weights symmetric about Q, so the quadrant holds exactly ¼ of them), and of the pillar only
    // its lower cap (z = 25.5, one voxel of α_z = 1; the sides are parallel to z, α_z = 0) lies
    // in the slab [24, 32). Averaging transmittance over the cross-section gives
    // T = ¾ + ¼·0.001 ≈ 0.75; averaging optical depth instead would give the slab a mean optical
    // depth of ¼·(−ln 0.001) = 1.73 and T = exp(−1.73) = 0.18.
    // The same from above: the −z slab of (24, 24, 32) reaches back to z = 24 and holds the cap.
    VoxelScene v{6};
    v.box({16.0, 16.0, 25.5}, {24.0, 24.0, 41.5});
    const Scene scene = v.scene();
    SvoHarness harness(scene);
    const GpuOctreeData gpu = harness.build(6);
    // GPU transmittance exp(−τ·h) of the slab of the sample at voxel position p, level `level`, direction d.
    auto transmittance = [&](const GpuOctreeData& g, int level, glm::ivec3 p, int d) {
        const int h = spacing(6, level);
        for (std::uint32_t i = 0; i < g.levelCount[level]; ++i) {
            const std::uint32_t node = g.levelStart[level] + i;
            for (int s = 0; s < 27; ++s)
                if (samplePosition(unpackCell(g.coord[node]), s, h) == p) return std::exp(-gpuDensities(g, node, s)[d] * h);
        }
        ADD_FAILURE() << "no sample at " << p.x << "," << p.y << "," << p.z << " at level " << level;
        return -1.0;
    };
    const double up = transmittance(gpu, 2, {24, 24, 24}, 2);    // +z from below the pillar
    const double down = transmittance(gpu, 2, {24, 24, 32}, 5);  // −z from inside it, towards its lower cap
    EXPECT_GE(up, 0.65);
    EXPECT_LE(up, 0.85);
    EXPECT_GE(down, 0.65);
    EXPECT_LE(down, 0.85);
    // One level finer (h = 4) the pillar fills the whole cross-section of the slab at (20, 20, 24),
    // whose +z slab [24, 28) holds the cap: opaque, so the pillar does block where it stands.
    const double filled = transmittance(gpu, 3, {20, 20, 24}, 2);
    EXPECT_LE(filled, 0.01);
    std::printf("[ slabs    ] pillar over a quarter of the slab (h = 8): T = %.4f along +z, %.4f along −z "
                "(averaged τ would give 0.18); filled slab (h = 4): T = %.4f\n",
                up, down, filled);
    checkSlabOpacity(gpu, "pillar");

    // Measured, not asserted: a box short enough for both caps to lie in the slab (z ∈ [25.5,
    // 30.5]) passes less than ¾. The caps lie in the two child slabs [24, 28) and [28, 32), and the
    // definition multiplies the child slabs' transmittances, each already averaged over its
    // cross-section: the child column at (24, 24), a quarter covered, gives 0.75 · 0.75 instead of
    // 0.75, and the 3 × 3 tent over the child columns gives 41/64 = 0.641 (1/16·0 + 2/8·0.25 +
    // 1/4·0.5625 + the uncovered rest), where the cross-section average of the whole slab is 0.75.
    VoxelScene shortBox{6};
    shortBox.box({16.0, 16.0, 25.5}, {24.0, 24.0, 30.5});
    const Scene shortScene = shortBox.scene();
    SvoHarness shortHarness(shortScene);
    const GpuOctreeData shortGpu = shortHarness.build(6);
    std::printf("[ slabs    ] box with both caps in the slab (h = 8): T = %.4f along +z (the definition: 41/64 = "
                "%.4f; a cross-section average over the whole slab: 0.75)\n",
                transmittance(shortGpu, 2, {24, 24, 24}, 2), 41.0 / 64.0);
}

TEST(Slabs, RadianceSeenFromTheDarkSideOfAWallIsDark) {
    // The wall of the wall test under a sun from the −x side, tilted 30° (travelling along
    // (cos 30°, −sin 30°, 0)). Its cells are lit: L = ρ/π·E·cos θ whichever way they are looked
    // at; only the slab's direction (which side of the wall sends the light) can keep a cone on the
    // +x side, looking along −x into the wall, from seeing it. Lit side: the +x slab of the sample
    // before the wall; dark side: the −x slab of the sample after it (same y, z), at every level.
    const VoxelScene v = wallScene();
    Scene scene = v.scene();
    const double theta = glm::radians(30.0), E = 4.0, rho = 0.8;
    Light sun;
    sun.direction = glm::dvec3(std::cos(theta), -std::sin(theta), 0.0);
    sun.irradiance = E;
    auto context = gl::createContext(gl::defaultBackend());
    const auto renderer = test::renderRadianceFrame(scene, {sun}, kWallLevels, 512);
    const Octree& octree = renderer->octree()->octree();
    const RadianceVolume& volume = *renderer->radiance();
    const auto coords = readBuffer<std::uint32_t>(octree.coord, octree.totalCount);
    const double expected = rho / glm::pi<double>() * E * std::cos(theta);

    // The wall's cells, interior ones (the edges of the wall hold less surface): their radiance.
    const auto cellRadiance = readBuffer<glm::vec4>(volume.cellRadiance, octree.cellCount());
    double cellSum = 0.0;
    int cells = 0;
    for (std::uint32_t i = 0; i < octree.cellCount(); ++i) {
        const glm::uvec3 c = unpackCell(coords[octree.levelStart[octree.levels] + i]);
        if (c.x != kWallCell || c.y < 4 || c.z < 4 || c.y > 59 || c.z > 59 || cellRadiance[i].w <= 0.0f) continue;
        cellSum += (cellRadiance[i].x + cellRadiance[i].y + cellRadiance[i].z) / 3.0 / cellRadiance[i].w;
        ++cells;
    }
    ASSERT_GT(cells, 1000) << "the wall's cells";
    const double cellMean = cellSum / cells;
    EXPECT_NEAR(cellMean, expected, 0.1 * expected) << "the wall's cells are lit";
    std::printf("[ slabs    ] lit wall: cell radiance %.4f (ρ/π·E·cos θ = %.4f)\n", cellMean, expected);

    // The six directions' bricks (+x −x +y −y +z −z), stacked along z (directional_pool.glsl).
    const glm::ivec3 bricks = volume.directionalBricks, size = 3 * bricks * glm::ivec3(1, 1, 6);
    const std::vector<float> pool = readBrickPool(volume.directional, bricks * glm::ivec3(1, 1, 6));
    auto radianceAt = [&](int direction, std::uint32_t node, int s, double& tau) {
        const int b = int(node);
        const glm::ivec3 t = 3 * glm::ivec3(b % bricks.x, (b / bricks.x) % bricks.y, b / (bricks.x * bricks.y)) +
                             glm::ivec3(0, 0, 3 * direction * bricks.z) + glm::ivec3(s % 3, (s / 3) % 3, s / 9);
        const float* texel = &pool[((std::size_t(t.z) * size.y + t.y) * size.x + t.x) * 4];
        tau = texel[3];
        return tau > 0.0 ? (double(texel[0]) + texel[1] + texel[2]) / 3.0 / tau : 0.0;  // L = rgb / a
    };
    for (int level = 0; level < kWallLevels; ++level) {
        const int h = spacing(kWallLevels, level);
        std::map<std::pair<int, int>, double> lit, dark;  // (y, z) → L
        for (std::uint32_t i = 0; i < octree.levelCount[level]; ++i) {
            const std::uint32_t node = octree.levelStart[level] + i;
            for (int s = 0; s < 27; ++s) {
                const glm::ivec3 p = samplePosition(unpackCell(coords[node]), s, h);
                if (!onTheWall(p, h)) continue;
                double tau = 0.0;
                if (p.x == plusSampleX(h)) {
                    lit[{p.y, p.z}] = radianceAt(0, node, s, tau);  // +x: looking into the lit face
                    EXPECT_GT(tau, 0.0) << "level " << level << ": the lit side's slab holds the wall";
                } else if (p.x == minusSampleX(h)) {
                    dark[{p.y, p.z}] = radianceAt(1, node, s, tau);  // −x: looking into the dark face
                    EXPECT_GT(tau, 0.0) << "level " << level << ": the dark side's slab holds the wall";
                }
            }
        }
        ASSERT_FALSE(lit.empty()) << "level " << level;
        EXPECT_EQ(lit.size(), dark.size()) << "level " << level;
        double litMin = 1e30, darkWorst = 0.0;
        for (const auto& [yz, l] : lit) {
            litMin = std::min(litMin, l);
            EXPECT_GE(l, 0.5 * expected) << "level " << level << " lit side at y, z = " << yz.first << "," << yz.second;
            const auto d = dark.find(yz);
            if (d == dark.end()) continue;
            darkWorst = std::max(darkWorst, d->second / l);
            EXPECT_LE(d->second, 0.01 * l) << "level " << level << " dark side at y, z = " << yz.first << "," << yz.second
                                           << ": L = " << d->second << ", lit side " << l;
        }
        std::printf("[ slabs    ] lit wall, level %d (h = %2d): %3zu sample pairs, lit side L ≥ %.4f (%.0f %% of the "
                    "cell's), dark side ≤ %.2e of the lit side\n",
                    level, h, lit.size(), litMin, 100.0 * litMin / expected, darkWorst);
    }
}

TEST(Slabs, AThinClosedRodBlocksItsSilhouetteNotTwice) {
    // A closed square rod 0.3 voxels thick inside one column of cells: a ray across it meets its
    // near face and leaves through its far face, both in the same cell, and is blocked once: the
    // cell's opacity across the rod is its silhouette, 0.3. Summing the areas the rod's faces
    // project across it counted both faces (0.6): every baluster, rod and chain link at the
    // voxels' scale blocked twice the light it does.
    VoxelScene v{kWallLevels};
    v.box({32.35, 32.35, 10.25}, {32.65, 32.65, 53.75});
    const Scene scene = v.scene();
    SvoHarness harness(scene);
    int cells = 0;
    glm::dvec2 lowest(1.0), highest(0.0);
    for (const auto& [packed, alpha] : cellOpacityOf(harness.build(kWallLevels))) {
        const glm::uvec3 c = unpackCell(packed);
        if (c.z <= 10 || c.z >= 53) continue;  // the caps
        ++cells;
        lowest = glm::min(lowest, glm::dvec2(alpha));
        highest = glm::max(highest, glm::dvec2(alpha));
    }
    std::printf("[ slabs    ] rod 0.3 voxels thick, %d cells: opacity across it %.3f..%.3f (x), %.3f..%.3f (y)\n", cells,
                lowest.x, highest.x, lowest.y, highest.y);
    EXPECT_EQ(cells, 42);
    for (int a = 0; a < 2; ++a) {
        EXPECT_NEAR(lowest[a], 0.3, 0.01) << "axis " << a;
        EXPECT_NEAR(highest[a], 0.3, 0.01) << "axis " << a;
    }
}
