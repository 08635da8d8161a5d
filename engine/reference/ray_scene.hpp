#pragma once
// The Scene's triangles in an Embree 3 BVH: closest-hit and any-hit (shadow) queries for the path
// tracer, with alpha-masked materials honoured on every kind of ray.
//
// Layout: one Embree triangle geometry per Scene::DrawRange (triangles are sorted by material,
// so geomID names the material), all sharing the Scene's index array and one copy of the vertex
// positions scaled to unit size (rtcSetSharedGeometryBuffer). Embree's intersection test
// multiplies coordinates three at a time, in float with denormals flushed to zero: in a scene
// 1e12 units wide its products overflow and in one 1e-12 wide they vanish, so shadows went
// missing. Scaled by a power of two, which every float multiplication carries exactly, Embree
// sees the same numbers at every scale; rays are scaled on the way in and distances on the way
// out. Geometries of alpha-masked materials get an
// intersection filter that samples the texture's alpha at the hit and rejects holes, so camera,
// bounce and shadow rays all pass through cut-outs exactly as the rasterizer's `discard` does.
//
// The scene is in the scene-local frame (world − Scene::origin), float, like the rasterizer's.
// Embree is built with RTC_SCENE_FLAG_ROBUST: watertight edges, so a ray cannot slip between
// two triangles that share an edge (a closed box must stay closed for the furnace test).
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "reference/materials.hpp"
#include "scene/scene.hpp"

namespace vct::reference {

struct SurfaceHit {
    float distance = 0.0f;        // along the (unit) ray direction
    glm::vec3 position{0.0f};     // scene-local, interpolated from the triangle's vertices
    glm::vec3 geometricNormal{};  // unit, from the triangle's edges; orientation arbitrary
    glm::vec3 shadingNormal{};    // unit interpolated vertex normal (geometric when degenerate)
    glm::vec2 uv{0.0f};           // vertex UV sets 0 and 1, interpolated
    glm::vec2 uv1{0.0f};
    glm::vec3 color{1.0f};        // vertex colour, interpolated
    std::uint32_t material = 0;
    float offset = 0.0f;          // how far to push a new ray's origin off this surface
    glm::vec3 inward{0.0f};       // towards the triangle's centroid, length ≤ offset (see below)

    // A new ray's origin for leaving the surface towards `direction`:
    //  * moved along the geometric normal to that side by `offset`, which scales with the
    //    magnitude of the coordinates (float's rounding error does), so a scene 10⁶ units wide
    //    behaves like one at unit scale;
    //  * and moved by `inward` into the triangle, away from its edges. A hit on (or within
    //    rounding of) an edge where two walls meet at a concave corner would otherwise start the
    //    next ray on the other wall's plane, where that wall is missed or hit from behind, and
    //    light leaks through the corner. Hits exactly on edges are common with axis-aligned
    //    rooms and symmetric cameras (a pixel centre looking straight along a corner).
    glm::vec3 spawnPoint(glm::vec3 direction) const {
        const float side = glm::dot(geometricNormal, direction) >= 0.0f ? 1.0f : -1.0f;
        return position + geometricNormal * (side * offset) + inward;
    }
};

class RayScene {
public:
    // Keeps pointers into `scene` and `materials`: both must outlive the RayScene.
    RayScene(const Scene& scene, const MaterialTable& materials);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Closest surface along origin + t·direction, t ∈ (0, tFar); direction must be unit length.
    std::optional<SurfaceHit> intersect(glm::vec3 origin, glm::vec3 direction,
                                        float tFar = std::numeric_limits<float>::infinity()) const;
    // True when anything blocks origin + t·direction for t ∈ (0, tFar).
    bool occluded(glm::vec3 origin, glm::vec3 direction,
                  float tFar = std::numeric_limits<float>::infinity()) const;

    // Per-geometry data the alpha filter reads (public so the C callback can see it).
    struct RangeData {
        const Scene* scene;
        const MaterialTable* materials;
        std::uint32_t firstTriangle;
        std::uint32_t material;
    };

private:
    // A ray of the scene (origin and tFar in its units, unit direction) as Embree's scaled one.
    RTCRay embreeRay(glm::vec3 origin, glm::vec3 direction, float tFar) const;

    const Scene& scene_;
    int scaleExponent_ = 0;              // Embree's coordinates are the scene's times 2^scaleExponent_
    std::vector<glm::vec4> positions_;   // scaled; vec4 because Embree reads 16 bytes per vertex
    std::vector<RangeData> ranges_;      // indexed by geomID
    float minimumOffset_ = 0.0f;     // floor of SurfaceHit::offset from the scene's size
    RTCDevice device_ = nullptr;
    RTCScene rtcScene_ = nullptr;
};

}  // namespace vct::reference
