#pragma once
// The benchmark's outputs: CSV (one row per engine point and per path-tracer spp), a markdown
// report, and a gnuplot chart of error against time (log–log) with the engine points labelled,
// the path tracer's curve and the engine's Pareto front. Also the two derived numbers: the Pareto
// front and the equal-error time of the path tracer.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_run.hpp"

namespace vct::bench {

// The quality a front or an equal-quality time is taken for: RMSE of the full image or of the
// indirect part (lower is better), SSIM of the displayed full image (higher is better; handled as
// the dissimilarity 1 − SSIM).
enum class Quality { Rmse, IndirectRmse, Ssim };
const char* qualityName(Quality quality);
double qualityValue(const BenchRow& row, Quality quality);  // as reported (SSIM itself, not 1 − SSIM)

// Marks BenchRow::pareto on the engine rows: a point is on the front when no other engine point
// is at least as fast and at least as good (full-image RMSE) and better in one of them.
// paretoFront returns the flags for any quality without storing them.
std::vector<bool> paretoFront(const std::vector<BenchRow>& rows, Quality quality);
void markPareto(std::vector<BenchRow>& rows);

// The time the path tracer needs to reach `value` of `quality`, read off its curve (the
// path-tracer rows) by linear interpolation of log time against log error (RMSE, or 1 − SSIM)
// between the two spp values around it. Outside the curve: for RMSE extrapolated with error ∝
// 1/√spp, i.e. time ∝ 1/RMSE², from its nearest end, and flagged; for SSIM not valid.
struct EqualErrorTime {
    double ms = 0.0;
    bool valid = false;         // false without a path-tracer curve (or SSIM outside it)
    bool extrapolated = false;
    std::string how;            // "between 4 and 8 spp", "below 1 spp (extrapolated)", …
};
EqualErrorTime pathTracerTimeAt(const std::vector<BenchRow>& rows, double value, Quality quality);

// The engine point whose static-geometry frame is the most times faster than the path tracer at
// the point's own error (`quality`): the sweep's best setting in the equal-error sense, where the
// default point is only one of them. `row` is null without a path-tracer curve.
struct EqualErrorSpeedup {
    const BenchRow* row = nullptr;
    EqualErrorTime time;
    double speedup = 0.0;  // path tracer ms / the point's static-geometry ms
};
EqualErrorSpeedup bestEqualErrorSpeedup(const std::vector<BenchRow>& rows, Quality quality);

struct BenchSummary {
    std::string name, scene, camera, command, date, renderer, backend, cpu;
    std::string commit;  // `git describe --always --dirty` of the source tree (shaders are read from it)
    std::string shaderDir;  // VCT_SHADER_DIR when set (shaders not from the source tree)
    std::string note;       // --note
    int width = 0, height = 0, repeats = 0, pathTracerThreads = 0;
    double exposureEV = 0.0;
    std::string tonemap;
    int referenceSpp = 0, referenceBounces = 0;
    std::uint64_t referenceSeed = 0, curveSeed = 0;
    double referenceSeconds = 0.0, referenceDirectSeconds = 0.0, referenceNoiseRmse = 0.0;
    bool referenceFromCache = false;
    std::string referenceKey;
    std::string defaultSettings;  // "voxel_levels=8, cones=5, …"
    std::string loadBefore, loadAfter;  // /proc/loadavg (1, 5, 15 min) at the start and the end
};

// The default point's settings as "name=value, …" over every sweep parameter.
std::string describeSettings(const PointSettings& settings);

void writeCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows);
void writeMarkdown(const std::filesystem::path& path, const std::vector<BenchRow>& rows, const BenchSummary& summary,
                   const std::string& chartFile);
// Writes the gnuplot script `script` (self-contained: the data is inline) drawing `png`, then runs
// gnuplot on it when it is installed. Returns an empty string when the chart was drawn, else a
// message saying why not and how to draw it.
std::string writeChart(const std::filesystem::path& script, const std::filesystem::path& png,
                       const std::vector<BenchRow>& rows, const BenchSummary& summary);

}  // namespace vct::bench
