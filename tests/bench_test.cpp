// `vct bench` (run time against error): the sweep definition, the Pareto front and the
// equal-error interpolation in process, and `vct bench --quick` end to end through the real binary.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "bench/bench_report.hpp"
#include "bench/sweep.hpp"
#include "core/error.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

using Json = nlohmann::ordered_json;

struct Csv {
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows;

    const std::map<std::string, std::string>* find(const std::string& kind, const std::string& label) const {
        for (const auto& r : rows)
            if (r.at("kind") == kind && r.at("label") == label) return &r;
        return nullptr;
    }
};

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    return cells;
}

Csv readCsv(const std::filesystem::path& path) {
    Csv csv;
    std::ifstream in(path);
    std::string line;
    if (!std::getline(in, line)) return csv;
    csv.header = split(line);
    while (std::getline(in, line)) {
        const auto cells = split(line);
        EXPECT_EQ(cells.size(), csv.header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < csv.header.size() && i < cells.size(); ++i) row[csv.header[i]] = cells[i];
        csv.rows.push_back(row);
    }
    return csv;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
    const std::string& text = row.at(column);
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    EXPECT_TRUE(!text.empty() && end && *end == '\0') << column << " = '" << text << "'";
    return v;
}

bench::BenchRow row(const std::string& kind, double ms, double rmse, int spp = 0) {
    bench::BenchRow r;
    r.kind = kind;
    r.frameMs = ms;
    r.error.rmse = rmse;
    r.error.indirectRmse = rmse;
    r.spp = spp;
    r.label = kind + std::to_string(ms);
    return r;
}

bool gnuplotInstalled() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

}  // namespace

TEST(Bench, SweepExpandsOneParameterAtATime) {
    const Json j = Json::parse(R"({"scene": "cornell", "width": 32, "height": 24,
        "default": {"voxel_levels": 6, "cones": 5},
        "sweep": {"voxel_levels": [5, 6, 7], "cones": [1, 16], "bricks": [false], "bounces": [2], "samples": [1, 8], "gi_resolution": ["full"]}})");
    const bench::SweepDefinition sweep = bench::parseSweep(j, "t");
    const auto points = bench::expandSweep(sweep);
    std::vector<std::string> labels;
    for (const auto& p : points) labels.push_back(p.label);
    // voxel_levels 6 is the default: not repeated.
    EXPECT_EQ(labels, (std::vector<std::string>{"default", "voxel_levels=5", "voxel_levels=7", "cones=1", "cones=16",
                                                "bricks=false", "bounces=2", "samples=8", "gi_resolution=full"}));
    EXPECT_TRUE(points[0].isDefault);
    EXPECT_EQ(points[0].settings.voxelLevels, 6);
    EXPECT_EQ(points[2].settings.voxelLevels, 7);
    EXPECT_EQ(points[2].settings.cones.cones, 5) << "the other parameters stay at the default";
    EXPECT_EQ(points[4].settings.cones.cones, 16);
    EXPECT_EQ(points[4].settings.voxelLevels, 6);
    EXPECT_FALSE(points[5].settings.bricks);
    EXPECT_EQ(points[6].settings.bounces, 2);
    EXPECT_EQ(points[5].settings.bounces, 1);
    EXPECT_EQ(points[7].settings.pixelSamples, 8);
    EXPECT_EQ(points[6].settings.pixelSamples, 1);
    EXPECT_EQ(points[8].settings.giResolution, GiResolution::Full);
    EXPECT_EQ(points[0].settings.giResolution, GiResolution::Auto) << "the engine's default";
    EXPECT_EQ(sweep.curveSeed, sweep.referenceSeed + 1) << "the curve's samples are independent of the reference's";
}

