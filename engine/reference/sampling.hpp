#pragma once
// Sampling routines of the path tracer: directions for the Lambertian BRDF and a frame around a
// normal.
#include <cmath>

#include <glm/glm.hpp>

#include "core/math_constants.hpp"

namespace vct::reference {


// Orthonormal basis (t, b, n) around unit n without a branch on "which axis is safe"
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
struct Frame {
    glm::vec3 t, b, n;
    explicit Frame(glm::vec3 normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float c = n.x * n.y * a;
        t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
        b = {c, sign + n.y * n.y * a, -n.y};
    }
    glm::vec3 toWorld(glm::vec3 local) const { return local.x * t + local.y * b + local.z * n; }
};

// Cosine-weighted direction on the hemisphere around n, pdf = cosθ/π (Malley's method: a
// uniform point on the unit disk lifted to the hemisphere). With this pdf the Lambertian
// estimator f·cosθ/pdf = (ρ/π)·cosθ/(cosθ/π) = ρ: a bounce multiplies the throughput by the albedo
// and nothing else, which keeps the variance low and the furnace test exact.
inline glm::vec3 sampleCosineHemisphere(glm::vec3 n, float u1, float u2) {
    const float r = std::sqrt(u1);
    const float phi = 2.0f * kPiF * u2;
    const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
    return Frame(n).toWorld({r * std::cos(phi), r * std::sin(phi), z});
}

}  // namespace vct::reference
