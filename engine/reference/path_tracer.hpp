#pragma once
// The integrator: unidirectional path tracing of two-sided Lambertian surfaces with next-event
// estimation for the delta lights.
//
// A path starts with a camera ray. At every surface it reaches it adds
//   emission Le (of the surface the ray hit), and
//   NEE: ρ/π · Σ_lights E·cosθ·V (one shadow ray per light).
// Then it continues with a cosine-weighted direction (throughput ×= ρ, see sampling.hpp).
//
// `bounces` B counts *indirect* bounces: B = 0 is direct light only (camera hit: Le + NEE);
// B = 1 adds light that reached the camera hit from one other surface (that surface's Le and
// NEE), which is what the voxel cone tracing models; larger B converges to full GI.
//
// Emissive triangles are not light-sampled (there is no list of emitters to pick from): their
// light arrives only when a bounce ray happens to hit them (plain BSDF sampling, no MIS). That
// is unbiased, and noisy only for small bright emitters, which the engine's scenes do not use.
//
// Russian roulette starts after bounce 3 (so it never acts for B ≤ 3 and the first bounces, the
// ones the engine is compared on, carry no roulette noise): survival probability
// q = min(0.95, max component of the throughput), throughput /= q.
//
// The triangle's geometric normal, turned to face the incoming ray, gives the side the ray
// arrived at; the shading normal is the interpolated vertex normal turned to that side, as in the
// engine's G-buffer (shaders/material.glsl facingNormal), and gives cosθ and the sampling frame.
// (Turned to face the ray by itself, a smooth normal tilted past edge-on would point into the
// surface and darken a curtain's folds seen at a grazing angle.) The geometric normal decides
// which side light may come from and leave to: light behind the triangle and bounce directions
// into it count 0, so interpolated normals that tilt past a wall (smoothed box corners) cannot
// leak light through it.
#include <limits>

#include <glm/glm.hpp>

#include "reference/camera_rays.hpp"
#include "reference/delta_lights.hpp"
#include "reference/materials.hpp"
#include "reference/ray_scene.hpp"
#include "reference/rng.hpp"

namespace vct::reference {

// One camera sample's radiance, split as --direct-out / --indirect-out want it.
struct RadianceSample {
    glm::dvec3 direct{0.0};    // camera hit's emission + NEE at the camera hit
    glm::dvec3 indirect{0.0};  // everything after the first bounce
    bool hit = false;          // the camera ray hit geometry (false: sky, radiance 0)
};

// Which first bounces count (`vct reference --cone-region`): those that leave in one region of
// the engine's cone set, in the engine's tangent frame around the shading normal; region −1: all.
struct ConeRegionFilter {
    int cones = 5;
    int region = -1;
};

// Which first bounces count (`vct reference --first-bounce-distance`): those whose ray meets its
// surface at a distance in [nearest, farthest) from the pixel's surface, in world units. The cones
// of the engine start a voxel and a half off the surface: light reflected by surfaces closer than
// that (a hem above a sunlit floor) is the near field they cannot see, and this splits it out.
struct FirstBounceDistanceFilter {
    float nearest = 0.0f;
    float farthest = std::numeric_limits<float>::infinity();
    bool keeps(float distance) const { return distance >= nearest && distance < farthest; }
};

class PathTracer {
public:
    PathTracer(const RayScene& rays, const MaterialTable& materials, const DeltaLights& lights, int bounces,
               ConeRegionFilter coneRegion = {}, FirstBounceDistanceFilter firstBounceDistance = {})
        : rays_(rays),
          materials_(materials),
          lights_(lights),
          bounces_(bounces),
          coneRegion_(coneRegion),
          firstBounceDistance_(firstBounceDistance) {}

    RadianceSample trace(const Ray& cameraRay, Pcg32& rng) const;

    static constexpr int kRouletteAfterBounce = 3;

private:
    bool inConeRegion(glm::vec3 normal, glm::vec3 direction) const;

private:
    const RayScene& rays_;
    const MaterialTable& materials_;
    const DeltaLights& lights_;
    int bounces_;
    ConeRegionFilter coneRegion_;
    FirstBounceDistanceFilter firstBounceDistance_;
};

}  // namespace vct::reference
