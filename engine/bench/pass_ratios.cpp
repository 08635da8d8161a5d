#include "bench/pass_ratios.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace vct::bench {
namespace {

// With every pass finished before the next begins, the CPU time is the pass's wall time.
double passMs(const gl::FrameTimings& timings, const std::string& name) {
    for (const gl::PassTiming& t : timings.passes)
        if (t.name == name) return t.cpuMs;
    fail("pass ", name, " ran in one full frame and not in the next (engine bug)");
}

}  // namespace

PassRatios measurePassRatios(Renderer& renderer, const Camera& camera, PerfCalibration& calibration, int repeats) {
    if (repeats < 1) fail("measurePassRatios: repeats must be at least 1");
    if (!renderer.settings().fullFrames) fail("measurePassRatios needs full frames (engine bug)");
    renderer.timer().setFinishEachPass(true);
    renderer.renderFrame(camera);
    renderer.timer().waitForLatest();
    calibration.run(WorkKind::Compute);
    calibration.run(WorkKind::Raster);

    PassRatios result;
    for (int r = 0; r < repeats; ++r) {
        const double compute = calibration.run(WorkKind::Compute);
        const double raster = calibration.run(WorkKind::Raster);
        renderer.renderFrame(camera);
        const auto timings = renderer.timer().waitForLatest();
        if (!timings) fail("the GPU timer returned no frame (engine bug)");
        if (r == 0) {
            result.computeCalibrationMs = compute;
            result.rasterCalibrationMs = raster;
            for (const PassRun& run : renderer.lastFrame())
                if (run.ran) result.passes.push_back({run.name, passWorkKind(run.pass), passMs(*timings, run.name)});
            continue;
        }
        result.computeCalibrationMs = std::min(result.computeCalibrationMs, compute);
        result.rasterCalibrationMs = std::min(result.rasterCalibrationMs, raster);
        for (PassRatio& p : result.passes) {
            p.ms = std::min(p.ms, passMs(*timings, p.name));
        }
    }
    renderer.timer().setFinishEachPass(false);
    for (PassRatio& p : result.passes)
        p.ratio = p.ms / (p.kind == WorkKind::Raster ? result.rasterCalibrationMs : result.computeCalibrationMs);
    return result;
}

}  // namespace vct::bench