TEST(Bench, SweepTakesAViewOfItsOwn) {
    const bench::SweepDefinition preset = bench::parseSweep(Json::parse(R"({"camera": "CameraMain"})"), "t");
    EXPECT_EQ(preset.camera, "CameraMain");
    EXPECT_FALSE(preset.view.any());
    const bench::SweepDefinition own = bench::parseSweep(
        Json::parse(R"({"camera": {"preset": "CameraMain", "eye": [0, 4.5, 0], "target": [20, 6, 3], "fov": 50}})"), "t");
    EXPECT_EQ(own.camera, "CameraMain");
    ASSERT_TRUE(own.view.eye && own.view.target && own.view.fovYDeg);
    EXPECT_EQ(*own.view.eye, glm::dvec3(0.0, 4.5, 0.0));
    EXPECT_EQ(*own.view.target, glm::dvec3(20.0, 6.0, 3.0));
    EXPECT_EQ(*own.view.fovYDeg, 50.0);
    EXPECT_FALSE(own.view.up) << "unset keys keep the preset's";
}

TEST(Bench, SweepRejectsTyposAndBadValues) {
    auto message = [](const char* text) {
        try {
            bench::parseSweep(Json::parse(text), "t");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(message(R"({"sweeps": {}})").find("unknown key 'sweeps'"), std::string::npos);
    EXPECT_NE(message(R"({"camera": {"eye": [1, 2]}})").find("three numbers"), std::string::npos);
    EXPECT_NE(message(R"({"camera": {"position": [1, 2, 3]}})").find("unknown key 'position'"), std::string::npos);
    EXPECT_NE(message(R"({"camera": 3})").find("preset name or an object"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"cone": [1]}})").find("unknown parameter 'cone'"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"cones": [7]}})").find("not a cone set"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"voxel_levels": [11]}})").find("out of range"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"bounces": [9]}})").find("out of range"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"samples": [0]}})").find("out of range"), std::string::npos);
    EXPECT_NE(message(R"({"sweep": {"gi_resolution": ["third"]}})").find("\"full\" or \"half\""), std::string::npos);
    EXPECT_NE(message(R"({"default": {"bricks": 1}})").find("true or false"), std::string::npos);
    EXPECT_NE(message(R"({"pathtracer_curve": {"spp": [4, 2]}})").find("must increase"), std::string::npos);
    EXPECT_NE(message(R"({"reference": {"seed": 3}, "pathtracer_curve": {"seed": 3}})").find("must differ"),
              std::string::npos);
}

TEST(Bench, ParetoFrontAndEqualErrorTime) {
    std::vector<bench::BenchRow> rows = {row("engine", 10, 0.5), row("engine", 20, 0.2), row("engine", 30, 0.3),
                                         row("engine", 40, 0.1), row("engine", 40, 0.15),
                                         row("pathtracer", 1, 0.4, 1), row("pathtracer", 4, 0.2, 4),
                                         row("pathtracer", 16, 0.1, 16)};
    bench::markPareto(rows);
    EXPECT_TRUE(rows[0].pareto);
    EXPECT_TRUE(rows[1].pareto);
    EXPECT_FALSE(rows[2].pareto) << "slower and worse than the 20 ms point";
    EXPECT_TRUE(rows[3].pareto);
    EXPECT_FALSE(rows[4].pareto) << "as fast as the 40 ms point and worse";
    EXPECT_FALSE(rows[5].pareto) << "path-tracer rows are not part of the engine's front";

    // On the curve: exact at a point, log–log interpolation between points.
    auto t = bench::pathTracerTimeAt(rows, 0.2, bench::Quality::Rmse);
    EXPECT_TRUE(t.valid);
    EXPECT_FALSE(t.extrapolated);
    EXPECT_NEAR(t.ms, 4.0, 1e-9);
    t = bench::pathTracerTimeAt(rows, std::sqrt(0.2 * 0.1), bench::Quality::Rmse);
    EXPECT_NEAR(t.ms, 8.0, 1e-9);
    // Beyond its ends: time ∝ 1/RMSE², flagged.
    t = bench::pathTracerTimeAt(rows, 0.8, bench::Quality::Rmse);
    EXPECT_TRUE(t.extrapolated);
    EXPECT_NEAR(t.ms, 0.25, 1e-9);
    t = bench::pathTracerTimeAt(rows, 0.05, bench::Quality::Rmse);
    EXPECT_TRUE(t.extrapolated);
    EXPECT_NEAR(t.ms, 64.0, 1e-9);
    // SSIM (higher is better) is read off as 1 − SSIM and never extrapolated.
    for (auto& r : rows) r.error.ssim = 1.0 - r.error.rmse;
    t = bench::pathTracerTimeAt(rows, 0.8, bench::Quality::Ssim);
    EXPECT_TRUE(t.valid);
    EXPECT_NEAR(t.ms, 4.0, 1e-9);
    EXPECT_FALSE(bench::pathTracerTimeAt(rows, 0.99, bench::Quality::Ssim).valid);
    const std::vector<bool> bySsim = bench::paretoFront(rows, bench::Quality::Ssim);
    for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(bySsim[i], rows[i].pareto) << i;
}

