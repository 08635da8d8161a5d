// Stress 4, accumulation limits (docs/robustness.md): 10⁵ fragments in one voxel average exactly;
// more than 10⁶ photons in one voxel store the right radiance (64-bit fixed-point sums with
// carries); light intensities from 1e-6 to 1e6 W/sr (and 1e-20/1e20 on 1e-4/1e15 scenes) give
// images that scale linearly with the light, the fixed point being chosen automatically.
#include <cmath>
#include <cstdio>
#include <random>

#include <glm/gtc/constants.hpp>

#include "lighting/inject.hpp"
#include "scene/scene_loader.hpp"
#include "stress_util.hpp"
#include "svo_readback.hpp"

using namespace vct;
using namespace vct::test;

namespace {

Scene unitBoxScene(const std::vector<glm::dvec3>& triangles,
                   const std::vector<std::pair<std::size_t, glm::vec3>>& groups = {}) {
    return makeTriangleScene(triangles, Bounds{glm::dvec3(0.0), glm::dvec3(1.0)}, groups);
}

// Largest relative difference between a/ka and b/kb over the values above `floor` × the largest.
double linearityError(const ImageF& a, double ka, const ImageF& b, double kb, double floor = 1e-3) {
    double peak = 0, worst = 0;
    for (std::size_t i = 0; i < b.rgba.size(); ++i)
        if (i % 4 != 3) peak = std::max(peak, std::abs(double(b.rgba[i]) / kb));
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double x = double(a.rgba[i]) / ka, y = double(b.rgba[i]) / kb;
        if (!std::isfinite(x)) return INFINITY;
        if (std::abs(y) < floor * peak && std::abs(x) < floor * peak) continue;
        worst = std::max(worst, std::abs(x - y) / std::max(std::abs(y), floor * peak));
    }
    return worst;
}

}  // namespace

TEST(StressAccumulation, HundredThousandFragmentsInOneVoxelAverageExactly) {
    // 100 000 tiny triangles inside one voxel: 70 001 red, 19 999 green, 10 000 blue. Each channel
    // sum (≤ 255 · 10⁵) is exact in the 32-bit accumulators; the mean within half an 8-bit step.
    const Scene probe = unitBoxScene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const VoxelGrid grid = makeVoxelGrid(probe, 5);
    std::vector<glm::dvec3> t;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> jitter(0.3, 0.7);
    for (int i = 0; i < 100000; ++i) {
        const glm::dvec3 base(16 + jitter(random), 16 + jitter(random), 16 + jitter(random));
        for (const glm::dvec3 d : {glm::dvec3(0), glm::dvec3(0.02, 0, 0), glm::dvec3(0, 0.02, 0.005)})
            t.push_back(grid.toLocal(base + d) + probe.origin);
    }
    const Scene scene = unitBoxScene(t, {{70001, {1, 0, 0}}, {19999, {0, 1, 0}}, {10000, {0, 0, 1}}});
    SvoHarness harness(scene);
    const GpuOctreeData gpu = harness.build(5);
    ASSERT_EQ(gpu.levelCount[5], 1u) << "all triangles lie in one voxel";
    EXPECT_EQ(gpu.cellFragments[0], 100000u);
    const std::uint32_t a = gpu.cellAlbedo[0];
    const glm::dvec3 expected(0.70001, 0.19999, 0.1);
    const glm::dvec3 got(double(a & 255) / 255.0, double((a >> 8) & 255) / 255.0, double((a >> 16) & 255) / 255.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 0.5 / 255.0 + 1e-9) << "channel " << c;
    double area = 0;
    for (float f : gpu.fragmentArea) area += f;
    EXPECT_NEAR(gpu.cellArea[0], area, 1e-4 * area) << "area sum over 10⁵ fragments (64-bit fixed point)";
    std::printf("[ accumulate] 100000 fragments in one voxel: mean (%.4f, %.4f, %.4f), expected (%.5f, %.5f, %.5f); "
                "area %.4f of %.4f voxel faces\n",
                got.x, got.y, got.z, expected.x, expected.y, expected.z, gpu.cellArea[0], area);
}

