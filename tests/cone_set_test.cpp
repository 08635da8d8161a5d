// Cone sets: weights integrate the cosine-weighted hemisphere exactly; each weight equals the
// cosine-weighted solid angle of the region its cone stands for (checked by numerical
// integration); cones stay inside the hemisphere.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/error.hpp"
#include "gl/context.hpp"
#include "render/cone_set.hpp"
#include "shader_probe.hpp"
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

TEST(ConeSet, WeightsAndAperturesMatchTheirRegionsByNumericalIntegration) {
    // Rebuild each cone's region from the documented rule (cap sin²θ < 1/N, then rings of equal
    // cosine-weighted share split into equal azimuthal sectors), integrate cosθ dω and dω over it
    // on a grid (0.125°: the grid alone errs by ~0.4 % at a region boundary), and compare with the
    // closed-form weight and the cone's solid angle within 1 %; the
    // cone's axis must lie inside its region.
    const std::map<int, std::vector<int>> rings = {{1, {}}, {5, {4}}, {6, {5}}, {9, {8}}, {16, {5, 10}}};
    for (const auto& [count, ringSizes] : rings) {
        const auto cones = makeConeSet(count);
        std::vector<double> cosine(cones.size(), 0.0), solid(cones.size(), 0.0);
        auto regionOf = [&](double theta, double phi) {
            const double s2 = std::sin(theta) * std::sin(theta);
            if (s2 < 1.0 / count) return std::size_t(0);
            double inner = 1.0 / count;
            std::size_t first = 1;
            for (std::size_t r = 0; r < ringSizes.size(); ++r) {
                const double outer = inner + double(ringSizes[r]) / count;
                if (s2 < outer || r + 1 == ringSizes.size()) {
                    const double sector = glm::two_pi<double>() / ringSizes[r];
                    // Sectors are centred on the cone azimuths (j + r/2) · sector.
                    double a = phi / sector - 0.5 * double(r) + 0.5;
                    a -= std::floor(a / ringSizes[r]) * ringSizes[r];
                    return first + std::size_t(a) % std::size_t(ringSizes[r]);
                }
                first += std::size_t(ringSizes[r]);
                inner = outer;
            }
            return std::size_t(0);
        };
        const int steps = 720;
        for (int i = 0; i < steps; ++i) {
            const double theta = (i + 0.5) / steps * glm::half_pi<double>();
            for (int j = 0; j < 2 * steps; ++j) {
                const double phi = (j + 0.5) / (2 * steps) * glm::two_pi<double>();
                const double dOmega = std::sin(theta) * (glm::half_pi<double>() / steps) * (glm::two_pi<double>() / (2 * steps));
                const std::size_t region = regionOf(theta, phi);
                cosine[region] += std::cos(theta) * dOmega;
                solid[region] += dOmega;
            }
        }
        for (std::size_t c = 0; c < cones.size(); ++c) {
            EXPECT_NEAR(cosine[c], cones[c].weight, 1e-2 * cones[c].weight) << count << " cones, cone " << c;
            const double coneSolidAngle = glm::two_pi<double>() * (1.0 - std::cos(double(cones[c].halfAngle)));
            EXPECT_NEAR(coneSolidAngle, solid[c], 1e-2 * solid[c]) << count << " cones, cone " << c;
            const glm::dvec3 axis(cones[c].direction);
            const double theta = std::acos(std::clamp(axis.z, -1.0, 1.0));
            double phi = std::atan2(axis.y, axis.x);
            if (phi < 0) phi += glm::two_pi<double>();
            if (c > 0) EXPECT_EQ(regionOf(theta, phi), c) << count << " cones: axis outside its region";
        }
    }
}

TEST(ConeSet, UnknownCountIsAClearError) { EXPECT_THROW(makeConeSet(7), Error); }

// The regions of coneRegionOf are those the weights stand for: each cone's axis lies in its own
// region, and of cosine-distributed directions each region holds 1/N (its weight over π).
TEST(ConeSet, RegionsHoldTheirConesAndEqualShares) {
    for (int count : {1, 5, 6, 9, 16}) {
        const auto cones = makeConeSet(count);
        for (int c = 0; c < count; ++c) EXPECT_EQ(coneRegionOf(count, cones[c].direction), c) << count << " cones";
        std::vector<int> hits(count, 0);
        const int n = 400;  // n × n stratified cosine-distributed directions
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n;
                const double r = std::sqrt(u1), phi = 2.0 * glm::pi<double>() * u2;
                const glm::vec3 local(float(r * std::cos(phi)), float(r * std::sin(phi)), float(std::sqrt(1.0 - u1)));
                ++hits[coneRegionOf(count, local)];
            }
        for (int c = 0; c < count; ++c)
            EXPECT_NEAR(double(hits[c]) / (double(n) * n), 1.0 / count, 0.002) << count << " cones, region " << c;
    }
}

