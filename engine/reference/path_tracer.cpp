#include "reference/path_tracer.hpp"

#include <algorithm>

#include "reference/sampling.hpp"
#include "render/cone_set.hpp"

namespace vct::reference {
namespace {

glm::vec3 facing(glm::vec3 n, glm::vec3 rayDirection) { return glm::dot(n, rayDirection) > 0.0f ? -n : n; }

// The shading normal on the side of the triangle the ray arrived at (`geometric`, already turned
// to face the ray).
glm::vec3 onSideOf(glm::vec3 shading, glm::vec3 geometric) { return glm::dot(shading, geometric) < 0.0f ? -shading : shading; }

}  // namespace

bool PathTracer::inConeRegion(glm::vec3 normal, glm::vec3 direction) const {
    glm::vec3 tangent, bitangent;
    coneTangentFrame(normal, tangent, bitangent);
    const glm::vec3 local(glm::dot(direction, tangent), glm::dot(direction, bitangent), glm::dot(direction, normal));
    return coneRegionOf(coneRegion_.cones, local) == coneRegion_.region;
}

RadianceSample PathTracer::trace(const Ray& cameraRay, Pcg32& rng) const {
    RadianceSample result;
    auto hit = rays_.intersect(cameraRay.origin, cameraRay.direction);
    if (!hit) return result;
    result.hit = true;

    glm::vec3 geometric = facing(hit->geometricNormal, cameraRay.direction);
    glm::vec3 normal = onSideOf(hit->shadingNormal, geometric);
    glm::vec3 albedo = materials_.albedo(hit->material, hit->uv, hit->uv1, hit->color);
    result.direct = glm::dvec3(materials_.emission(hit->material));
    if (!lights_.empty()) result.direct += lights_.reflected(rays_, *hit, normal, geometric, albedo);

    glm::dvec3 throughput(1.0);
    for (int bounce = 1; bounce <= bounces_; ++bounce) {
        throughput *= glm::dvec3(albedo);  // f·cosθ/pdf of the cosine-sampled Lambertian BRDF
        if (bounce > kRouletteAfterBounce) {
            const double q = std::min(0.95, std::max({throughput.x, throughput.y, throughput.z}));
            if (!(q > 0.0) || rng.uniform() >= q) break;
            throughput /= q;
        } else if (throughput == glm::dvec3(0.0)) {
            break;
        }
        const float u1 = rng.uniform(), u2 = rng.uniform();
        const glm::vec3 direction = glm::normalize(sampleCosineHemisphere(normal, u1, u2));
        if (bounce == 1 && coneRegion_.region >= 0 && !inConeRegion(normal, direction)) break;
        // Sampled around the shading normal, the direction may point into the triangle itself
        // (behind its geometric normal): a reflection cannot go there, the BRDF is 0 (pbrt's
        // "reflect" test). Continuing would carry light through closed walls.
        if (glm::dot(direction, geometric) <= 0.0f) break;
        hit = rays_.intersect(hit->spawnPoint(direction), direction);
        if (!hit) break;  // left the scene: the sky is black
        if (bounce == 1 && !firstBounceDistance_.keeps(hit->distance)) break;
        geometric = facing(hit->geometricNormal, direction);
        normal = onSideOf(hit->shadingNormal, geometric);
        albedo = materials_.albedo(hit->material, hit->uv, hit->uv1, hit->color);
        glm::dvec3 radiance(materials_.emission(hit->material));
        if (!lights_.empty()) radiance += lights_.reflected(rays_, *hit, normal, geometric, albedo);
        result.indirect += throughput * radiance;
    }
    return result;
}

}  // namespace vct::reference
