// Cone sets: weights integrate the cosine-weighted hemisphere exactly; each weight equals the
// cosine-weighted solid angle of the region its cone stands for (checked by numerical
// integration); cones stay inside the hemisphere.
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "core/error.hpp"
#include "render/cone_set.hpp"
#include "test_util.hpp"

using namespace vct;

TEST(ConeSet, WeightsSumToPiForEverySet) {
    for (int count : {1, 5, 6, 9, 16}) {
        const auto cones = makeConeSet(count);
        ASSERT_EQ(int(cones.size()), count);
        double sum = 0.0;
        for (const Cone& c : cones) {
            sum += c.weight;
            EXPECT_NEAR(glm::length(c.direction), 1.0, 1e-6);
            EXPECT_GE(c.direction.z, 0.0f);
            EXPECT_GT(c.halfAngle, 0.0f);
        }
        EXPECT_NEAR(sum, glm::pi<double>(), 1e-6) << count << " cones";
    }
}

TEST(ConeSet, EachWeightIsTheCosineWeightedSolidAngleOfItsRegion) {
    // Assign every direction of a fine grid on the hemisphere to the nearest cone axis (by angle)
    // and integrate cosθ dω per cone: with regions built as documented, the nearest-axis cells and
    // the regions coincide closely enough to agree within a few percent.
    for (int count : {5, 6, 9, 16}) {
        const auto cones = makeConeSet(count);
        std::vector<double> integral(cones.size(), 0.0);
        const int steps = 600;
        for (int i = 0; i < steps; ++i) {
            const double theta = (i + 0.5) / steps * glm::half_pi<double>();
            for (int j = 0; j < 2 * steps; ++j) {
                const double phi = (j + 0.5) / (2 * steps) * glm::two_pi<double>();
                const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
                const double dOmega = std::sin(theta) * (glm::half_pi<double>() / steps) * (glm::two_pi<double>() / (2 * steps));
                std::size_t best = 0;
                double bestDot = -2;
                for (std::size_t c = 0; c < cones.size(); ++c) {
                    const double dot = glm::dot(d, glm::dvec3(cones[c].direction));
                    if (dot > bestDot) bestDot = dot, best = c;
                }
                integral[best] += std::cos(theta) * dOmega;
            }
        }
        for (std::size_t c = 0; c < cones.size(); ++c)
            EXPECT_NEAR(integral[c], cones[c].weight, 0.12 * cones[c].weight) << count << " cones, cone " << c;
    }
}

TEST(ConeSet, UnknownCountIsAClearError) { EXPECT_THROW(makeConeSet(7), Error); }
