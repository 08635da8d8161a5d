#include "scene/mesh_cleanup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/vector_text.hpp"
#include "scene/texture_mapping.hpp"

namespace vct {
namespace {

// Named apart from vct::isFinite(dvec3): glm converts a dvec3 to a dvec2 implicitly, so an
// overload of the same name would quietly check only x and y of a normal.
bool isUsableUv(const glm::dvec2& v) { return isUsableTextureCoordinate(v.x) && isUsableTextureCoordinate(v.y); }

// ------------------------------------------------------------------------------------------------
// Input checks

// Callers build WorldGeometry in code, so a mismatch here is a bug in vct, not in the model.
void checkConsistency(const WorldGeometry& g, std::size_t materialCount, const std::string& sourceName) {
    const std::size_t vertexCount = g.positions.size();
    const std::size_t triangleCount = g.triangleCount();
    if (g.normals.size() != vertexCount || g.uvs.size() != vertexCount ||
        (!g.uvs1.empty() && g.uvs1.size() != vertexCount) || (!g.colors.empty() && g.colors.size() != vertexCount) ||
        g.triangleMaterials.size() != triangleCount || g.indices.size() != 3 * triangleCount)
        fail(sourceName, ": internal error: inconsistent geometry arrays");
    for (std::uint32_t index : g.indices)
        if (index >= vertexCount) fail(sourceName, ": internal error: vertex index out of range");
    for (std::uint32_t m : g.triangleMaterials)
        if (m >= materialCount) fail(sourceName, ": internal error: material index out of range");
}

void resetGeometryCounters(LoadReport& report, std::size_t sourceTriangles) {
    report.sourceTriangles = sourceTriangles;
    report.degenerateTriangles = 0;
    report.nonFinitePositions = 0;
    report.droppedTriangles = 0;
    report.repairedNormals = 0;
    report.repairedUvs = 0;
}

// ------------------------------------------------------------------------------------------------
// Non-finite positions

// The part that owns vertex `v` (parts are sorted by firstVertex).
const GeometryPart* partOf(const WorldGeometry& g, std::uint32_t v) {
    auto it = std::upper_bound(g.parts.begin(), g.parts.end(), v,
                               [](std::uint32_t value, const GeometryPart& p) {
                                   return value < p.firstVertex;
                               });
    if (it == g.parts.begin()) return nullptr;
    return &*std::prev(it);
}

std::vector<char> referencedVertices(const WorldGeometry& g) {
    std::vector<char> referenced(g.positions.size(), 0);
    for (std::uint32_t index : g.indices) referenced[index] = 1;
    return referenced;
}

// Counts the referenced vertices without a usable position once per *source* vertex (mesh and
// index within it), so a bad vertex of a mesh placed ten times counts once. `firstBad` names the
// first one for the error message.
std::size_t countBadSourceVertices(const WorldGeometry& g, const std::vector<char>& usable,
                                   std::string& firstBad) {
    const std::vector<char> referenced = referencedVertices(g);
    std::unordered_set<std::uint64_t> badSourceVertices;
    for (std::size_t v = 0; v < usable.size(); ++v) {
        if (usable[v] || !referenced[v]) continue;
        const GeometryPart* part = partOf(g, static_cast<std::uint32_t>(v));
        const std::uint32_t local = part ? static_cast<std::uint32_t>(v) - part->firstVertex
                                         : static_cast<std::uint32_t>(v);
        const std::uint64_t key =
            (std::uint64_t(part ? part->sourceMesh : 0) << 32) | std::uint64_t(local);
        badSourceVertices.insert(key);
        if (firstBad.empty())
            firstBad = concat("mesh '", part ? part->name : std::string("?"), "' vertex ", local);
    }
    return badSourceVertices.size();
}

// Per vertex: is its position usable? Beyond ±kMaxWorldCoordinate counts as non-finite
// (core/vector_text.hpp). Sets report.nonFinitePositions; without `sanitize` any such vertex that
// a triangle uses is an error.
std::vector<char> usablePositions(const WorldGeometry& g, const std::string& sourceName,
                                  bool sanitize, LoadReport& report) {
    std::vector<char> usable(g.positions.size());
    for (std::size_t v = 0; v < usable.size(); ++v) usable[v] = isUsableCoordinate(g.positions[v]);
    std::string firstBad;
    report.nonFinitePositions = countBadSourceVertices(g, usable, firstBad);
    if (report.nonFinitePositions > 0 && !sanitize)
        failNonFinitePositions(sourceName, report.nonFinitePositions, firstBad);
    return usable;
}

// ------------------------------------------------------------------------------------------------
// Per-triangle checks: non-finite (sanitize), zero area

struct UsableTriangles {
    std::vector<std::uint32_t> ids;     // the triangles kept, in input order
    std::vector<glm::dvec3> faceCross;  // per input triangle: unnormalized, area-weighted normal
};

UsableTriangles keepUsableTriangles(const WorldGeometry& g, const std::vector<char>& usable,
                                    LoadReport& report) {
    const std::size_t triangleCount = g.triangleCount();
    UsableTriangles kept;
    kept.ids.reserve(triangleCount);
    kept.faceCross.resize(triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t i0 = g.indices[3 * t], i1 = g.indices[3 * t + 1],
                            i2 = g.indices[3 * t + 2];
        if (!usable[i0] || !usable[i1] || !usable[i2]) {
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
        kept.faceCross[t] = c;
        kept.ids.push_back(static_cast<std::uint32_t>(t));
    }
    return kept;
}

// Warns about the triangles left out; none left at all is an error.
void reportLeftOutTriangles(const std::string& sourceName, std::size_t triangleCount,
                            bool noneKept, const LoadReport& report) {
    if (report.droppedTriangles > 0)
        warnDroppedNonFiniteTriangles(sourceName, report.droppedTriangles, report.nonFinitePositions);
    if (report.degenerateTriangles > 0)
        logWarn(concat(sourceName, ": left out ", report.degenerateTriangles,
                       " zero-area triangles (duplicate or collinear vertices)"));
    if (noneKept)
        fail(sourceName, ": the model has no triangles (", triangleCount,
             " in the file; ", report.degenerateTriangles, " have zero area, ",
             report.droppedTriangles, " were dropped for non-finite positions)");
}

// ------------------------------------------------------------------------------------------------
// Index buffer: sorted by material, vertices compacted

// Stable counting sort of the kept triangles by material; one draw range per material used.
std::vector<std::uint32_t> sortByMaterial(const WorldGeometry& g,
                                          const std::vector<std::uint32_t>& kept,
                                          std::size_t materialCount,
                                          std::vector<DrawRange>& drawRanges) {
    std::vector<std::uint32_t> perMaterial(materialCount + 1, 0);
    for (std::uint32_t t : kept) ++perMaterial[g.triangleMaterials[t] + 1];
    for (std::size_t m = 0; m < materialCount; ++m) perMaterial[m + 1] += perMaterial[m];
    std::vector<std::uint32_t> sorted(kept.size());
    std::vector<std::uint32_t> cursor(perMaterial.begin(), perMaterial.end() - 1);
    for (std::uint32_t t : kept) sorted[cursor[g.triangleMaterials[t]]++] = t;

    drawRanges.clear();
    for (std::size_t m = 0; m < materialCount; ++m) {
        const std::uint32_t count = perMaterial[m + 1] - perMaterial[m];
        if (count == 0) continue;
        drawRanges.push_back({3 * perMaterial[m], 3 * count, static_cast<std::uint32_t>(m)});
    }
    return sorted;
}

// Fills `indices` for the sorted triangles with the vertices renumbered in order of first use,
// so vertices no kept triangle uses disappear. Returns new index -> old index.
std::vector<std::uint32_t> compactVertices(const WorldGeometry& g,
                                           const std::vector<std::uint32_t>& sorted,
                                           std::vector<std::uint32_t>& indices) {
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(g.positions.size(), kUnused);
    std::vector<std::uint32_t> order;
    order.reserve(g.positions.size());
    indices.clear();
    indices.reserve(3 * sorted.size());
    for (std::uint32_t t : sorted)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t old = g.indices[3 * t + k];
            if (remap[old] == kUnused) {
                remap[old] = static_cast<std::uint32_t>(order.size());
                order.push_back(old);
            }
            indices.push_back(remap[old]);
        }
    return order;
}

// ------------------------------------------------------------------------------------------------
// Normals: keep valid ones (normalized), rebuild the others from the faces

// The source normals of the compacted vertices, normalized; a missing, zero or non-finite one is
// left at zero and flagged in `needsRepair`.
std::vector<glm::dvec3> validNormals(const WorldGeometry& g, const std::vector<std::uint32_t>& order,
                                     std::vector<char>& needsRepair) {
    std::vector<glm::dvec3> normals(order.size());
    needsRepair.assign(order.size(), 0);
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
    return normals;
}

// Each flagged normal becomes the area-weighted average of the faces that use the vertex, or the
// first such face's normal where that sum cancels out (faces back to back) or overflows.
void rebuildFromFaces(const std::vector<std::uint32_t>& sorted,
                      const std::vector<glm::dvec3>& faceCross,
                      const std::vector<std::uint32_t>& indices,
                      const std::vector<char>& needsRepair, std::vector<glm::dvec3>& normals,
                      std::size_t& repaired) {
    std::vector<glm::dvec3> firstFace(normals.size(), glm::dvec3(0.0));
    for (std::size_t s = 0; s < sorted.size(); ++s) {
        const glm::dvec3 c = faceCross[sorted[s]];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t n = indices[3 * s + k];
            if (!needsRepair[n]) continue;
            normals[n] += c;
            if (firstFace[n] == glm::dvec3(0.0)) firstFace[n] = c;
        }
    }
    for (std::size_t n = 0; n < normals.size(); ++n) {
        if (!needsRepair[n]) continue;
        ++repaired;
        const double length = glm::length(normals[n]);
        normals[n] = (length > 0.0 && std::isfinite(length)) ? normals[n] / length
                                                             : glm::normalize(firstFace[n]);
    }
}

// ------------------------------------------------------------------------------------------------
// Bounds in double, origin at the centre, float positions relative to it

Bounds boundsOf(const std::vector<glm::dvec3>& positions, const std::vector<std::uint32_t>& used) {
    Bounds bounds;
    bounds.min = glm::dvec3(std::numeric_limits<double>::infinity());
    bounds.max = glm::dvec3(-std::numeric_limits<double>::infinity());
    for (std::uint32_t old : used) {
        bounds.min = glm::min(bounds.min, positions[old]);
        bounds.max = glm::max(bounds.max, positions[old]);
    }
    return bounds;
}

// A texture coordinate with its non-finite or unusably large components (isUsableUv) set to 0
// (counted in `repaired`).
glm::vec2 repairedUv(glm::dvec2 uv, std::size_t& repaired) {
    if (!isUsableUv(uv)) {
        ++repaired;
        for (int i = 0; i < 2; ++i)
            if (!isUsableTextureCoordinate(uv[i])) uv[i] = 0.0;
    }
    return glm::vec2(uv);
}

// A vertex colour as an albedo factor: within [0, 1], a non-finite component white (counted in
// `repaired`).
glm::vec3 repairedColour(glm::vec3 c, std::size_t& repaired) {
    glm::vec3 out = c;
    for (int i = 0; i < 3; ++i) out[i] = std::isfinite(out[i]) ? std::clamp(out[i], 0.0f, 1.0f) : 1.0f;
    if (out != c) ++repaired;
    return out;
}

// The Scene's vertices: positions as float(world − origin); non-finite UV components set to 0
// and counted in `repairedUvs`; vertex colours outside [0, 1] clamped, counted in
// `repairedColours`.
std::vector<Vertex> localVertices(const WorldGeometry& g, const std::vector<std::uint32_t>& order,
                                  const std::vector<glm::dvec3>& normals, const glm::dvec3& origin,
                                  std::size_t& repairedUvs, std::size_t& repairedColours) {
    std::vector<Vertex> vertices(order.size());
    for (std::size_t n = 0; n < order.size(); ++n) {
        const std::uint32_t old = order[n];
        Vertex& out = vertices[n];
        out.position = glm::vec3(g.positions[old] - origin);
        out.normal = glm::vec3(normals[n]);
        out.uv = repairedUv(g.uvs[old], repairedUvs);
        if (!g.uvs1.empty()) out.uv1 = repairedUv(g.uvs1[old], repairedUvs);
        if (!g.colors.empty()) out.color = repairedColour(g.colors[old], repairedColours);
    }
    return vertices;
}

void reportRepairs(const std::string& sourceName, const LoadReport& report) {
    if (report.repairedUvs > 0)
        logWarn(concat(sourceName, ": set ", report.repairedUvs,
                       " non-finite texture coordinates or coordinates beyond ±2^24 (no texel can be told apart there) to 0"));
    if (report.repairedNormals > 0)
        logInfo(concat(sourceName, ": rebuilt ", report.repairedNormals,
                       " missing, zero or non-finite normals from the faces"));
}

}  // namespace

