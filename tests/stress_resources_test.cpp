// Stress 7, resource limits (docs/robustness.md, policy "Resource limits"): a request over the
// memory budget (--memory-budget MiB / $VCT_MEMORY_BUDGET_MIB) fails before any GPU allocation
// with the size it needs and the largest settings that fit, and those settings then render
// within the budget; requests beyond GL's limits fail with the limit; a real GL out-of-memory
// (llvmpipe under a virtual-memory limit) is caught and reported, never a crash.
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "render/memory_budget.hpp"
#include "scene/scene_loader.hpp"
#include "stress_util.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;
namespace fs = std::filesystem;

namespace {

const std::string kCornell = "render -q --scene cornell ";

bool sanitizerBuild() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}

}  // namespace

TEST(StressResources, OverBudgetFailsEarlyAndItsSuggestionFits) {
    const auto dir = testDir();
    for (const int budget : {300, 64, 16}) {
        std::map<std::string, std::string> settings = {
            {"--width", "640"}, {"--height", "480"}, {"--voxel-levels", "8"}, {"--light-view-res", "2048"}};
        auto options = [&] {
            std::string text = kCornell;
            for (const auto& [name, value] : settings) text += name + " " + value + " ";
            return text;
        };
        const std::string request = options();
        const CommandResult refused = runVct(request + "--memory-budget " + std::to_string(budget) + " --out " +
                                             (dir / "x.png").string());
        EXPECT_EQ(refused.exitCode, 1) << refused.output;
        EXPECT_NE(refused.output.find("needs about"), std::string::npos) << refused.output;
        EXPECT_NE(refused.output.find("memory budget of " + std::to_string(budget) + " MiB"), std::string::npos)
            << refused.output;
        EXPECT_EQ(refused.output.find("OpenGL 4.5"), std::string::npos) << "it must fail before a GL context exists";
        EXPECT_FALSE(fs::exists(dir / "x.png"));
        // "the largest that fits: --voxel-levels 6 --light-view-res 512 ... (about N MiB)": render with it.
        const std::smatch match = [&] {
            std::smatch m;
            std::regex_search(refused.output, m, std::regex("the largest that fits: ((--[a-z-]+ [0-9]+ )+)\\(about"));
            return m;
        }();
        ASSERT_FALSE(match.empty()) << refused.output;
        const std::string suggestion = match[1];
        std::istringstream words(suggestion);
        for (std::string name, value; words >> name >> value;) settings[name] = value;
        const CommandResult fits = runVct(options() + "--memory-budget " + std::to_string(budget) +
                                          " --timings " + (dir / "t.json").string() + " --out " + (dir / "y.png").string());
        ASSERT_EQ(fits.exitCode, 0) << suggestion << "\n" << fits.output;
        const auto report = nlohmann::json::parse(std::ifstream(dir / "t.json"));
        const double used = report["memory_total_bytes"].get<double>() / 1048576.0;
        EXPECT_LE(used, budget) << suggestion;
        std::printf("[ resources] budget %3d MiB: refused (%s), suggested %sused %.1f MiB\n", budget,
                    refused.output.substr(refused.output.find("needs"), 22).c_str(), suggestion.c_str(), used);
    }
}

TEST(StressResources, BudgetFromTheEnvironmentAndBadValues) {
    const auto dir = testDir();
    const std::string request = kCornell + "--width 64 --height 48 --voxel-levels 7 --out " + (dir / "x.png").string();
    const CommandResult refused = runVct(request, "VCT_MEMORY_BUDGET_MIB=32");
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_NE(refused.output.find("memory budget of 32 MiB"), std::string::npos) << refused.output;
    EXPECT_EQ(runVct(request, "VCT_MEMORY_BUDGET_MIB=100000").exitCode, 0);
    for (const char* bad : {"abc", "-5", "0", "nan", "inf"}) {
        const CommandResult r = runVct(request, std::string("VCT_MEMORY_BUDGET_MIB=") + bad);
        EXPECT_EQ(r.exitCode, 1) << bad << "\n" << r.output;
        EXPECT_NE(r.output.find("VCT_MEMORY_BUDGET_MIB"), std::string::npos) << r.output;
    }
    const CommandResult option = runVct(request + " --memory-budget -1");
    EXPECT_EQ(option.exitCode, 1) << option.output;
    EXPECT_NE(option.output.find("--memory-budget"), std::string::npos) << option.output;
}

