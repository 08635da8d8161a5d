#pragma once
// What each pass of a full frame costs relative to a calibration workload of its kind
// (bench/perf_calibration.hpp), measured in one run: the numbers the performance guard
// (tests/perf_guard_test.cpp) records and later compares with.
//
// Protocol, on a Renderer whose settings have fullFrames set (every pass every frame):
//   - passes end with glFinish (GpuTimer::setFinishEachPass), so a pass's wall time is its whole
//     cost and none of it spills into the next pass (docs/timings.md);
//   - one warm-up frame and one run of each calibration (shader compilation, first allocations,
//     the driver's JIT);
//   - `repeats` rounds of: the compute calibration, the raster calibration, one full frame;
//   - each pass's time and each calibration's time is the fastest of its rounds: on a shared
//     machine noise only ever adds time, so the minimum is the best estimate of the work itself,
//     and interleaving puts calibrations and passes under the same conditions.
#include <string>
#include <vector>

#include "bench/perf_calibration.hpp"
#include "pipeline/renderer.hpp"

namespace vct::bench {

struct PassRatio {
    std::string name;
    WorkKind kind = WorkKind::Compute;
    double ms = 0.0;     // fastest wall time of the pass
    double ratio = 0.0;  // ms / the fastest calibration of its kind
};

struct PassRatios {
    double computeCalibrationMs = 0.0, rasterCalibrationMs = 0.0;
    std::vector<PassRatio> passes;  // in frame order, the passes that ran
};

PassRatios measurePassRatios(Renderer& renderer, const Camera& camera, PerfCalibration& calibration, int repeats);

}  // namespace vct::bench