TEST(Bench, BestEqualErrorSpeedupIsTheFastestPointAgainstThePathTracerAtItsOwnError) {
    // Path tracer: 1 ms at RMSE 0.4, 4 ms at 0.2, 16 ms at 0.1 (time ∝ 1/RMSE²).
    std::vector<bench::BenchRow> rows = {row("engine", 10, 0.4), row("engine", 20, 0.1), row("engine", 30, 0.2),
                                         row("pathtracer", 1, 0.4, 1), row("pathtracer", 4, 0.2, 4),
                                         row("pathtracer", 16, 0.1, 16)};
    rows[0].frameStaticMs = 2.0;   // the path tracer needs 1 ms at its error: 0.5×
    rows[1].frameStaticMs = 4.0;   // 16 ms: 4×, the best
    rows[2].frameStaticMs = 2.0;   // 4 ms: 2×
    const bench::EqualErrorSpeedup best = bench::bestEqualErrorSpeedup(rows, bench::Quality::Rmse);
    ASSERT_NE(best.row, nullptr);
    EXPECT_EQ(best.row, &rows[1]);
    EXPECT_NEAR(best.time.ms, 16.0, 1e-9);
    EXPECT_NEAR(best.speedup, 4.0, 1e-9);
    // Without a path-tracer curve there is no best point.
    rows.resize(3);
    EXPECT_EQ(bench::bestEqualErrorSpeedup(rows, bench::Quality::Rmse).row, nullptr);
}

