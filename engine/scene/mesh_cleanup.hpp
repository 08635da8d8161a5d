#pragma once
// From world-space triangles (double precision, as gathered by the model importer or built by a
// procedural scene) to the Scene's float buffers, with the input validated and repaired:
//
//   * triangles that use a vertex with a NaN/Inf position (or one beyond ±kMaxWorldCoordinate =
//     1e18, core/vector_text.hpp): an error naming the first such vertex, or (with `sanitize`)
//     dropped and counted;
//   * zero-area triangles (duplicate or collinear vertices, exact test in double): left out and
//     counted, one warning;
//   * missing, zero or non-finite normals: replaced by the (area-weighted) normal of the faces
//     that use the vertex; non-finite UVs: set to 0;
//   * no triangle left: an error;
//   * triangles sorted by material into Scene::drawRanges, unreferenced vertices removed;
//   * Scene::worldBounds computed in double over the remaining vertices, Scene::origin set to its
//     centre and positions stored as float(world − origin) (DESIGN 5.1).
//
// Files and built-in scenes both go through here, so their bounds and origin follow one rule.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace vct {

// One mesh instance inside WorldGeometry, so that messages can name the source mesh and vertex.
struct GeometryPart {
    std::string name;               // the mesh's name in the source file
    std::uint32_t sourceMesh = 0;   // the same value for every instance of one source mesh
    std::uint32_t firstVertex = 0;  // index of its first vertex in WorldGeometry::positions
};

struct WorldGeometry {
    std::vector<glm::dvec3> positions;             // world space
    std::vector<glm::dvec3> normals;               // world space, same size; zero = missing
    std::vector<glm::dvec2> uvs;                   // same size; see Vertex::uv
    std::vector<glm::dvec2> uvs1;                  // same size, or empty (all 0); Vertex::uv1
    std::vector<glm::vec3> colors;                 // same size, or empty (all white); Vertex::color
    std::vector<std::uint32_t> indices;            // 3 per triangle, counter-clockwise = front
    std::vector<std::uint32_t> triangleMaterials;  // one per triangle, index into Scene::materials
    std::vector<GeometryPart> parts;               // ascending firstVertex, first at 0

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Fills scene.vertices, indices, drawRanges, worldBounds, origin and the geometry counters of
// scene.report (sourceTriangles, degenerateTriangles, nonFinitePositions, droppedTriangles,
// repairedNormals, repairedUvs). scene.materials must already hold every material the triangles
// refer to. `sourceName` (usually the file path) starts every message. Throws vct::Error as
// described above.
void buildSceneGeometry(const WorldGeometry& geometry, const std::string& sourceName,
                        bool sanitize, Scene& scene);

// The messages about vertices with non-finite positions, also used by the model importer's own
// check before Assimp merges vertices (scene_loader.cpp), so that both say the same.
[[noreturn]] void failNonFinitePositions(const std::string& sourceName, std::size_t vertices,
                                         const std::string& first);
void warnDroppedNonFiniteTriangles(const std::string& sourceName, std::size_t triangles,
                                   std::size_t vertices);

}  // namespace vct