// The C++ tangent frame is the GPU's (shaders/math.glsl orthonormalBasis): orthonormal and
// right-handed around the normal, continuous except at n.z = −1's sign switch.
TEST(ConeSet, TangentFrameIsOrthonormalAroundTheNormal) {
    for (const glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                              glm::normalize(glm::vec3(0.3f, -0.8f, 0.52f)), glm::normalize(glm::vec3(-0.1f, 0.2f, -0.97f))}) {
        glm::vec3 t, b;
        coneTangentFrame(n, t, b);
        EXPECT_NEAR(glm::length(t), 1.0, 1e-5);
        EXPECT_NEAR(glm::length(b), 1.0, 1e-5);
        EXPECT_NEAR(glm::dot(t, n), 0.0, 1e-5);
        EXPECT_NEAR(glm::dot(b, n), 0.0, 1e-5);
        EXPECT_NEAR(glm::dot(t, b), 0.0, 1e-5);
        EXPECT_NEAR(glm::dot(glm::cross(t, b), n), 1.0, 1e-5);
    }
}

TEST(ConeSet, TheShadersRegionsAreThePathTracers) {
    // shaders/cone_regions.glsl (which cone's region a narrow cone lies in, for --only-cone) and
    // coneRegionOf (the path tracer's --cone-region) must split the hemisphere alike, or a region's
    // light would be compared with another region's. Directions on a Fibonacci hemisphere, for
    // every set; those within 1e-4 rad of a region's border may round either way.
    const std::string probe =
        "#version 450\nlayout(local_size_x = 64) in;\n#include \"math.glsl\"\n#include \"cone_regions.glsl\"\n"
           "layout(std430, binding = SSBO_CONE_COUNTERS) buffer Cases { vec4 cases[]; };\n"
           "uniform uint uCount;\n"
           "void main() {\n"
           "    uint i = gl_GlobalInvocationID.x;\n"
           "    if (i >= uCount) return;\n"
           "    cases[i].w = float(coneRegionOf(int(cases[i].w), cases[i].xyz));\n"
           "}\n";
    std::vector<glm::vec4> cases;
    const int counts[] = {1, 5, 6, 9, 16};
    const int directions = 4000;
    for (int count : counts)
        for (int i = 0; i < directions; ++i) {
            const float z = 1.0f - (i + 0.5f) / directions, r = std::sqrt(1.0f - z * z), phi = 2.39996323f * i;
            cases.push_back({r * std::cos(phi), r * std::sin(phi), z, float(count)});
        }
    auto context = gl::createContext(gl::defaultBackend());
    const std::vector<glm::vec4> out =
        test::runShaderProbe("cone_regions_probe.comp", {"math.glsl", "cone_regions.glsl"}, probe, cases);
    int disagreements = 0, nearBorder = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const int count = int(cases[i].w);
        const glm::vec3 d(cases[i]);
        const int expected = coneRegionOf(count, d);
        if (int(out[i].w) == expected) continue;
        // Nudged by 1e-4 rad either way, does the C++ side give the shader's answer? Then the
        // direction lies on a border.
        bool border = false;
        for (const glm::vec3 nudge : {glm::vec3(1e-4f, 0, 0), glm::vec3(0, 1e-4f, 0), glm::vec3(0, 0, 1e-4f)})
            for (float s : {-1.0f, 1.0f})
                border = border || coneRegionOf(count, glm::normalize(d + s * nudge)) == int(out[i].w);
        (border ? nearBorder : disagreements) += 1;
        EXPECT_TRUE(border) << count << " cones, direction (" << d.x << ", " << d.y << ", " << d.z << "): shader "
                            << out[i].w << ", path tracer " << expected;
    }
    std::printf("[ regions  ] %zu directions: %d on a border, %d disagreements\n", cases.size(), nearBorder, disagreements);
}