// The whole benchmark on tiny images: rows, finite numbers, chart, the reference cache, and the
// default setting beating an obviously bad one.
TEST(Bench, QuickRunWritesRowsChartAndUsesTheCache) {
    const auto dir = test::testDir();
    const std::string args = "bench --quick --cache " + (dir / "cache").string();
    const auto first = test::runVct(args + " --out " + (dir / "results").string());
    ASSERT_EQ(first.exitCode, 0) << first.output;

    const Csv csv = readCsv(dir / "results" / "bench_quick.csv");
    ASSERT_EQ(csv.rows.size(), 7u) << "4 engine points and 3 path-tracer spp values";
    for (const auto& [kind, label] : std::vector<std::pair<std::string, std::string>>{
             {"engine", "default"}, {"engine", "cone_rays=1"}, {"engine", "gi=false"}, {"engine", "samples=4"},
             {"pathtracer", "1 spp"}, {"pathtracer", "4 spp"}, {"pathtracer", "16 spp"}})
        ASSERT_TRUE(csv.find(kind, label)) << kind << " " << label;
    for (const auto& r : csv.rows) {
        for (const char* column : {"frame_ms", "frame_static_ms", "rmse", "relmse", "psnr", "ssim", "direct_rmse",
                                   "indirect_rmse", "indirect_relmse"}) {
            const double v = number(r, column);
            EXPECT_TRUE(std::isfinite(v)) << r.at("label") << " " << column;
            EXPECT_GE(v, 0.0) << r.at("label") << " " << column;
        }
        EXPECT_GT(number(r, "frame_ms"), 0.0) << r.at("label");
        EXPECT_GT(number(r, "rmse"), 0.0) << r.at("label");
        if (r.at("kind") == "engine") {
            EXPECT_GT(number(r, "memory_mib"), 0.0);
            EXPECT_EQ(r.at("incremental_identical"), "1") << r.at("label") << ": update frame ≠ full frame";
            EXPECT_GT(number(r, "ms_gbuffer"), 0.0);
        }
    }
    const auto& def = *csv.find("engine", "default");
    const auto& oneCone = *csv.find("engine", "cone_rays=1");
    EXPECT_EQ(def.at("is_default"), "1");
    EXPECT_EQ(oneCone.at("cone_rays"), "1");
    EXPECT_EQ(oneCone.at("voxel_levels"), def.at("voxel_levels"));
    EXPECT_EQ(oneCone.at("update_passes"), "cone_trace;composite") << "a cone setting re-runs only cone tracing";
    // Which of one and four narrow cones comes closer is not decided at this size: with their cones
    // shared between neighbours (--cone-reuse) one cone per pixel already averages 25 cells' worth,
    // and the 32³ voxels' bias is most of both errors (measured: RMSE 0.0401 and 0.0407).
    const auto& giOff = *csv.find("engine", "gi=false");
    EXPECT_LT(number(def, "rmse"), number(giOff, "rmse")) << "indirect light must bring the image closer";
    EXPECT_NEAR(number(giOff, "indirect_ratio"), 0.0, 1e-12) << "GI off: no indirect light";
    // Four pixel samples: only the camera's passes re-run, and the averaged pixels are closer to the
    // path tracer's, which averages each pixel's area.
    const auto& fourSamples = *csv.find("engine", "samples=4");
    EXPECT_EQ(fourSamples.at("samples"), "4");
    EXPECT_EQ(def.at("samples"), "1");
    EXPECT_EQ(fourSamples.at("update_passes"), "gbuffer;direct_lighting;cone_trace;composite");
    EXPECT_LT(number(fourSamples, "direct_rmse"), number(def, "direct_rmse"));
    EXPECT_LT(number(fourSamples, "rmse"), number(def, "rmse"));
    // The path tracer converges: 16 spp beats 1 spp by about √16.
    const double ratio = number(*csv.find("pathtracer", "1 spp"), "rmse") / number(*csv.find("pathtracer", "16 spp"), "rmse");
    EXPECT_GT(ratio, 2.5);
    EXPECT_LT(ratio, 5.0);

    EXPECT_TRUE(std::filesystem::exists(dir / "results" / "bench_quick.md"));
    EXPECT_TRUE(std::filesystem::exists(dir / "results" / "bench_quick.gp"));
    if (gnuplotInstalled())
        EXPECT_GT(std::filesystem::file_size(dir / "results" / "bench_quick.png"), 1000u);

    // The reference is cached: a second run renders nothing new and gives the same errors (every
    // image is deterministic).
    std::vector<std::filesystem::path> cached;
    for (const auto& e : std::filesystem::directory_iterator(dir / "cache")) cached.push_back(e.path());
    ASSERT_EQ(cached.size(), 3u) << "full and direct-only reference and their metadata";
    std::map<std::filesystem::path, std::filesystem::file_time_type> times;
    for (const auto& p : cached) times[p] = std::filesystem::last_write_time(p);

    // Without gnuplot on the PATH: the data and a clear message, no failure.
    const auto second = test::runVct(args + " --out " + (dir / "again").string(), "PATH=/nonexistent");
    ASSERT_EQ(second.exitCode, 0) << second.output;
    EXPECT_NE(second.output.find("gnuplot is not installed"), std::string::npos) << second.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "again" / "bench_quick.png"));
    for (const auto& p : cached) EXPECT_EQ(std::filesystem::last_write_time(p), times[p]) << p;
    const Csv again = readCsv(dir / "again" / "bench_quick.csv");
    ASSERT_EQ(again.rows.size(), csv.rows.size());
    for (std::size_t i = 0; i < csv.rows.size(); ++i)
        for (const char* column : {"rmse", "indirect_rmse", "ssim"})
            EXPECT_EQ(again.rows[i].at(column), csv.rows[i].at(column)) << csv.rows[i].at("label") << " " << column;
}

TEST(Bench, MissingSweepFileIsACleanError) {
    const auto dir = test::testDir();
    const auto result = test::runVct("bench " + (dir / "nope.json").string() + " --out " + dir.string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("vct: error: cannot read the sweep file"), std::string::npos) << result.output;
}
