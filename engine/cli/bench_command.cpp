// `vct bench`: run time against error (DESIGN §5.7). Sweeps engine settings one at a time around a
// default (benchmarks/sweeps/*.json), measures each point's warm frame time and its error against a
// cached path-traced reference, runs the path tracer's own error-against-time curve, and writes
// bench_<name>.csv, .md, .gp and .png into the results folder. The work is in engine/bench/.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <ctime>
#include <fstream>
#include <thread>

#include "bench/bench_report.hpp"
#include "bench/bench_run.hpp"
#include "bench/reference_cache.hpp"
#include "bench/sweep.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/tonemap.hpp"
#include "gl/context.hpp"
#include "scene/scene_loader.hpp"

namespace vct::cli {
namespace {

struct BenchOptions {
    std::string sweep;
    bool quick = false;
    std::string out;
    std::string cache;
    std::string backend = gl::defaultBackendName();
    int threads = 0;
    int repeats = 0;  // 0 = the sweep's
    bool refreshReference = false;
    std::string note;
};

const std::filesystem::path kSourceDir = VCT_SOURCE_DIR;

std::string today() {
    const std::time_t now = std::time(nullptr);
    char text[16];
    std::strftime(text, sizeof text, "%Y-%m-%d", std::localtime(&now));
    return text;
}

std::string cpuDescription() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, model = "unknown CPU";
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    return concat(model, ", ", std::thread::hardware_concurrency(), " hardware threads");
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "";
    return one + ", " + five + ", " + fifteen;
}

// The source tree's commit: the shaders are read from it at run time, so it identifies what ran.
std::string sourceCommit() {
    const std::string command = "git -C '" + kSourceDir.string() + "' describe --always --dirty 2>/dev/null";
    std::string text;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[128];
        while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
        if (pclose(pipe) != 0) return "";
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

// The path as the command line should show it: relative to the repository when inside it.
std::string displayPath(const std::filesystem::path& p) {
    std::error_code ec;
    const auto relative = std::filesystem::relative(std::filesystem::absolute(p), kSourceDir, ec);
    if (!ec && !relative.empty() && relative.native().rfind("..", 0) != 0) return relative.string();
    return p.string();
}

void run(const BenchOptions& o) {
    if (o.quick && !o.sweep.empty()) fail("give either a sweep file or --quick, not both");
    const std::filesystem::path sweepFile =
        o.quick ? kSourceDir / "benchmarks" / "sweeps" / "quick.json"
                : (o.sweep.empty() ? kSourceDir / "benchmarks" / "sweeps" / "cornell.json" : std::filesystem::path(o.sweep));
    bench::SweepDefinition sweep = bench::loadSweep(sweepFile);
    if (o.repeats < 0 || o.repeats > 100) fail("--repeats ", o.repeats, " is out of range; use 1..100 (0 = the sweep's)");
    if (o.repeats > 0) sweep.repeats = o.repeats;
    if (o.threads < 0 || o.threads > 1024) fail("--threads ", o.threads, " is out of range; use 0 (all cores)..1024");
    const std::filesystem::path outDir = o.out.empty() ? kSourceDir / "benchmarks" / "results" : std::filesystem::path(o.out);
    const std::filesystem::path cacheDir =
        o.cache.empty() ? kSourceDir / "benchmarks" / "cache" : std::filesystem::path(o.cache);
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (!std::filesystem::is_directory(outDir))
        fail("cannot create the results folder '", outDir.string(), "'; check --out");
    const std::filesystem::path csvPath = outDir / ("bench_" + sweep.name + ".csv");
    const std::filesystem::path mdPath = outDir / ("bench_" + sweep.name + ".md");
    const std::filesystem::path gpPath = outDir / ("bench_" + sweep.name + ".gp");
    const std::filesystem::path pngPath = outDir / ("bench_" + sweep.name + ".png");
    for (const auto& p : {csvPath, mdPath, gpPath, pngPath}) ensureWritable(p);
    const auto backend = gl::parseBackend(o.backend);
    const TonemapCurve curve = parseTonemapCurve(sweep.tonemap);
    const auto started = std::chrono::steady_clock::now();
    const std::string loadBefore = loadAverage();

    const Scene scene = loadScene(bench::resolveScenePath(sweep));
    Camera camera = scene.cameras.front();
    bool presetFound = false;
    for (const auto& c : scene.cameras) presetFound = presetFound || c.name == sweep.camera;
    if (presetFound || (sweep.camera != "default" && !sweep.camera.empty())) camera = scene.camera(sweep.camera);
    if (sweep.view.any()) {
        try {
            camera = changedCamera(camera, sweep.view);
        } catch (const Error& e) {
            fail("the camera of ", sweepFile.string(), ": ", e.what());
        }
        camera.name = concat("eye (", camera.eye.x, ", ", camera.eye.y, ", ", camera.eye.z, ") to (", camera.target.x,
                             ", ", camera.target.y, ", ", camera.target.z, ")");
    }
    const double exposure = sweep.exposureEV.value_or(scene.exposureEV);
    const metrics::DisplaySettings display{exposure, curve};

    // Every point's complete settings, checked on the context before the expensive steps.
    auto context = gl::createContext(backend);
    std::vector<bench::SweepPoint> points = bench::expandSweep(sweep);
    for (auto& p : points) {
        p.settings.width = sweep.width;
        p.settings.height = sweep.height;
        p.settings.display.exposureEV = exposure;
        p.settings.display.toneCurve = parseToneCurve(sweep.tonemap);
        p.settings.display.giScale = 1.0f;
        try {
            validateRenderSettingsForContext(p.settings);
        } catch (const Error& e) {
            fail("point ", p.label, " of ", sweepFile.string(), ": ", e.what());
        }
    }
    const bool info = logLevel() >= LogLevel::Info;
    if (info)
        std::printf("bench %s: %s %dx%d, %zu engine points, path tracer at %zu spp values, reference %d spp, "
                    "%d bounce(s)\n",
                    sweep.name.c_str(), scene.name.c_str(), sweep.width, sweep.height, points.size(),
                    sweep.curveSpp.size(), sweep.referenceSpp, sweep.referenceBounces);

    reference::ReferenceSettings refSettings;
    refSettings.width = sweep.width;
    refSettings.height = sweep.height;
    refSettings.samplesPerPixel = sweep.referenceSpp;
    refSettings.bounces = sweep.referenceBounces;
    refSettings.seed = sweep.referenceSeed;
    refSettings.threads = o.threads;
    refSettings.progress = info;
    const bench::ReferenceImages ref =
        bench::loadOrRenderReference(scene, camera, refSettings, cacheDir, !o.refreshReference);
    if (info) std::fflush(stdout);

    auto report = [&](const bench::BenchRow& r, std::size_t i, std::size_t n) {
        if (!info) return;
        std::printf("  [%zu/%zu] %-10s %-22s %9.1f ms  RMSE %.4g  indirect RMSE %.4g (x%.3f)\n", i + 1, n,
                    r.kind.c_str(), r.label.c_str(), r.frameMs, r.error.rmse, r.error.indirectRmse,
                    r.error.indirectRatio);
        std::fflush(stdout);
    };
    std::vector<bench::BenchRow> rows =
        bench::runPathTracerCurve(scene, camera, sweep, ref, display, o.threads, report);
    // A point with another bounce count than the sweep's reference is measured against a reference
    // with its own count (cached like the first).
    std::map<int, bench::ReferenceImages> otherBounces;
    auto referenceFor = [&](int bounces) -> const bench::ReferenceImages& {
        if (bounces == sweep.referenceBounces) return ref;
        auto found = otherBounces.find(bounces);
        if (found == otherBounces.end()) {
            reference::ReferenceSettings s = refSettings;
            s.bounces = bounces;
            found = otherBounces.emplace(bounces, bench::loadOrRenderReference(scene, camera, s, cacheDir,
                                                                               !o.refreshReference))
                        .first;
        }
        return found->second;
    };
    std::vector<bench::BenchRow> engineRows =
        bench::runEnginePoints(scene, camera, points, sweep.repeats, referenceFor, display, report);
    rows.insert(rows.begin(), engineRows.begin(), engineRows.end());
    bench::markPareto(rows);

    bench::BenchSummary summary;
    summary.name = sweep.name;
    summary.scene = scene.name;
    summary.camera = camera.name.empty() ? sweep.camera : camera.name;
    summary.command = "vct bench " + (o.quick ? std::string("--quick") : displayPath(sweepFile));
    summary.date = today();
    summary.renderer = context->info().renderer;
    summary.backend = context->info().backend;
    summary.cpu = cpuDescription();
    summary.width = sweep.width;
    summary.height = sweep.height;
    summary.repeats = sweep.repeats;
    summary.pathTracerThreads = ref.threads > 0 ? ref.threads
                                                : (o.threads > 0 ? o.threads : int(std::thread::hardware_concurrency()));
    summary.exposureEV = exposure;
    summary.tonemap = sweep.tonemap;
    summary.referenceSpp = ref.spp;
    summary.referenceBounces = ref.bounces;
    summary.referenceSeed = ref.seed;
    summary.curveSeed = sweep.curveSeed;
    summary.referenceSeconds = ref.seconds;
    summary.referenceDirectSeconds = ref.directSeconds;
    summary.referenceNoiseRmse = std::sqrt(std::max(0.0, ref.meanVariance));
    summary.referenceFromCache = ref.fromCache;
    summary.referenceKey = ref.key;
    summary.defaultSettings = bench::describeSettings(points.front().settings);
    summary.loadBefore = loadBefore;
    summary.commit = sourceCommit();
    if (const char* dir = std::getenv("VCT_SHADER_DIR"); dir && *dir) summary.shaderDir = dir;
    summary.note = o.note;
    summary.loadAfter = loadAverage();

    bench::writeCsv(csvPath, rows);
    const std::string chartProblem = bench::writeChart(gpPath, pngPath, rows, summary);
    bench::writeMarkdown(mdPath, rows, summary, chartProblem.empty() ? pngPath.filename().string() : "");

    if (info) {
        for (const auto& r : rows) {
            if (r.kind != "engine" || !r.isDefault) continue;
            std::printf("default point: RMSE %.4g, relMSE %.4g, PSNR %.2f dB, SSIM %.4f; indirect RMSE %.4g, relMSE "
                        "%.4g (mean x%.3f of the reference); frame %.1f ms (static geometry %.1f ms)\n",
                        r.error.rmse, r.error.relMse, r.error.psnr, r.error.ssim, r.error.indirectRmse,
                        r.error.indirectRelMse, r.error.indirectRatio, r.frameMs, r.frameStaticMs);
            for (bench::Quality q : {bench::Quality::Rmse, bench::Quality::IndirectRmse, bench::Quality::Ssim}) {
                const bench::EqualErrorTime t = bench::pathTracerTimeAt(rows, bench::qualityValue(r, q), q);
                if (t.valid)
                    std::printf("equal %s: path tracer %.1f ms (%s) = %.3gx the engine frame, %.3gx its "
                                "static-geometry frame\n",
                                bench::qualityName(q), t.ms, t.how.c_str(), t.ms / r.frameMs, t.ms / r.frameStaticMs);
                else
                    std::printf("equal %s: %s\n", bench::qualityName(q), t.how.c_str());
            }
        }
        std::printf("Pareto front:");
        for (const auto& r : rows)
            if (r.pareto) std::printf(" %s", r.label.c_str());
        std::printf("\n");
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        std::printf("wrote %s, %s%s (%.0f s)\n", csvPath.string().c_str(), mdPath.string().c_str(),
                    chartProblem.empty() ? (", " + pngPath.string()).c_str() : "", seconds);
        std::fflush(stdout);
    }
    if (!chartProblem.empty()) logWarn(chartProblem);
}

}  // namespace

Run addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    BenchOptions& o = *options;
    CLI::App* command = app.add_subcommand(
        "bench", "run time against error: sweep engine settings, compare with a cached path-traced reference and "
                 "the path tracer's own curve; CSV, markdown and chart");
    command->add_option("SWEEP", o.sweep,
                        "sweep definition (JSON; default benchmarks/sweeps/cornell.json; format in "
                        "engine/bench/sweep.hpp)");
    command->add_flag("--quick", o.quick, "the small Cornell sweep benchmarks/sweeps/quick.json (seconds)");
    command->add_option("--out", o.out, "results folder (default <repo>/benchmarks/results)");
    command->add_option("--cache", o.cache, "reference cache folder (default <repo>/benchmarks/cache)");
    command->add_flag("--refresh-reference", o.refreshReference, "render the reference even when it is cached");
    command->add_option("--threads", o.threads, "path-tracer threads (0 = all cores)")->capture_default_str();
    command->add_option("--repeats", o.repeats, "warm full frames timed per point (0 = the sweep's)")
        ->capture_default_str();
    command->add_option("--backend", o.backend, "osmesa, egl or glfw")->capture_default_str();
    command->add_option("--note", o.note, "a sentence for the markdown report (e.g. how the run differs from the commit)");
    return [options] { run(*options); };
}

}  // namespace vct::cli