TEST(StressAccumulation, MillionsOfPhotonsInOneVoxelStoreTheRightRadiance) {
    // A floor at 5 levels and a narrow spot (inner = outer: constant intensity inside the cone)
    // whose whole footprint lies inside one voxel: every lit texel of a 2048² light-view map is a
    // photon of that voxel (π/4 · 2048² ≈ 3.3 M of them). Expected: L = ρ·Φ / (π·A) with Φ the
    // flux through the cone's texels and A the voxel's floor area (voxel size²).
    const double half = 1.0;  // floor [-1, 1]² at y = 0
    const double voxel = 2.0 * half / (32 - 3);
    std::vector<glm::dvec3> t = {{-half, 0, -half}, {half, 0, half}, {half, 0, -half},
                                 {-half, 0, -half}, {-half, 0, half}, {half, 0, half},
                                 // a speck one voxel below: the floor then lies in the middle of a voxel layer
                                 {-0.9, -voxel, -0.9}, {-0.9 + 1e-3, -voxel, -0.9}, {-0.9, -voxel, -0.9 + 1e-3}};
    Scene scene = makeTriangleScene(t, Bounds{glm::dvec3(-half, -voxel, -half), glm::dvec3(half, 0.0, half)});
    const double albedo = 0.8;
    scene.materials[0].baseColor = glm::vec3(float(albedo));
    const VoxelGrid grid = makeVoxelGrid(scene, 5);
    ASSERT_NEAR(grid.voxelSize, voxel, 1e-12);
    // Aim at the centre of voxel (16, ·, 16): x = z = voxel / 2 in world units.
    const glm::dvec3 target(0.5 * voxel, 0.0, 0.5 * voxel);
    const double height = 1.0, radius = 0.25 * voxel;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = target + glm::dvec3(0, height, 0);
    spot.direction = {0, -1, 0};
    spot.intensity = 3.0;
    spot.innerAngleDeg = spot.outerAngleDeg = glm::degrees(std::atan(radius / height));
    scene.lights = {spot};
    Camera camera;
    camera.eye = {0.0, 2.0, 1.0};
    camera.target = {0.0, 0.0, 0.0};

    auto context = gl::createContext(gl::defaultBackend());
    RenderSettings settings = smallSettings(16, 16, 5, 2048);
    Renderer renderer(scene, settings);
    renderer.renderFrame(camera);
    const Octree& octree = renderer.octree()->octree();
    const auto radiance = readBuffer<glm::vec4>(renderer.radiance()->cellRadiance, octree.cellCount());
    const auto coords = readBuffer<std::uint32_t>(octree.coord, octree.totalCount);
    const auto area = readBuffer<float>(octree.cellArea, octree.cellCount());
    const auto sums = readBuffer<std::uint32_t>(renderer.radiance()->accumulators, std::size_t(octree.cellCount()) * kAccumulatorWords);
    EXPECT_EQ(renderer.statistics().photonsMissed, 0u);

    // The lit texels and their flux, exactly as the light-view map defines them.
    const int res = settings.lightViewResolution;
    const double tanHalf = std::tan(glm::radians(spot.outerAngleDeg)), cosOuter = std::cos(glm::radians(spot.outerAngleDeg));
    const double footprint = std::pow(2.0 * tanHalf / res, 2.0);
    double flux = 0;
    std::size_t photons = 0;
    for (int j = 0; j < res; ++j)
        for (int i = 0; i < res; ++i) {
            const double x = ((i + 0.5) / res * 2.0 - 1.0) * tanHalf, y = ((j + 0.5) / res * 2.0 - 1.0) * tanHalf;
            const double cosAxis = 1.0 / std::sqrt(1.0 + x * x + y * y);
            if (cosAxis < cosOuter) continue;
            ++photons;
            flux += spot.intensity * footprint * cosAxis * cosAxis * cosAxis;
        }
    ASSERT_GE(photons, 1000000u);
    const double analytic = spot.intensity * 2.0 * glm::pi<double>() * (1.0 - cosOuter);
    const glm::uvec3 cell = glm::uvec3(glm::floor(grid.toVoxel(target - scene.origin)));
    int found = -1, lit = 0;
    for (std::uint32_t i = 0; i < octree.cellCount(); ++i) {
        if (radiance[i].x > 0) ++lit;
        if (unpackCell(coords[octree.levelStart[octree.levels] + i]) == cell) found = int(i);
    }
    ASSERT_GE(found, 0) << "no voxel at the spot's target";
    EXPECT_EQ(lit, 1) << "the whole footprint must land in one voxel";
    const double expected = albedo * flux / (glm::pi<double>() * double(area[found]) * voxel * voxel);
    const double stored = radiance[found].x / radiance[found].w;
    EXPECT_NEAR(stored, expected, 0.01 * expected);
    EXPECT_NEAR(area[found], 1.0, 2e-3) << "the floor crosses the whole voxel";
    EXPECT_GT(sums[std::size_t(found) * kAccumulatorWords + 1], 0u) << "the sum needs the high word (carries into 64 bits)";
    std::printf("[ accumulate] %zu photons in one voxel (flux %.6f W, analytic %.6f): radiance %.5f, expected %.5f "
                "(%.3f %%); red sum %.3g units\n",
                photons, flux, analytic, stored, expected, 100.0 * (stored / expected - 1.0),
                double(sums[std::size_t(found) * kAccumulatorWords]) + 4294967296.0 * sums[std::size_t(found) * kAccumulatorWords + 1]);
}

