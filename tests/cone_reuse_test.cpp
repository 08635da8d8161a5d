// Narrow cones shared between neighbouring traced pixels (`--cone-reuse`, shaders/cone_reuse.comp).
// What it must do: lower the noise of four cones per pixel without moving the light they estimate
// (it weighs each cone by the density with which the whole window drew its direction, which makes
// it as unbiased as a pixel's own cones wherever neighbours see the same light), and take no light
// across a surface.
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

// Cornell's irradiance (AOV indirect) at 160×120 in 2×2 blocks, 128³, without the edge-aware
// filter, so that what the cones gathered is what is measured.
ImageF cornellIrradiance(const Scene& scene, int rays, float reuseVoxels) {
    RenderSettings s = test::cornellIrradianceSettings(rays);
    s.giFilter = 0.0f;
    s.cones.reuseVoxels = reuseVoxels;
    Renderer renderer(scene, s);
    renderer.renderFrame(scene.cameras[0]);
    return renderer.readHdr();
}

}  // namespace

// Against the same engine with 64 cones per pixel (its noise a quarter of four cones'), so that
// only noise is measured, not the voxels' bias (measured: RMSE 0.184 → 0.085, the mean within
// 0.2 %).
TEST(ConeReuse, SharedConesLowerTheNoiseAndKeepTheLight) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    const ImageF converged = cornellIrradiance(scene, 64, 0.0f);
    const ImageF own = cornellIrradiance(scene, 4, 0.0f);
    const ImageF shared = cornellIrradiance(scene, 4, kDefaultConeReuseVoxels);
    const double ownError = metrics::rmse(own, converged), sharedError = metrics::rmse(shared, converged);
    const metrics::RegionRatios ownRegions = metrics::regionRatios(own, converged, 3, 3);
    const metrics::RegionRatios sharedRegions = metrics::regionRatios(shared, converged, 3, 3);
    const double ownMean = ownRegions.meanA / ownRegions.meanB, sharedMean = sharedRegions.meanA / sharedRegions.meanB;
    std::printf("[ reuse ] Cornell irradiance against 64 cones: RMSE %.4f own cones, %.4f shared; mean %.4f / %.4f; "
                "cells %.3f..%.3f / %.3f..%.3f\n",
                ownError, sharedError, ownMean, sharedMean, ownRegions.minRatioSignificant.value_or(0.0),
                ownRegions.maxRatioSignificant.value_or(0.0), sharedRegions.minRatioSignificant.value_or(0.0),
                sharedRegions.maxRatioSignificant.value_or(0.0));
    EXPECT_LT(sharedError, 0.75 * ownError);
    EXPECT_NEAR(sharedMean, 1.0, 0.02);
    for (const metrics::RegionCell& cell : sharedRegions.cells)
        if (cell.significant && cell.ratio) EXPECT_NEAR(*cell.ratio, 1.0, 0.06) << cell.column << "," << cell.row;
}

// σ 0 is each pixel's own cones: the same bits as before the pass existed, and as the cone set
// ignores it (it has no per-pixel directions to share).
TEST(ConeReuse, OffIsEachPixelsOwnCones) {
    auto context = gl::createContext(gl::defaultBackend());
    const Scene scene = makeCornellBox();
    EXPECT_TRUE(cornellIrradiance(scene, 0, 0.0f).rgba == cornellIrradiance(scene, 0, kDefaultConeReuseVoxels).rgba);
    EXPECT_FALSE(cornellIrradiance(scene, 4, 0.0f).rgba == cornellIrradiance(scene, 4, kDefaultConeReuseVoxels).rgba);
}
