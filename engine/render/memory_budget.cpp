#include "render/memory_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"
#include "render/light_view.hpp"
#include "voxel/voxel_grid.hpp"
#include "voxel/voxelize.hpp"

namespace vct {
namespace {

std::optional<double> budgetOverride;

double mib(std::size_t bytes) { return double(bytes) / 1048576.0; }

std::string mibText(std::size_t bytes) { return concat(std::round(mib(bytes) * 10.0) / 10.0, " MiB"); }

// Occupied voxels at `grid`: a surface fills about |n|₁ voxels per voxel face of its area (the
// layers it crosses along the axes); 1.3 × that covers surfaces on voxel boundaries (two layers)
// and open edges. Triangles of one surface share their voxels, so no per-triangle term.
double estimateCells(const Scene& scene, const VoxelGrid& grid) {
    double projected = 0.0;
    for (std::size_t t = 0; t + 2 < scene.indices.size(); t += 3) {
        const glm::dvec3 a(scene.vertices[scene.indices[t]].position);
        const glm::dvec3 b(scene.vertices[scene.indices[t + 1]].position);
        const glm::dvec3 c(scene.vertices[scene.indices[t + 2]].position);
        const glm::dvec3 n = 0.5 * glm::cross(b - a, c - a);  // area-weighted normal
        projected += std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    }
    return 1.3 * projected / (grid.voxelSize * grid.voxelSize) + 64.0;
}

std::size_t estimateVoxelBytes(const Scene& scene, int levels, bool radiance, bool bounces) {
    const VoxelGrid grid = makeVoxelGrid(scene, levels);
    const double fragments = double(std::min<std::uint64_t>(estimateFragments(scene, grid), 1u << 26));
    const double cells = std::min(estimateCells(scene, grid), std::pow(double(grid.resolution()), 3.0));
    const double nodes = cells / 3.0 + 8.0 * levels;
    bool emissive = false;
    for (const Material& m : scene.materials) emissive = emissive || m.emissive != glm::vec3(0.0f);
    // Bytes per fragment, occupied voxel and interior node of the pools (voxel/octree.hpp,
    // lighting/radiance_volume.hpp); the temporary cell accumulators of svo_leaves included.
    // Three geometry pools (albedo; opacity of the slabs along +axes and −axes) of 27 RGBA16F
    // samples and a raw value per node.
    double bytes = fragments * (16 + 4) + cells * (16 + 16 + 4 + 64 + 24 + (emissive ? 16 : 0)) +
                   nodes * (16 + 24 + 3 * 27 * 8 + 16 + 27 * 16);
    bytes += cells * 16;  // node pool entries of the voxels themselves
    // Radiance: accumulators, cell radiance and direction, flags; per node flags and lists and the
    // six radiance pools of 27 RGBA32F samples (brick_layout.hpp, "Slabs").
    if (radiance) bytes += cells * (4 * gl::RADIANCE_ACCUMULATOR_WORDS + 16 + 32 + 8) + nodes * (8 + 8 + 6 * 27 * 16);
    // The first bounce's radiance and direction, the irradiance first children gather, the radiance
    // and direction of the bounce being gathered (bounce_gather, 128 in all) and the list of cells
    // that gather their own; the voxels' radiance and direction after the last bounce (narrow cones
    // read them).
    if (radiance && bounces) bytes += cells * (128 + 4 + 48);
    return std::size_t(bytes * 1.1);  // brick pools are rounded up to whole rows and slabs
}

// The light-view maps at half the resolution (photons and shadows), never below 16 texels.
void halveMaps(MemoryRequest& r) {
    r.lightViewResolution = std::max(16, r.lightViewResolution / 2);
    r.shadowMapResolution = std::max(16, r.shadowMapResolution / 2);
}

MemoryEstimate estimate(const Scene& scene, const MemoryRequest& r) {
    MemoryEstimate e;
    // Per pixel: G-buffer 60, direct 16, composite 52 (average, sum, weighted indirect sum, 8-bit),
    // voxel view 16; the cones' (render/cone_trace.cpp, ConeTrace::bytes): irradiance 16, the list of
    // pixels that trace their own 20, the edge-aware filter 32, the light carried over camera moves
    // 60, the near field's detail 16. Per traced cell (one pixel of each giBlock² block): its
    // irradiance and pixel 20 (in blocks), the carry's list 4, the near detail's visibility 12 and
    // the shared cones (ConeReuse::coneBytes, and 16).
    const std::size_t pixels = std::size_t(r.width) * std::size_t(r.height);
    const int block = giBlockSize(r.giResolution, r.width, r.height);
    const int cellsWide = (r.width + block - 1) / block, cellsHigh = (r.height + block - 1) / block;
    const std::size_t cells = std::size_t(cellsWide) * std::size_t(cellsHigh);
    const std::size_t sharedCones = r.coneRays > 0 ? ConeReuse::coneBytes(cellsWide, cellsHigh, r.coneRays) + cells * 16 : 0;
    e.imageTargets = pixels * (60 + 16 + 52 + 16) + pixels * (16 + 20 + 32 + 60 + 16) +
                     cells * ((block > 1 ? 20 : 0) + 4 + 12) + sharedCones;
    // Depth 4, position 16, normal 8, flux 16 bytes per texel, one map per light, and a finer
    // shadow map (depth, 4 bytes per texel) beside each.
    // A point light has six maps (a cube), the others one; its faces' shadow maps are coarser.
    const auto mapBytes = [&](int shadowResolution) {
        const std::size_t shadowTexels = shadowResolution > r.lightViewResolution
                                             ? std::size_t(shadowResolution) * std::size_t(shadowResolution)
                                             : 0;
        return std::size_t(r.lightViewResolution) * std::size_t(r.lightViewResolution) * 44 + shadowTexels * 4;
    };
    e.lightViewMaps = 0;
    for (const Light& light : scene.lights) {
        const std::size_t maps = std::size_t(lightViewCount(light));
        e.lightViewMaps += mapBytes(shadowMapSide(light, r.shadowMapResolution)) * maps;
    }
    if (scene.lights.empty()) e.lightViewMaps = mapBytes(r.shadowMapResolution);
    e.sceneData = scene.vertices.size() * sizeof(Vertex) + scene.indices.size() * 4 + scene.materials.size() * 32;
    for (const Texture& t : scene.textures) e.sceneData += std::size_t(t.width) * std::size_t(t.height) * 4 * 4 / 3;
    if (r.octree) e.voxels = estimateVoxelBytes(scene, r.voxelLevels, r.radiance, r.bounces);
    return e;
}

}  // namespace

MemoryEstimate estimateGpuMemory(const Scene& scene, const MemoryRequest& request) { return estimate(scene, request); }

void setMemoryBudgetMiB(double value) {
    if (!(value > 0.0) || !std::isfinite(value))
        fail("--memory-budget ", value, " must be a positive number of MiB");
    budgetOverride = value;
}

std::optional<std::size_t> memoryBudget() {
    if (budgetOverride) return std::size_t(*budgetOverride * 1048576.0);
    const char* env = std::getenv("VCT_MEMORY_BUDGET_MIB");
    if (!env || !*env) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(env, &end);
    if (end == env || *end != '\0' || !(value > 0.0) || !std::isfinite(value))
        fail("VCT_MEMORY_BUDGET_MIB='", env, "' must be a positive number of MiB");
    return std::size_t(value * 1048576.0);
}

void checkMemoryBudget(const Scene& scene, const MemoryRequest& request) {
    const std::optional<std::size_t> budget = memoryBudget();
    if (!budget) return;
    const MemoryEstimate e = estimate(scene, request);
    if (e.total() <= *budget) return;
    // The largest that fits: shrink whichever part is largest (voxel levels by one, the light-view
    // maps by half, the image by 10 %) until the estimate fits, and name the settings changed.
    MemoryRequest r = request;
    std::size_t total = e.total();
    for (int step = 0; step < 200 && total > *budget; ++step) {
        const MemoryEstimate now = estimate(scene, r);
        const bool voxels = r.octree && r.voxelLevels > kMinVoxelLevels;
        const bool maps = r.lightViewResolution > 16 || r.shadowMapResolution > 16;
        const bool image = r.width > 1 || r.height > 1;
        if (voxels && now.voxels >= now.lightViewMaps && now.voxels >= now.imageTargets) --r.voxelLevels;
        else if (maps && now.lightViewMaps >= now.imageTargets) halveMaps(r);
        else if (image) {
            r.width = std::max(1, int(r.width * 0.9));
            r.height = std::max(1, int(r.height * 0.9));
        } else if (voxels) --r.voxelLevels;
        else if (maps) halveMaps(r);
        else break;
        total = estimate(scene, r).total();
    }
    std::string fits;
    if (total > *budget) {
        fits = concat("nothing: even --voxel-levels ", r.voxelLevels, " --light-view-res ", r.lightViewResolution,
                      " --shadow-res ", r.shadowMapResolution,
                      " at ", r.width, "x", r.height, " needs about ", mibText(total));
    } else {
        if (r.voxelLevels != request.voxelLevels) fits += concat("--voxel-levels ", r.voxelLevels, " ");
        if (r.lightViewResolution != request.lightViewResolution) fits += concat("--light-view-res ", r.lightViewResolution, " ");
        if (r.shadowMapResolution != request.shadowMapResolution) fits += concat("--shadow-res ", r.shadowMapResolution, " ");
        if (r.width != request.width || r.height != request.height) fits += concat("--width ", r.width, " --height ", r.height, " ");
        fits += concat("(about ", mibText(total), ")");
    }
    fail("this frame needs about ", mibText(e.total()), " of GPU memory (image targets ", mibText(e.imageTargets),
         ", light-view maps ", mibText(e.lightViewMaps), ", scene ", mibText(e.sceneData), ", voxels at ",
         request.voxelLevels, " levels ", mibText(e.voxels), "), more than the memory budget of ", mibText(*budget),
         "; the largest that fits: ", fits);
}

}  // namespace vct
