// Cones at half or quarter resolution (--gi-resolution, shaders/cone_upsample.comp): about a
// quarter (a sixteenth) of the pixels traced, and the indirect light the same as at full
// resolution where it matters to a viewer (its mean and its regions); accumulated samples trace
// every pixel in turn, so they close the remaining gap.
#include <cmath>
#include <cstdio>

#include "gl/context.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

RenderSettings indirectSettings(GiResolution resolution, int width, int height) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.voxelLevels = 7;
    s.lightViewResolution = 1024;
    s.display.aov = Aov::Indirect;
    s.giResolution = resolution;
    s.cones.rays = 0;  // the cone set: no noise of narrow cones in what blocks change
    return s;
}

struct IndirectImage {
    ImageF image;
    ConeStatistics cones;
};

// `samples` accumulated, all of the cone set: narrow cones (render/cone_trace.hpp, conesForSample)
// would add their noise to what blocks change.
IndirectImage renderIndirect(const Scene& scene, GiResolution resolution, int samples, int width = 160,
                             int height = 120) {
    RenderSettings settings = indirectSettings(resolution, width, height);
    settings.cones.narrowConesAfterFirstSample = false;
    Renderer renderer(scene, settings);
    for (int sample = 0; sample < samples; ++sample) renderer.renderFrame(scene.cameras[0], sample);
    return {renderer.readHdr(), renderer.statistics().cones};
}

// Cones in blocks against cones at every pixel: the traced share of the pixels in
// (minShare, maxShare) (one pixel of every block that sees a surface, and few pixels that share
// their surface with no traced pixel), the indirect light within 2 % and every significant 3×3
// cell within 7 %.
void expectBlocksKeepTheLight(const char* name, const IndirectImage& blocks, const IndirectImage& full,
                              double minShare, double maxShare) {
    const double tracedShare = double(blocks.cones.tracedPixels) / double(full.cones.tracedPixels);
    std::printf("[ upsample ] %s: traced pixels %llu of %llu (%.4f); cone samples %.4f of full\n", name,
                static_cast<unsigned long long>(blocks.cones.tracedPixels),
                static_cast<unsigned long long>(full.cones.tracedPixels), tracedShare,
                double(blocks.cones.samples) / double(full.cones.samples));
    EXPECT_EQ(blocks.cones.skyPixels, full.cones.skyPixels);
    EXPECT_GT(tracedShare, minShare) << "one pixel of every block that sees a surface";
    EXPECT_LT(tracedShare, maxShare) << "and few pixels that share their surface with no traced pixel";

    const metrics::RegionRatios regions = metrics::regionRatios(blocks.image, full.image, 3, 3);
    const double ratio = regions.meanA / regions.meanB;
    std::printf("[ upsample ] %s: indirect light against full resolution %.4f, cells %.3f..%.3f\n", name, ratio,
                regions.minRatioSignificant.value_or(0.0), regions.maxRatioSignificant.value_or(0.0));
    EXPECT_NEAR(ratio, 1.0, 0.02);
    for (const metrics::RegionCell& cell : regions.cells)
        if (cell.significant && cell.ratio) EXPECT_NEAR(*cell.ratio, 1.0, 0.07) << cell.column << "," << cell.row;
}

}  // namespace

// The largest cell at half resolution, the floor in front of the short box, measured 1.057
// without the edge-aware filter and 1.061 with it (in blocks it filters the traced blocks, at full
// resolution every pixel).
TEST(ConeUpsample, HalfResolutionTracesAQuarterOfThePixelsAndKeepsTheLight) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    expectBlocksKeepTheLight("half", renderIndirect(scene, GiResolution::Half, 1),
                             renderIndirect(scene, GiResolution::Full, 1), 0.25, 0.30);
}

// Quarter resolution is what `auto` chooses from 360 lines up: at 480×360 a Cornell voxel of the
// 128³ grid covers about three pixels, so one traced pixel in 16 still samples every voxel face.
TEST(ConeUpsample, QuarterResolutionTracesASixteenthOfThePixelsAndKeepsTheLight) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const IndirectImage quarter = renderIndirect(scene, GiResolution::Quarter, 1, 480, 360);
    const IndirectImage automatic = renderIndirect(scene, GiResolution::Auto, 1, 480, 360);
    EXPECT_TRUE(automatic.image.rgba == quarter.image.rgba) << "auto traces 4x4 blocks from 360 lines up";
    EXPECT_EQ(giBlockSize(GiResolution::Auto, 640, 359), 2) << "and 2x2 blocks below";
    expectBlocksKeepTheLight("quarter", quarter, renderIndirect(scene, GiResolution::Full, 1, 480, 360), 1.0 / 16.0,
                             0.075);
}

TEST(ConeUpsample, AccumulatedSamplesTraceEveryPixelInTurn) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const double oneSample = metrics::rmse(renderIndirect(scene, GiResolution::Half, 1).image,
                                  renderIndirect(scene, GiResolution::Full, 1).image);
    const double fourSamples = metrics::rmse(renderIndirect(scene, GiResolution::Half, 4).image,
                                    renderIndirect(scene, GiResolution::Full, 4).image);
    std::printf("[ upsample ] RMSE half against full: %.4f with 1 sample, %.4f with 4\n", oneSample, fourSamples);
    EXPECT_LT(fourSamples, 0.8 * oneSample);
}