void failNonFinitePositions(const std::string& sourceName, std::size_t vertices,
                            const std::string& first) {
    fail(sourceName, ": ", vertices, " vertices have non-finite (NaN/Inf, or beyond ±",
         kMaxWorldCoordinate, ") positions (first: ", first,
         "); fix the model or pass --sanitize to drop the triangles that use them");
}

void warnDroppedNonFiniteTriangles(const std::string& sourceName, std::size_t triangles,
                                   std::size_t vertices) {
    logWarn(concat(sourceName, ": dropped ", triangles, " triangles that use the ", vertices,
                   " vertices with non-finite positions (--sanitize)"));
}

void buildSceneGeometry(const WorldGeometry& g, const std::string& sourceName, bool sanitize,
                        Scene& scene) {
    checkConsistency(g, scene.materials.size(), sourceName);
    LoadReport& report = scene.report;
    resetGeometryCounters(report, g.triangleCount());

    const std::vector<char> usable = usablePositions(g, sourceName, sanitize, report);
    const UsableTriangles kept = keepUsableTriangles(g, usable, report);
    reportLeftOutTriangles(sourceName, g.triangleCount(), kept.ids.empty(), report);

    const std::vector<std::uint32_t> sorted =
        sortByMaterial(g, kept.ids, scene.materials.size(), scene.drawRanges);
    const std::vector<std::uint32_t> order = compactVertices(g, sorted, scene.indices);

    std::vector<char> needsRepair;
    std::vector<glm::dvec3> normals = validNormals(g, order, needsRepair);
    rebuildFromFaces(sorted, kept.faceCross, scene.indices, needsRepair, normals,
                     report.repairedNormals);

    scene.worldBounds = boundsOf(g.positions, order);
    scene.origin = scene.worldBounds.centre();
    std::size_t repairedColours = 0;
    scene.vertices = localVertices(g, order, normals, scene.origin, report.repairedUvs, repairedColours);
    reportRepairs(sourceName, report);
    if (repairedColours > 0)
        logWarn(concat(sourceName, ": clamped ", repairedColours,
                       " vertex colours outside [0, 1] (non-finite components made 1)"));
}

}  // namespace vct
