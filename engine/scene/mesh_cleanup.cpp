#include "scene/mesh_cleanup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/vector_text.hpp"

namespace vct {
namespace {

bool isFinite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// The part that owns vertex `v` (parts are sorted by firstVertex).
const GeometryPart* partOf(const WorldGeometry& g, std::uint32_t v) {
    auto it = std::upper_bound(g.parts.begin(), g.parts.end(), v,
                               [](std::uint32_t value, const GeometryPart& p) {
                                   return value < p.firstVertex;
                               });
    if (it == g.parts.begin()) return nullptr;
    return &*std::prev(it);
}

}  // namespace

void buildSceneGeometry(const WorldGeometry& g, const std::string& sourceName, bool sanitize,
                        Scene& scene) {
    const std::size_t vertexCount = g.positions.size();
    const std::size_t triangleCount = g.triangleCount();
    if (g.normals.size() != vertexCount || g.uvs.size() != vertexCount ||
        g.triangleMaterials.size() != triangleCount || g.indices.size() != 3 * triangleCount)
        fail(sourceName, ": internal error: inconsistent geometry arrays");
    for (std::uint32_t index : g.indices)
        if (index >= vertexCount) fail(sourceName, ": internal error: vertex index out of range");
    for (std::uint32_t m : g.triangleMaterials)
        if (m >= scene.materials.size())
            fail(sourceName, ": internal error: material index out of range");

    LoadReport& report = scene.report;
    report.sourceTriangles = triangleCount;
    report.degenerateTriangles = 0;
    report.nonFinitePositions = 0;
    report.droppedTriangles = 0;
    report.repairedNormals = 0;
    report.repairedUvs = 0;

    // --- 1. Non-finite positions (counted once per source vertex, however often instanced) ----
    std::vector<char> finite(vertexCount);
    // Beyond ±kMaxWorldCoordinate counts as non-finite (core/vector_text.hpp).
    for (std::size_t v = 0; v < vertexCount; ++v) finite[v] = isUsableCoordinate(g.positions[v]);
    std::vector<char> referenced(vertexCount, 0);
    for (std::uint32_t index : g.indices) referenced[index] = 1;

    std::unordered_set<std::uint64_t> badSourceVertices;
    std::string firstBad;
    for (std::size_t v = 0; v < vertexCount; ++v) {
        if (finite[v] || !referenced[v]) continue;
        const GeometryPart* part = partOf(g, static_cast<std::uint32_t>(v));
        const std::uint32_t local = part ? static_cast<std::uint32_t>(v) - part->firstVertex
                                         : static_cast<std::uint32_t>(v);
        const std::uint64_t key =
            (std::uint64_t(part ? part->sourceMesh : 0) << 32) | std::uint64_t(local);
        badSourceVertices.insert(key);
        if (firstBad.empty())
            firstBad = concat("mesh '", part ? part->name : std::string("?"), "' vertex ", local);
    }
    report.nonFinitePositions = badSourceVertices.size();
    if (report.nonFinitePositions > 0 && !sanitize)
        fail(sourceName, ": ", report.nonFinitePositions,
             " vertices have non-finite (NaN/Inf, or beyond ±", kMaxWorldCoordinate, ") positions (first: ", firstBad,
             "); fix the model or pass --sanitize to drop the triangles that use them");

    // --- 2. Per-triangle checks: non-finite (sanitize), zero area -----------------------------
    std::vector<std::uint32_t> kept;  // triangle ids
    kept.reserve(triangleCount);
    std::vector<glm::dvec3> faceCross(triangleCount);  // unnormalized, area-weighted normal
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t i0 = g.indices[3 * t], i1 = g.indices[3 * t + 1],
                            i2 = g.indices[3 * t + 2];
        if (!finite[i0] || !finite[i1] || !finite[i2]) {
            ++report.droppedTriangles;
            continue;
        }
        const glm::dvec3 c =
            glm::cross(g.positions[i1] - g.positions[i0], g.positions[i2] - g.positions[i0]);
        const double area2 = glm::length(c);
        if (!(area2 > 0.0) || !std::isfinite(area2)) {
            // Exactly zero in double: duplicate or collinear vertices. (An overflowing cross
            // product of finite but absurdly large coordinates is treated the same way.)
            ++report.degenerateTriangles;
            continue;
        }
        faceCross[t] = c;
        kept.push_back(static_cast<std::uint32_t>(t));
    }
    if (report.droppedTriangles > 0)
        logWarn(concat(sourceName, ": dropped ", report.droppedTriangles,
                       " triangles that use the ", report.nonFinitePositions,
                       " vertices with non-finite positions (--sanitize)"));
    if (report.degenerateTriangles > 0)
        logWarn(concat(sourceName, ": left out ", report.degenerateTriangles,
                       " zero-area triangles (duplicate or collinear vertices)"));
    if (kept.empty())
        fail(sourceName, ": the model has no triangles (", triangleCount,
             " in the file; ", report.degenerateTriangles, " have zero area, ",
             report.droppedTriangles, " were dropped for non-finite positions)");

