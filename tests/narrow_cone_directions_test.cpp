// Which cones the pixel samples of an accumulated frame trace (render/cone_trace.hpp,
// conesForSample), and where narrow cones point (shaders/narrow_cone_directions.glsl): the later
// samples continue one low-discrepancy sequence per block of pixels, so that their directions
// together cover the hemisphere evenly, which independent random directions would not.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/context.hpp"
#include "render/cone_trace.hpp"
#include "shader_probe.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// narrowConePoint for each case (x: k, y: count, z: sequence; the shift in `shift`), in x and y.
std::vector<glm::vec4> narrowConePoints(const std::vector<glm::vec4>& cases, glm::vec2 shift) {
    const std::string probe =
        "#version 450\nlayout(local_size_x = 64) in;\n#include \"narrow_cone_directions.glsl\"\n"
        "layout(std430, binding = SSBO_CONE_COUNTERS) buffer Cases { vec4 cases[]; };\n"
        "uniform uint uCount;\n"
        "void main() {\n"
        "    uint i = gl_GlobalInvocationID.x;\n"
        "    if (i >= uCount) return;\n"
        "    vec4 c = cases[i];\n"
        "    cases[i] = vec4(narrowConePoint(int(c.x), c.y, vec2(" +
        std::to_string(shift.x) + ", " + std::to_string(shift.y) +
        "), int(c.z)), 0.0, 0.0);\n"
        "}\n";
    return test::runShaderProbe("narrow_cone_probe.comp", {"narrow_cone_directions.glsl"}, probe, cases);
}

// The largest number of `points` in one cell of a 4×4 grid over the unit square, and the smallest.
std::pair<int, int> fullestAndEmptiestCell(const std::vector<glm::vec4>& points, std::size_t first, std::size_t count) {
    int cells[16] = {};
    for (std::size_t i = first; i < first + count; ++i) {
        const int x = std::clamp(int(points[i].x * 4.0f), 0, 3), y = std::clamp(int(points[i].y * 4.0f), 0, 3);
        ++cells[4 * y + x];
    }
    return {*std::max_element(cells, cells + 16), *std::min_element(cells, cells + 16)};
}

}  // namespace

TEST(NarrowConeDirections, TheLaterSamplesTraceOneNarrowConeEach) {
    ConeSettings set;
    set.rays = 0;  // `--cone-rays 0`
    const ConeSettings narrow;  // the default: kDefaultNarrowCones
    ASSERT_EQ(narrow.rays, kDefaultNarrowCones);
    for (const ConeSettings& frame : {set, narrow}) {
        const SampleCones first = conesForSample(frame, 0);
        EXPECT_EQ(first.cones, frame);  // a one-sample frame is the plain frame
        EXPECT_EQ(first.raySequence, -1);
        for (int sample : {1, 2, 15, 1000}) {
            const SampleCones later = conesForSample(frame, sample);
            EXPECT_EQ(later.cones.rays, kNarrowConesPerLaterSample) << sample;
            EXPECT_EQ(coneStep(later.cones), kNarrowConeStep) << sample;
            EXPECT_EQ(later.raySequence, (sample - 1) * kNarrowConesPerLaterSample) << sample;
        }
        ConeSettings everySample = frame;
        everySample.narrowConesAfterFirstSample = false;  // `--sample-cones frame`
        EXPECT_EQ(conesForSample(everySample, 5).cones, everySample);
        EXPECT_EQ(conesForSample(everySample, 5).raySequence, -1);
    }
}

TEST(NarrowConeDirections, EachKindOfConeStepsByItsOwnLengthUnlessOneIsGiven) {
    ConeSettings s;
    EXPECT_EQ(coneStep(s), kNarrowConeStep);
    s.rays = 0;
    EXPECT_EQ(coneStep(s), kConeSetStep);
    s.step = 0.75f;
    EXPECT_EQ(coneStep(s), 0.75f);
    // The bounces' gathers trace narrow cones unless they are told to trace the set.
    EXPECT_EQ(coneStep(voxelGatherCones(ConeSettings{})), kNarrowConeStep);
    ConeSettings set;
    set.bounceRays = 0;
    EXPECT_EQ(coneStep(voxelGatherCones(set)), kConeSetStep);
}

TEST(NarrowConeDirections, SamplesContinueOneEvenlySpreadSequence) {
    auto context = gl::createContext(gl::defaultBackend());
    // Sample s's one cone is cone s of the sequence: one cone per sample over N samples points
    // where N cones of one long trace would.
    std::vector<glm::vec4> continued, atOnce;
    for (int s = 0; s < 64; ++s) {
        continued.push_back({0.0f, 1.0f, float(s), 0.0f});
        atOnce.push_back({float(s), 64.0f, 0.0f, 0.0f});
    }
    const glm::vec2 shifts[] = {{0.0f, 0.0f}, {0.3f, 0.8f}, {0.97f, 0.41f}};
    for (const glm::vec2 shift : shifts) {
        const std::vector<glm::vec4> a = narrowConePoints(continued, shift), b = narrowConePoints(atOnce, shift);
        for (std::size_t i = 0; i < a.size(); ++i) {
            EXPECT_EQ(a[i].x, b[i].x) << i;
            EXPECT_EQ(a[i].y, b[i].y) << i;
            EXPECT_GE(a[i].x, 0.0f);
            EXPECT_LT(a[i].x, 1.0f);
        }
        // Evenly spread at every prefix: 16 points leave at most two in any cell of a 4×4 grid, 64
        // points two to six, where independent random points often leave cells empty or crowded.
        for (std::size_t count : {16u, 64u}) {
            const auto [fullest, emptiest] = fullestAndEmptiestCell(a, 0, count);
            const int expected = int(count / 16);
            std::printf("[ sequence ] shift (%.2f, %.2f), first %zu points: %d..%d per cell of 16\n", shift.x, shift.y,
                        count, emptiest, fullest);
            EXPECT_LE(fullest, expected + 2) << count << " points";
            EXPECT_GE(emptiest, std::max(expected - 2, 0)) << count << " points";
        }
        // A later stretch of the sequence (samples 1000..1063) is as even.
        std::vector<glm::vec4> late;
        for (int s = 1000; s < 1064; ++s) late.push_back({0.0f, 1.0f, float(s), 0.0f});
        const auto [fullest, emptiest] = fullestAndEmptiestCell(narrowConePoints(late, shift), 0, 64);
        EXPECT_LE(fullest, 6);
        EXPECT_GE(emptiest, 2);
    }
}

TEST(NarrowConeDirections, ALatticeTracedAtOnceIsUnchanged) {
    // Without a sequence (`--cone-rays N` in one frame) cone k of N is the shifted Fibonacci point.
    auto context = gl::createContext(gl::defaultBackend());
    std::vector<glm::vec4> cases;
    for (int k = 0; k < 16; ++k) cases.push_back({float(k), 16.0f, -1.0f, 0.0f});
    const glm::vec2 shift(0.25f, 0.6f);
    const std::vector<glm::vec4> points = narrowConePoints(cases, shift);
    for (int k = 0; k < 16; ++k) {
        const float sin2 = std::fmod((k + 0.5f) / 16.0f + shift.x, 1.0f);
        const float azimuth = std::fmod(k * 0.61803398875f + shift.y, 1.0f);
        EXPECT_NEAR(points[std::size_t(k)].x, sin2, 1e-6f) << k;
        EXPECT_NEAR(points[std::size_t(k)].y, azimuth, 1e-6f) << k;
    }
}