TEST(StressResources, EstimateIsAConservativeBoundOfThePoolsUsed) {
    // Stated: the estimate is at least what the renderer's pools hold and at most 2.5× it.
    const Scene scene = makeCornellBox();
    for (int levels : {5, 6, 7}) {
        auto context = gl::createContext(gl::defaultBackend());
        const RenderSettings settings = smallSettings(96, 72, levels, 512);
        Renderer renderer(scene, settings);
        renderer.renderFrame(scene.cameras[0]);
        std::size_t used = 0;
        for (const MemoryPool& pool : renderer.memory()) used += pool.bytes;
        const MemoryEstimate e = estimateGpuMemory(
            scene, MemoryRequest{96, 72, 512, levels, true, true, false, settings.shadowMapResolution});
        EXPECT_GE(e.total(), used) << levels << " levels";
        EXPECT_LE(double(e.total()), 2.5 * double(used)) << levels << " levels";
        std::printf("[ resources] Cornell %d³: pools %.2f MiB, estimate %.2f MiB (%.2f×)\n", 1 << levels,
                    double(used) / 1048576.0, double(e.total()) / 1048576.0, double(e.total()) / double(used));
    }
}

// A point light's six cube faces get shadow maps of half the side (render/light_view.hpp): the
// pools hold exactly what the estimate counts: a quarter of the depth texels of full-size faces.
TEST(StressResources, APointLightsCubeFacesHoldHalfSizeShadowMaps) {
    Scene scene = makeCornellBox();
    Light point;
    point.type = LightType::Point;
    point.position = {0.0, 1.5, 0.0};
    point.intensity = 3.0;
    scene.lights = {point};
    auto context = gl::createContext(gl::defaultBackend());
    RenderSettings settings = smallSettings(96, 72, 5, 256);
    settings.shadowMapResolution = 1024;
    Renderer renderer(scene, settings);
    renderer.renderFrame(scene.cameras[0]);
    std::size_t maps = 0;
    for (const MemoryPool& pool : renderer.memory())
        if (pool.name == "light-view maps") maps = pool.bytes;
    const std::size_t photons = 256 * 256 * 44, halfShadow = 512 * 512 * 4;
    EXPECT_EQ(maps, 6 * (photons + halfShadow));
    const MemoryEstimate e =
        estimateGpuMemory(scene, MemoryRequest{96, 72, 256, 5, true, true, false, settings.shadowMapResolution});
    EXPECT_EQ(e.lightViewMaps, maps);
}

TEST(StressResources, RequestsBeyondGlLimitsFailWithTheLimit) {
    const auto dir = testDir();
    const std::string out = " --out " + (dir / "x.png").string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--width 20000 --height 100", "16384"},
        {"--width 64 --height 48 --light-view-res 100000", "use 16.."},
        {"--width 64 --height 48 --light-view-res 8", "use 16.."},
        {"--width 64 --height 48 --shadow-res 100000", "use 16.."},
        {"--width 64 --height 48 --shadow-res 8", "use 16.."},
        {"--width 64 --height 48 --voxel-levels 11", "use 5..10"},
        {"--width 64 --height 48 --voxel-levels 4", "use 5..10"},
    };
    for (const auto& [options, mentions] : cases) {
        const CommandResult r = runVct(kCornell + options + out);
        EXPECT_EQ(r.exitCode, 1) << options << "\n" << r.output;
        EXPECT_NE(r.output.find(mentions), std::string::npos) << options << "\n" << r.output;
        EXPECT_FALSE(fs::exists(dir / "x.png")) << options;
    }
}

TEST(StressResources, GlOutOfMemoryIsCaughtAndReported) {
    if (sanitizerBuild()) GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: ulimit -v cannot be used";
    // llvmpipe allocates GPU memory with malloc: under a 1.5 GB address-space limit a 1024³ octree
    // with 8192² light-view maps cannot be allocated, and GL reports GL_OUT_OF_MEMORY.
    const auto dir = testDir();
    const CommandResult r = runVct(kCornell + "--width 64 --height 48 --voxel-levels 10 --light-view-res 8192 --out " +
                                       (dir / "x.png").string(),
                                   "ulimit -v 1500000;");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("out of memory"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("engine bug"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
    std::printf("[ resources] under ulimit -v 1500000: %s", r.output.substr(r.output.find("vct: error")).c_str());
}
