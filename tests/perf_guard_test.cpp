// The performance guard (docs/benchmark.md "The performance guard"): every pass of a full frame,
// timed against a calibration workload of its kind in the same run (bench/pass_ratios.hpp), must
// stay within kSlowdownLimit of the ratio recorded in tests/data/perf_guard.json. Ratios, not
// milliseconds, so a slower or busier machine does not fail it; a pass that became several times
// slower does. ctest runs it alone (RUN_SERIAL, tests/CMakeLists.txt), so no other test competes
// for the cores while it measures.
//
// After a change that makes a pass legitimately slower or faster, record anew and commit the file:
//   VCT_PERF_GUARD_RECORD=1 ./build/vct_tests --gtest_filter='PerfGuard.*'
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/pass_ratios.hpp"
#include "gl/context.hpp"
#include "scene/scene_loader.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// A pass fails when its ratio exceeds this many times the recorded one.
constexpr double kSlowdownLimit = 2.5;
// Ratios below this (a pass under ~1/30 of the calibration: well under a millisecond on llvmpipe)
// are mostly fixed costs and timer granularity; they are held to this floor instead.
constexpr double kRatioFloor = 0.03;
constexpr int kRepeats = 3, kRecordRepeats = 7;

const std::filesystem::path kRecordFile = std::filesystem::path(VCT_TEST_DATA_DIR) / "perf_guard.json";

bool recording() {
    const char* value = std::getenv("VCT_PERF_GUARD_RECORD");
    return value && std::string(value) == "1";
}

// The frame the guard times: small enough for a test, with every pass of a lit frame running
// (a second bounce, so the bounce pass is guarded too).
// "llvmpipe (LLVM 15.0.6, 256 bits)" -> "llvmpipe"; "NVIDIA H200/PCIe/SSE2" -> "NVIDIA H200".
std::string rendererFamily(const std::string& renderer) {
    std::string family = renderer.substr(0, renderer.find_first_of("(/"));
    while (!family.empty() && family.back() == ' ') family.pop_back();
    return family;
}

RenderSettings guardSettings(int voxelLevels) {
    RenderSettings settings;
    settings.width = 160;
    settings.height = 90;
    settings.voxelLevels = voxelLevels;
    settings.lightViewResolution = 1024;
    settings.bounces = 2;
    settings.fullFrames = true;
    return settings;
}

void guard(const std::string& key, const Scene& scene, int voxelLevels) {
    auto context = gl::createContext(gl::defaultBackend());
    nlohmann::ordered_json record;
    if (std::ifstream in(kRecordFile); in) record = nlohmann::ordered_json::parse(in);
    // A pass's share of the work is a property of the renderer: a GPU's rasterizer and compute
    // units relate nothing like llvmpipe's threads. Ratios recorded on one family of renderer
    // (the name before its details, "llvmpipe" or "NVIDIA H200") guard only that family.
    if (!recording() && record.contains(key)) {
        const std::string recordedRenderer = record[key]["renderer"].get<std::string>();
        if (rendererFamily(recordedRenderer) != rendererFamily(context->info().renderer))
            GTEST_SKIP() << key << "'s ratios were recorded on " << recordedRenderer << ", not on "
                         << context->info().renderer << "; record them there with VCT_PERF_GUARD_RECORD=1";
    }
    Renderer renderer(scene, guardSettings(voxelLevels));
    bench::PerfCalibration calibration;
    const bench::PassRatios measured =
        bench::measurePassRatios(renderer, scene.cameras.at(0), calibration, recording() ? kRecordRepeats : kRepeats);
    std::printf("[ perf     ] %s: calibration compute %.1f ms, raster %.1f ms\n", key.c_str(),
                measured.computeCalibrationMs, measured.rasterCalibrationMs);

    if (recording()) {
        nlohmann::ordered_json passes;
        for (const bench::PassRatio& p : measured.passes)
            passes[p.name] = {{"kind", bench::workKindName(p.kind)}, {"ratio", p.ratio}, {"ms", p.ms}};
        record[key] = {{"renderer", context->info().renderer},
                       {"calibration_ms",
                        {{"compute", measured.computeCalibrationMs}, {"raster", measured.rasterCalibrationMs}}},
                       {"passes", passes}};
        std::ofstream(kRecordFile) << record.dump(2) << "\n";
        std::printf("[ perf     ] recorded %s in %s\n", key.c_str(), kRecordFile.string().c_str());
    }
    ASSERT_TRUE(record.contains(key)) << "no recorded ratios for " << key << " in " << kRecordFile
                                      << "; record them with VCT_PERF_GUARD_RECORD=1";
    const auto& recorded = record[key]["passes"];
    for (const bench::PassRatio& p : measured.passes) {
        ASSERT_TRUE(recorded.contains(p.name)) << "pass " << p.name << " has no recorded ratio in " << kRecordFile
                                                << "; record anew with VCT_PERF_GUARD_RECORD=1";
        const double was = recorded[p.name]["ratio"].get<double>();
        const double limit = kSlowdownLimit * std::max(was, kRatioFloor);
        std::printf("[ perf     ] %-16s %-7s %8.2f ms  ratio %7.3f  recorded %7.3f  (%.2fx; fails above %.3f)\n",
                    p.name.c_str(), bench::workKindName(p.kind), p.ms, p.ratio, was, p.ratio / was, limit);
        char message[256];
        std::snprintf(message, sizeof message,
                      "pass %s is %.2fx slower than recorded: %.2f ms, %.3f times the %s calibration (recorded %.3f)",
                      p.name.c_str(), p.ratio / was, p.ms, p.ratio, bench::workKindName(p.kind), was);
        EXPECT_LE(p.ratio, limit) << message;
    }
    for (const auto& [name, value] : recorded.items()) {
        bool ran = false;
        for (const bench::PassRatio& p : measured.passes) ran |= p.name == name;
        EXPECT_TRUE(ran) << "recorded pass " << name << " did not run in the guard's full frame";
    }
}

}  // namespace

TEST(PerfGuard, CornellPassesWithinRecordedRatios) { guard("cornell_L6", makeCornellBox(), 6); }

TEST(PerfGuard, SponzaPassesWithinRecordedRatios) {
    if (!findAsset("sponza/Sponza.gltf")) GTEST_SKIP() << "Sponza not found (" << assetSearchPathDescription() << ")";
    guard("sponza_L7", loadScene("sponza"), 7);
}