TEST(StressAccumulation, ImagesScaleLinearlyWithLightIntensity) {
    // The Cornell box's spot from 1e-6 to 1e6 W/sr: HDR image at I equals I/8 × the image at the
    // box's 8 W/sr within float tolerance (stated and asserted: 1e-5 relative, measured ~5e-7),
    // for the final image and for the indirect light alone. The fixed point follows the light:
    // wattsPerUnit × 2^24 = the brightest texel's flux.
    const Scene scene = makeCornellBox();
    auto context = gl::createContext(gl::defaultBackend());
    RenderSettings settings = smallSettings(64, 48, 6, 512);
    Renderer renderer(scene, settings);
    auto render = [&](double intensity, Aov aov) {
        std::vector<Light> lights = scene.lights;
        lights[0].intensity = intensity;
        renderer.setLights(lights);
        settings.display.aov = aov;
        renderer.setSettings(settings);
        renderer.renderFrame(scene.cameras[0]);
        return renderer.readHdr();
    };
    const ImageF reference = render(8.0, Aov::Final), referenceIndirect = render(8.0, Aov::Indirect);
    const double referenceUnit = renderer.radiance()->wattsPerUnit;
    double worst = 0;
    for (double intensity : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
        const ImageF indirect = render(intensity, Aov::Indirect);
        const double unit = renderer.radiance()->wattsPerUnit;
        const ImageF final = render(intensity, Aov::Final);
        const double e = linearityError(final, intensity, reference, 8.0), ei = linearityError(indirect, intensity, referenceIndirect, 8.0);
        EXPECT_LE(e, 1e-5) << "I = " << intensity;
        EXPECT_LE(ei, 1e-5) << "I = " << intensity << ", indirect";
        EXPECT_NEAR(unit / intensity, referenceUnit / 8.0, 1e-9 * referenceUnit / 8.0) << "I = " << intensity;
        worst = std::max({worst, e, ei});
        std::printf("[ linearity] I = %-6g W/sr: max relative difference from linear %.2e (final), %.2e (indirect); "
                    "fixed-point unit %.3e W\n",
                    intensity, e, ei, unit);
    }
    std::printf("[ linearity] worst %.2e over 1e-6..1e6 W/sr\n", worst);
}

TEST(StressAccumulation, ExtremeLightsOnExtremeScalesStayLinear) {
    // Where the old float fixed-point scale (2^24 / texel flux) overflowed: a 1e-20 W/m² sun on
    // the box scaled by 1e-4 (texel flux 1e-32 W), and a 1e20 W/m² sun on the box scaled by 1e15
    // (texel flux 1e45 W, beyond float). Each against the same scene under a 1 W/m² sun.
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.2, -0.6, -1.0));  // in through the open front
    for (const auto& [scale, irradiance] : {std::pair{1e-4, 1e-20}, std::pair{1e15, 1e20}}) {
        Scene scene = transformedCornell(scale, glm::dvec3(0.0));  // its lights are replaced below
        auto render = [&](double e) {
            sun.irradiance = e;
            scene.lights = {sun};
            return renderInProcess(scene, scene.cameras[0], smallSettings(48, 36, 5, 256));
        };
        const ImageF one = render(1.0), extreme = render(irradiance);
        ASSERT_EQ(countNonFinite(extreme.rgba), 0u) << "scale " << scale;
        ASSERT_GT(meanRgb(one), 0.0);
        const double e = linearityError(extreme, irradiance, one, 1.0);
        EXPECT_LE(e, 1e-5) << "scale " << scale << ", E = " << irradiance;
        std::printf("[ linearity] box × %g under a %g W/m² sun: max relative difference from linear %.2e\n", scale,
                    irradiance, e);
    }
}