// The viewer switches the block size of a running renderer: each switch must give the image a
// renderer made with that size gives. At 2 pixels wide 2×2 and 4×4 blocks make traced images of
// the same width (one block), only their heights differ.
TEST(ConeUpsample, SwitchingTheBlockSizeGivesTheImageOfAFreshRenderer) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const IndirectImage freshHalf = renderIndirect(scene, GiResolution::Half, 1, 2, 16);
    const IndirectImage freshQuarter = renderIndirect(scene, GiResolution::Quarter, 1, 2, 16);
    RenderSettings s = indirectSettings(GiResolution::Half, 2, 16);
    Renderer renderer(scene, s);
    renderer.renderFrame(scene.cameras[0]);
    EXPECT_TRUE(renderer.readHdr().rgba == freshHalf.image.rgba);
    s.giResolution = GiResolution::Quarter;
    renderer.setSettings(s);
    renderer.renderFrame(scene.cameras[0]);
    EXPECT_TRUE(renderer.readHdr().rgba == freshQuarter.image.rgba) << "2x2 -> 4x4";
    s.giResolution = GiResolution::Half;
    renderer.setSettings(s);
    renderer.renderFrame(scene.cameras[0]);
    EXPECT_TRUE(renderer.readHdr().rgba == freshHalf.image.rgba) << "4x4 -> 2x2";
}

// Thin poles (6 cm, about two pixels and half a voxel of the 128³ grid) stand before a wall on a
// sunlit floor. In 4×4 blocks the traced pixel of a block lies at the same place in every block,
// which most poles miss, so their pixels trace four cones of their own (about 900 of them), which
// no filter averages; each is then averaged with the pixels around it on its own surface. Their
// light against the same poles at full resolution (every pixel traced, the filter along the
// pole): the mean within 10 %, and the pixel-to-pixel difference (RMSE over the poles' pixels)
// below 0.3 of their mean light (0.24 measured; 0.35 with each pixel keeping its own four cones).
TEST(ConeUpsample, PixelsThatTraceTheirOwnConesAreAveragedOverTheirSurface) {
    auto context = gl::createContext(gl::defaultBackend());
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.6f));
    obj.floor(0.0f, 4.0f);
    obj.box({-4.0f, 0.0f, -1.2f}, {4.0f, 3.0f, -1.0f});  // the wall
    for (int i = -3; i <= 3; ++i) obj.box({0.5f * i - 0.03f, 0.0f, 0.4f}, {0.5f * i + 0.03f, 2.0f, 0.46f});
    Scene scene = loadModelFile(obj.write(test::testDir()));
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.3, -1.0, -0.4));
    sun.irradiance = 5.0;
    scene.lights = {sun};
    Camera camera;
    camera.eye = {0.0, 1.2, 4.0};
    camera.target = {0.0, 1.0, 0.0};
    auto render = [&](GiResolution resolution, Aov aov) {
        RenderSettings s;
        s.width = 160;
        s.height = 120;
        s.voxelLevels = 7;
        s.lightViewResolution = 1024;
        s.display.aov = aov;
        s.giResolution = resolution;
        Renderer renderer(scene, s);
        renderer.renderFrame(camera);
        return IndirectImage{renderer.readHdr(), renderer.statistics().cones};
    };
    const ImageF depth = render(GiResolution::Full, Aov::Depth).image, normal = render(GiResolution::Full, Aov::Normal).image;
    const IndirectImage blocks = render(GiResolution::Quarter, Aov::Indirect);
    const ImageF& half = blocks.image;
    const ImageF full = render(GiResolution::Full, Aov::Indirect).image;
    // The poles' front faces: nearer than the wall, facing the camera (+z).
    double sumHalf = 0.0, sumFull = 0.0, squaredDifference = 0.0;
    int poles = 0;
    for (int y = 0; y < half.height; ++y)
        for (int x = 0; x < half.width; ++x) {
            const float d = depth.at(x, y)[0];
            if (!(d > 3.3f && d < 3.8f) || normal.at(x, y)[2] < 0.9f) continue;
            const double h = half.at(x, y)[1], f = full.at(x, y)[1];
            sumHalf += h;
            sumFull += f;
            squaredDifference += (h - f) * (h - f);
            ++poles;
        }
    ASSERT_GT(poles, 100);
    const double meanHalf = sumHalf / poles, meanFull = sumFull / poles;
    const double relativeRmse = std::sqrt(squaredDifference / poles) / meanFull;
    std::printf("[ upsample ] thin poles, %d pixels: blocks / full %.3f, RMSE blocks against full %.3f of the mean; "
                "pixels traced in blocks %llu\n", poles, meanHalf / meanFull, relativeRmse,
                static_cast<unsigned long long>(blocks.cones.tracedPixels));
    EXPECT_NEAR(meanHalf / meanFull, 1.0, 0.1);
    EXPECT_LT(relativeRmse, 0.3);
}
