#include "render/cone_set.hpp"

#include <algorithm>
#include <cmath>
#include <span>


#include "core/error.hpp"
#include "core/math_constants.hpp"

namespace vct {

const char* coneSetNames() { return "1|5|6|9|16"; }

namespace {

// Cones per ring after the cap. Static tables: coneRegionOf runs for every path-traced sample
// of `vct reference --cone-region`.
std::span<const int> ringsOf(int count) {
    static constexpr int kFour[] = {4}, kFive[] = {5}, kEight[] = {8}, kFiveTen[] = {5, 10};
    switch (count) {
        case 1: return {};
        case 5: return kFour;
        case 6: return kFive;
        case 9: return kEight;
        case 16: return kFiveTen;
        default: fail("--cones ", count, " is not a cone set; use one of ", coneSetNames());
    }
}

// The azimuth of cone j of ring `ring` (m cones): alternate rings interleave.
double coneAzimuth(int j, int ring, int m) { return (j + 0.5 * double(ring)) * 2.0 * kPi / m; }

}  // namespace

std::vector<Cone> makeConeSet(int count) {
    const std::span<const int> rings = ringsOf(count);
    const double share = 1.0 / count;  // of the cosine-weighted hemisphere, per cone
    std::vector<Cone> cones;
    // The cap: sin²θ ∈ [0, 1/N] (the whole hemisphere for N = 1).
    const double capSin2 = share;
    cones.push_back({glm::vec3(0, 0, 1), float(std::asin(std::sqrt(capSin2))), float(kPi * share)});
    double inner = capSin2;
    for (std::size_t ring = 0; ring < rings.size(); ++ring) {
        const int m = rings[ring];
        const double outer = inner + m * share;
        const double axisSin2 = 0.5 * (inner + outer);
        const double polar = std::asin(std::sqrt(std::min(axisSin2, 1.0)));
        const double cosInner = std::sqrt(1.0 - inner), cosOuter = std::sqrt(std::max(0.0, 1.0 - outer));
        const double solidAngle = 2.0 * kPi * (cosInner - cosOuter) / m;
        const double halfAngle = std::acos(1.0 - solidAngle / (2.0 * kPi));
        for (int j = 0; j < m; ++j) {
            const double azimuth = coneAzimuth(j, int(ring), m);
            const glm::dvec3 d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
            cones.push_back({glm::vec3(d), float(halfAngle), float(kPi * share)});
        }
        inner = outer;
    }
    return cones;
}

int coneRegionOf(int count, glm::vec3 local) {
    const std::span<const int> rings = ringsOf(count);
    const double length2 = double(glm::dot(local, local));
    const double z = length2 > 0.0 ? double(local.z) / std::sqrt(length2) : 1.0;
    const double sin2 = std::max(0.0, 1.0 - z * z);
    double outer = 1.0 / count;  // the cap
    if (sin2 <= outer || rings.empty()) return 0;
    int first = 1;  // the first cone of the ring
    for (std::size_t ring = 0; ring < rings.size(); ++ring) {
        const int m = rings[ring];
        outer += double(m) / count;
        if (sin2 <= outer || ring + 1 == rings.size()) {
            // The nearest cone axis in azimuth: sectors of 2π/m centred on the axes.
            const double azimuth = std::atan2(double(local.y), double(local.x));
            const double sector = azimuth * m / (2.0 * kPi) - 0.5 * double(ring);
            const int j = int(std::lround(sector));
            return first + ((j % m) + m) % m;
        }
        first += m;
    }
    return 0;
}

void coneTangentFrame(glm::vec3 n, glm::vec3& tangent, glm::vec3& bitangent) {
    const float s = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (s + n.z);
    const float b = n.x * n.y * a;
    tangent = glm::vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    bitangent = glm::vec3(b, s + n.y * n.y * a, -n.y);
}

}  // namespace vct
