// Indirect light carried over camera moves (`--cone-carry`, render/cone_carry.hpp). What it must
// do: when only the camera moved, give most pixels the last frame's light without moving the light
// they see; never carry across a change of anything but the camera; and with it off, a moved
// camera's frame is the very frame a fresh renderer makes.
#include <cmath>
#include <cstdio>

#include "cornell_irradiance.hpp"
#include "gl/context.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// `camera` with its eye turned by `angle` radians around the target's vertical axis (the CLI's
// `--camera-path orbit`).
Camera turned(const Camera& camera, double angle) {
    Camera c = camera;
    const glm::dvec3 d = camera.eye - camera.target;
    c.eye = camera.target +
            glm::dvec3(std::cos(angle) * d.x + std::sin(angle) * d.z, d.y, -std::sin(angle) * d.x + std::cos(angle) * d.z);
    return c;
}

// A renderer that drew the scene's camera and then `moved`: its second frame carried light.
void renderMove(Renderer& renderer, const Scene& scene, const Camera& moved) {
    renderer.renderFrame(scene.cameras[0]);
    renderer.renderFrame(moved);
}

// The share of the pixels that see a surface which took the last frame's light.
double carriedShare(const Renderer& renderer, const RenderSettings& s) {
    const ConeStatistics c = renderer.statistics().cones;
    return double(c.carriedPixels) / double(std::uint64_t(s.width) * s.height - c.skyPixels);
}

}  // namespace

// A camera move too small to uncover anything: every pixel finds the light it had, and no block
// traces (this checks where pixel_carry.glsl looks the last frame's points up as much as whether
// it carries).
TEST(ConeCarry, ATinyCameraMoveCarriesEveryCell) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    Renderer renderer(scene, test::cornellIrradianceSettings());
    renderer.renderFrame(scene.cameras[0]);
    EXPECT_EQ(renderer.statistics().cones.carriedPixels, 0u);  // nothing to carry from
    renderer.renderFrame(turned(scene.cameras[0], 1e-4));
    const ConeStatistics c = renderer.statistics().cones;
    std::printf("[ carry ] tiny move: %.2f %% of the pixels carried, %llu traced\n",
                100.0 * carriedShare(renderer, test::cornellIrradianceSettings()), (unsigned long long)c.tracedPixels);
    EXPECT_GE(carriedShare(renderer, test::cornellIrradianceSettings()), 0.99);
    EXPECT_LT(c.tracedPixels, 0.01 * 80 * 60);
}

// Light is carried for a frame or two, then estimated anew (kConeCarryFrames, by a hash of its
// voxel): over a run of tiny moves the second frame carries every pixel, each one after it about
// half (measured 0.49-0.51), never the same light a third time.
TEST(ConeCarry, LightIsCarriedForAFrameOrTwo) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    Renderer renderer(scene, test::cornellIrradianceSettings());
    std::vector<double> shares;
    for (int frame = 0; frame < 5; ++frame) {
        renderer.renderFrame(turned(scene.cameras[0], 1e-4 * frame));
        shares.push_back(carriedShare(renderer, test::cornellIrradianceSettings()));
    }
    std::printf("[ carry ] tiny moves, share carried per frame: %.3f %.3f %.3f %.3f %.3f\n", shares[0], shares[1],
                shares[2], shares[3], shares[4]);
    EXPECT_EQ(shares[0], 0.0);
    EXPECT_GE(shares[1], 0.99);
    for (int frame = 2; frame < 5; ++frame) {
        EXPECT_GT(shares[frame], 0.3) << frame;
        EXPECT_LT(shares[frame], 0.7) << frame;
    }
}