    // --- 3. Sort by material (stable counting sort), one draw range per used material --------
    const std::size_t materialCount = scene.materials.size();
    std::vector<std::uint32_t> perMaterial(materialCount + 1, 0);
    for (std::uint32_t t : kept) ++perMaterial[g.triangleMaterials[t] + 1];
    for (std::size_t m = 0; m < materialCount; ++m) perMaterial[m + 1] += perMaterial[m];
    std::vector<std::uint32_t> sorted(kept.size());
    {
        std::vector<std::uint32_t> cursor(perMaterial.begin(), perMaterial.end() - 1);
        for (std::uint32_t t : kept) sorted[cursor[g.triangleMaterials[t]]++] = t;
    }
    scene.drawRanges.clear();
    for (std::size_t m = 0; m < materialCount; ++m) {
        const std::uint32_t count = perMaterial[m + 1] - perMaterial[m];
        if (count == 0) continue;
        scene.drawRanges.push_back({3 * perMaterial[m], 3 * count, static_cast<std::uint32_t>(m)});
    }

    // --- 4. Compact vertices in order of first use --------------------------------------------
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(vertexCount, kUnused);
    std::vector<std::uint32_t> order;  // new index -> old index
    order.reserve(vertexCount);
    scene.indices.clear();
    scene.indices.reserve(3 * sorted.size());
    for (std::uint32_t t : sorted)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t old = g.indices[3 * t + k];
            if (remap[old] == kUnused) {
                remap[old] = static_cast<std::uint32_t>(order.size());
                order.push_back(old);
            }
            scene.indices.push_back(remap[old]);
        }

    // --- 5. Normals: keep valid ones (normalized), rebuild the others from the faces ----------
    std::vector<glm::dvec3> normals(order.size());
    std::vector<char> needsRepair(order.size(), 0);
    for (std::size_t n = 0; n < order.size(); ++n) {
        const glm::dvec3 source = g.normals[order[n]];
        const double length = glm::length(source);
        if (isFinite(source) && length > 0.0 && std::isfinite(length)) {
            normals[n] = source / length;
        } else {
            needsRepair[n] = 1;
            normals[n] = glm::dvec3(0.0);
        }
    }
    std::vector<glm::dvec3> firstFace(order.size(), glm::dvec3(0.0));
    for (std::size_t s = 0; s < sorted.size(); ++s) {
        const glm::dvec3 c = faceCross[sorted[s]];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t n = scene.indices[3 * s + k];
            if (!needsRepair[n]) continue;
            normals[n] += c;
            if (firstFace[n] == glm::dvec3(0.0)) firstFace[n] = c;
        }
    }
    for (std::size_t n = 0; n < order.size(); ++n) {
        if (!needsRepair[n]) continue;
        ++report.repairedNormals;
        const double length = glm::length(normals[n]);
        normals[n] = (length > 0.0 && std::isfinite(length)) ? normals[n] / length
                                                             : glm::normalize(firstFace[n]);
    }

    // --- 6. Bounds in double, origin at the centre, float positions relative to it ------------
    Bounds bounds;
    bounds.min = glm::dvec3(std::numeric_limits<double>::infinity());
    bounds.max = glm::dvec3(-std::numeric_limits<double>::infinity());
    for (std::uint32_t old : order) {
        bounds.min = glm::min(bounds.min, g.positions[old]);
        bounds.max = glm::max(bounds.max, g.positions[old]);
    }
    scene.worldBounds = bounds;
    scene.origin = bounds.centre();

    scene.vertices.resize(order.size());
    for (std::size_t n = 0; n < order.size(); ++n) {
        const std::uint32_t old = order[n];
        Vertex& out = scene.vertices[n];
        out.position = glm::vec3(g.positions[old] - scene.origin);
        out.normal = glm::vec3(normals[n]);
        glm::dvec2 uv = g.uvs[old];
        if (!isFinite(uv)) {
            ++report.repairedUvs;
            if (!std::isfinite(uv.x)) uv.x = 0.0;
            if (!std::isfinite(uv.y)) uv.y = 0.0;
        }
        out.uv = glm::vec2(uv);
    }
    if (report.repairedUvs > 0)
        logWarn(concat(sourceName, ": set ", report.repairedUvs,
                       " non-finite texture coordinates to 0"));
    if (report.repairedNormals > 0)
        logInfo(concat(sourceName, ": rebuilt ", report.repairedNormals,
                       " missing, zero or non-finite normals from the faces"));
}

}  // namespace vct
