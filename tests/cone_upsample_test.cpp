// Cones at half or quarter resolution (--gi-resolution, shaders/cone_upsample.comp): about a
// quarter (a sixteenth) of the pixels traced, and the indirect light the same as at full
// resolution where it matters to a viewer (its mean and its regions); accumulated samples trace
// every pixel in turn, so they close the remaining gap.
#include <cstdio>

#include "gl/context.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene_loader.hpp"
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