// An interactive move (the CLI's orbit step, 0.05 rad): most pixels carry, and the image holds the
// same light as a fresh renderer's frame of the moved camera, as close to 64 cones as it.
TEST(ConeCarry, ACameraMoveCarriesMostCellsAndKeepsTheLight) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const Camera moved = turned(scene.cameras[0], 0.05);
    Renderer carrying(scene, test::cornellIrradianceSettings());
    renderMove(carrying, scene, moved);
    const ImageF carried = carrying.readHdr();
    const double share = carriedShare(carrying, test::cornellIrradianceSettings());

    Renderer fresh(scene, test::cornellIrradianceSettings());
    fresh.renderFrame(moved);
    const ImageF traced = fresh.readHdr();
    Renderer converging(scene, test::cornellIrradianceSettings(64));
    converging.renderFrame(moved);
    const ImageF converged = converging.readHdr();

    const double carriedError = metrics::rmse(carried, converged), tracedError = metrics::rmse(traced, converged);
    // Against 64 cones, whose noise is an eighth of four cones': each image's mean and cells.
    const metrics::RegionRatios carriedRegions = metrics::regionRatios(carried, converged, 3, 3);
    const metrics::RegionRatios tracedRegions = metrics::regionRatios(traced, converged, 3, 3);
    std::printf("[ carry ] orbit step: %.1f %% of the pixels carried; against 64 cones: RMSE %.4f carried, %.4f traced; "
                "mean %.4f / %.4f; cells %.3f..%.3f / %.3f..%.3f\n",
                100.0 * share, carriedError, tracedError, carriedRegions.meanA / carriedRegions.meanB,
                tracedRegions.meanA / tracedRegions.meanB, carriedRegions.minRatioSignificant.value_or(0.0),
                carriedRegions.maxRatioSignificant.value_or(0.0), tracedRegions.minRatioSignificant.value_or(0.0),
                tracedRegions.maxRatioSignificant.value_or(0.0));
    EXPECT_GT(share, 0.7);
    EXPECT_LT(carriedError, 1.1 * tracedError);
    EXPECT_NEAR(carriedRegions.meanA / carriedRegions.meanB, 1.0, 0.02);
    for (const metrics::RegionCell& cell : carriedRegions.cells)
        if (cell.significant && cell.ratio) EXPECT_NEAR(*cell.ratio, 1.0, 0.06) << cell.column << "," << cell.row;
}

// Lights, materials or any setting changed with the camera: the last frame's traces saw another
// scene, and none is carried.
TEST(ConeCarry, AnythingButTheCameraChangedTracesEveryCell) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    Renderer renderer(scene, test::cornellIrradianceSettings());
    renderer.renderFrame(scene.cameras[0]);
    std::vector<Light> lights = renderer.lights();
    lights[0].color *= 0.5;
    renderer.setLights(lights);
    renderer.renderFrame(turned(scene.cameras[0], 1e-4));
    EXPECT_EQ(renderer.statistics().cones.carriedPixels, 0u);
    RenderSettings s = test::cornellIrradianceSettings();
    s.giFilter *= 0.5f;
    renderer.setSettings(s);
    renderer.renderFrame(turned(scene.cameras[0], 2e-4));
    EXPECT_EQ(renderer.statistics().cones.carriedPixels, 0u);
    renderer.renderFrame(turned(scene.cameras[0], 3e-4));  // only the camera again
    EXPECT_GT(renderer.statistics().cones.carriedPixels, 0u);
}

// Off (0 voxels), a moved camera's frame owes nothing to the last one: the same bits as a fresh
// renderer's.
TEST(ConeCarry, OffIsAFreshFrame) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    RenderSettings s = test::cornellIrradianceSettings();
    s.cones.carryVoxels = 0.0f;
    const Camera moved = turned(scene.cameras[0], 0.05);
    Renderer renderer(scene, s);
    renderMove(renderer, scene, moved);
    EXPECT_EQ(renderer.statistics().cones.carriedPixels, 0u);
    Renderer fresh(scene, s);
    fresh.renderFrame(moved);
    EXPECT_TRUE(renderer.readHdr().rgba == fresh.readHdr().rgba);
}

// At rest the output averages samples; after a camera move its first sample carried light, which
// the second sample's frame traces again, anew: the average has the bits of a fresh renderer's.
TEST(ConeCarry, AtRestTheAverageIsAFreshFramesAverage) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const Camera moved = turned(scene.cameras[0], 0.05);
    Renderer carrying(scene, test::cornellIrradianceSettings());
    renderMove(carrying, scene, moved);
    EXPECT_GT(carrying.statistics().cones.carriedPixels, 0u);
    Renderer fresh(scene, test::cornellIrradianceSettings());
    fresh.renderFrame(moved);
    EXPECT_FALSE(carrying.readHdr().rgba == fresh.readHdr().rgba);
    for (int sample = 1; sample < 4; ++sample) {
        carrying.renderFrame(moved, sample);
        fresh.renderFrame(moved, sample);
    }
    EXPECT_EQ(carrying.samplesInOutput(), 4);
    EXPECT_TRUE(carrying.readHdr().rgba == fresh.readHdr().rgba);
}
