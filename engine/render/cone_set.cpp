#include "render/cone_set.hpp"

#include <cmath>


#include "core/error.hpp"
#include "core/math_constants.hpp"

namespace vct {

const char* coneSetNames() { return "1|5|6|9|16"; }

std::vector<Cone> makeConeSet(int count) {
    std::vector<int> rings;  // cones per ring after the cap
    switch (count) {
        case 1: rings = {}; break;
        case 5: rings = {4}; break;
        case 6: rings = {5}; break;
        case 9: rings = {8}; break;
        case 16: rings = {5, 10}; break;
        default: fail("--cones ", count, " is not a cone set; use one of ", coneSetNames());
    }
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
            const double azimuth = (j + 0.5 * double(ring)) * 2.0 * kPi / m;  // alternate rings interleave
            const glm::dvec3 d(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
            cones.push_back({glm::vec3(d), float(halfAngle), float(kPi * share)});
        }
        inner = outer;
    }
    return cones;
}

}  // namespace vct
