// The cone spread model of cone_trace (shaders/cone_spread.glsl), run on the GPU: for cones in
// every direction and of every aperture the engine uses, how much of the cone travels along
// ±x, ±y, ±z. Checked against the same normal model in double precision, against its defining
// identity (E[max(d_a, 0)] − E[max(−d_a, 0)] = E[d_a]) and against the cone itself (directions
// uniform over its cap, by numerical integration); no weight may be negative, since a negative
// weight subtracts the light that lies ahead.
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "gl/compute.hpp"
#include "gl/context.hpp"
#include "gl/shader.hpp"
#include "shader_probe.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

struct SpreadCase {
    glm::vec4 cone;       // unit axis, tan of the half-angle
    glm::vec4 alongPlus;  // written by the shader
    glm::vec4 alongMinus;
};

// E[max(x, 0)] for x normal (mu, sigma), in double precision.
double positivePartMean(double mu, double sigma) {
    if (sigma < 1e-12) return std::max(mu, 0.0);
    const double z = mu / sigma;
    return mu * 0.5 * std::erfc(-z / std::sqrt(2.0)) + sigma * std::exp(-0.5 * z * z) / std::sqrt(2.0 * glm::pi<double>());
}

// The model of cone_spread.glsl, in double precision: E[max(d_a, 0)] for axis component c.
double modelAlongPlus(double c, double tanHalfAngle) {
    const double cosHalf = 1.0 / std::sqrt(1.0 + tanHalfAngle * tanHalfAngle);
    const double cosMean = 0.5 * (1.0 + cosHalf);
    const double sin2Mean = (1.0 - cosHalf) * (2.0 + cosHalf) / 3.0;  // E[sin² φ] over the cap
    return positivePartMean(c * cosMean, std::sqrt(std::max((1.0 - c * c) * sin2Mean * 0.5, 0.0)));
}

// The cone itself: E[max(d_a, 0)] over directions uniform in solid angle on its cap.
glm::dvec3 integratedAlongPlus(glm::dvec3 axis, double tanHalfAngle) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
    const double cosHalf = 1.0 / std::sqrt(1.0 + tanHalfAngle * tanHalfAngle);
    const int rings = 200, sectors = 400;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < rings; ++i) {
        const double cosPhi = 1.0 - (i + 0.5) / rings * (1.0 - cosHalf);  // uniform in cos φ: equal solid angle
        const double sinPhi = std::sqrt(1.0 - cosPhi * cosPhi);
        for (int j = 0; j < sectors; ++j) {
            const double theta = (j + 0.5) / sectors * 2.0 * glm::pi<double>();
            const glm::dvec3 d = cosPhi * axis + sinPhi * (std::cos(theta) * u + std::sin(theta) * v);
            sum += glm::max(d, glm::dvec3(0.0));
        }
    }
    return sum / double(rings * sectors);
}

}  // namespace

TEST(ConeSpread, AxisWeightsMatchTheModelAndTheConeAndAreNeverNegative) {
    // A compute shader that runs coneSpread for every case, on the real include.
    const std::string probe =
        "#version 450\nlayout(local_size_x = 64) in;\n#include \"cone_spread.glsl\"\n"
           "struct SpreadCase { vec4 cone; vec4 alongPlus; vec4 alongMinus; };\n"
           "layout(std430, binding = SSBO_CONE_COUNTERS) buffer Cases { SpreadCase cases[]; };\n"
           "uniform uint uCount;\n"
           "void main() {\n"
           "    uint i = gl_GlobalInvocationID.x;\n"
           "    if (i >= uCount) return;\n"
           "    vec3 plus, minus;\n"
           "    coneSpread(cases[i].cone.xyz, cases[i].cone.w, plus, minus);\n"
           "    cases[i].alongPlus = vec4(plus, 0.0);\n"
           "    cases[i].alongMinus = vec4(minus, 0.0);\n"
           "}\n";

    // Axes over the sphere (including exact and nearly exact axis directions, where the model's
    // deviation vanishes), apertures from narrow to the widest ring cones.
    std::vector<SpreadCase> cases;
    const float tanHalfAngles[] = {0.05f, 0.3f, 0.577f, 0.8f, 1.0f, 1.5f};
    std::vector<glm::vec3> axes = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, glm::normalize(glm::vec3(1e-3f, -1, 0)),
                                   glm::normalize(glm::vec3(0.05f, -1, 0.02f))};
    for (int i = 0; i < 60; ++i) {  // a Fibonacci sphere
        const float z = 1.0f - (i + 0.5f) / 30.0f, r = std::sqrt(1.0f - z * z), phi = 2.39996323f * i;
        axes.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    for (const glm::vec3& axis : axes)
        for (float t : tanHalfAngles) cases.push_back({glm::vec4(axis, t), glm::vec4(0.0f), glm::vec4(0.0f)});

    auto context = gl::createContext(gl::defaultBackend());
    const std::vector<SpreadCase> out = test::runShaderProbe("cone_spread_probe.comp", {"cone_spread.glsl"}, probe, cases);

    double worstModel = 0.0, worstCone = 0.0;
    for (const SpreadCase& c : out) {
        const glm::dvec3 axis = glm::dvec3(glm::vec3(c.cone));
        const double t = c.cone.w;
        const double cosHalf = 1.0 / std::sqrt(1.0 + t * t);
        const glm::dvec3 cone = integratedAlongPlus(axis, t);
        for (int a = 0; a < 3; ++a) {
            const double plus = c.alongPlus[a], minus = c.alongMinus[a];
            EXPECT_GE(plus, 0.0) << "axis " << axis[a] << " tan " << t;
            EXPECT_GE(minus, 0.0) << "axis " << axis[a] << " tan " << t;
            const double model = modelAlongPlus(axis[a], t);
            EXPECT_NEAR(plus, model, 2e-5) << "axis component " << axis[a] << ", tan " << t;
            EXPECT_NEAR(minus, model - axis[a] * 0.5 * (1.0 + cosHalf), 2e-5) << "axis component " << axis[a] << ", tan " << t;
            worstModel = std::max(worstModel, std::abs(plus - model));
            // The normal model against the cone: both sides' weight within 0.03 of the true mean
            // (E[|d_a|] is at most 1).
            EXPECT_NEAR(plus, cone[a], 0.03) << "axis component " << axis[a] << ", tan " << t;
            worstCone = std::max(worstCone, std::abs(plus - cone[a]));
        }
    }
    std::printf("[ spread   ] %zu cones: GPU vs double-precision model %.2e, model vs the cone's directions %.4f\n",
                out.size(), worstModel, worstCone);
}
