// Stress 6, determinism (docs/robustness.md): every voxel pool (octree, albedo and radiance, the
// 64-bit photon sums) and the HDR image are bit-identical over three independent renders, over
// llvmpipe thread counts 1, 2 and 3 (different thread interleavings of every atomic), and between
// the OSMesa and EGL backends. Extends Svo.ThreeBuildsAreBitIdentical (octree only, one context)
// and Cli.CornellRendersThroughOSMesaAndEGLIdentically (≤ 1e-6, direct and GI).
// The pools and every image are also compared with hashes recorded in tests/data/
// determinism_hashes.txt: a change meant to leave the output alone (a refactor) must leave every
// hash alone; a change meant to alter it re-records them (VCT_RECORD_HASHES=1) and says why.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <fstream>
#include <iterator>

#include "scene/scene_loader.hpp"
#include "stress_util.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;

namespace {

// Everything a frame leaves in the voxel pools and the image, as raw bytes per pool.
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> snapshot(const Scene& scene) {
    auto context = gl::createContext(gl::Backend::OSMesa);
    RenderSettings settings = smallSettings(64, 48, 6, 512);
    Renderer renderer(scene, settings);
    renderer.renderFrame(scene.cameras[0]);
    const Octree& o = renderer.octree()->octree();
    const RadianceVolume& r = *renderer.radiance();
    std::vector<std::pair<std::string, std::vector<std::uint8_t>>> pools;
    auto buffer = [&](const char* name, const gl::Buffer& b, std::size_t bytes) {
        std::vector<std::uint8_t> data(bytes);
        if (bytes) glGetNamedBufferSubData(b.id(), 0, GLsizeiptr(bytes), data.data());
        pools.emplace_back(name, std::move(data));
    };
    auto texture = [&](const char* name, GLuint t, glm::ivec3 bricks) {
        const glm::ivec3 size = 3 * bricks;
        std::vector<std::uint8_t> data(std::size_t(size.x) * size.y * size.z * 16);
        glGetTextureImage(t, 0, GL_RGBA, GL_FLOAT, GLsizei(data.size()), data.data());
        pools.emplace_back(name, std::move(data));
    };
    buffer("octree child", o.child, std::size_t(o.totalCount) * 4);
    buffer("octree coord", o.coord, std::size_t(o.totalCount) * 4);
    buffer("octree neighbours", o.neighbours, std::size_t(o.nodeCount) * 24);
    buffer("cell albedo", o.cellAlbedo, std::size_t(o.cellCount()) * 4);
    buffer("cell normal", o.cellNormal, std::size_t(o.cellCount()) * 4);
    buffer("cell area", o.cellArea, std::size_t(o.cellCount()) * 4);
    buffer("cell column partners", o.cellColumns, std::size_t(o.cellCount()) * 4);
    buffer("node raw values", o.rawValue, std::size_t(o.nodeCount) * 16);
    texture("albedo bricks", o.brickAlbedo.id(), o.brickPoolBricks);
    buffer("cell opacity by axis", o.cellOpacity, std::size_t(o.cellCount()) * 4);
    texture("opacity bricks +", o.brickOpacityPlus.id(), o.brickPoolBricks);
    texture("opacity bricks -", o.brickOpacityMinus.id(), o.brickPoolBricks);
    buffer("photon sums", r.accumulators, std::size_t(o.cellCount()) * 4 * kAccumulatorWords);
    buffer("cell radiance", r.cellRadiance, std::size_t(o.cellCount()) * 16);
    buffer("cell exit shares", r.cellExitShares, std::size_t(o.cellCount()) * 32);
    texture("radiance bricks", r.directional.id(), r.directionalBricks * glm::ivec3(1, 1, 6));
    for (Aov aov : {Aov::Final, Aov::Indirect}) {
        settings.display.aov = aov;
        renderer.setSettings(settings);
        renderer.renderFrame(scene.cameras[0]);
        const ImageF image = renderer.readHdr();
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(image.rgba.data());
        pools.emplace_back(std::string("image ") + aovName(aov), std::vector<std::uint8_t>(bytes, bytes + image.rgba.size() * 4));
    }
    return pools;
}

// 64-bit FNV-1a: enough to tell two byte strings apart, and the same on every platform.
std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
    std::uint64_t hash = 14695981039346656037ull;
    for (std::uint8_t b : bytes) hash = (hash ^ b) * 1099511628211ull;
    return hash;
}

std::vector<std::uint8_t> bytesOf(const ImageF& image) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(image.rgba.data());
    return std::vector<std::uint8_t>(bytes, bytes + image.rgba.size() * sizeof(float));
}

// Every image the suite's settings can produce of the Cornell box: each AOV, raw node values, the
// voxel views and the 8-bit output.
std::vector<std::pair<std::string, std::vector<std::uint8_t>>> imageSnapshot(const Scene& scene) {
    auto context = gl::createContext(gl::Backend::OSMesa);
    RenderSettings settings = smallSettings(64, 48, 6, 512);
    Renderer renderer(scene, settings);
    std::vector<std::pair<std::string, std::vector<std::uint8_t>>> images;
    for (Aov aov : {Aov::Final, Aov::Direct, Aov::Indirect, Aov::Ao, Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Gi}) {
        settings.display.aov = aov;
        renderer.setSettings(settings);
        renderer.renderFrame(scene.cameras[0]);
        images.emplace_back(std::string("aov ") + aovName(aov), bytesOf(renderer.readHdr()));
    }
    settings.display.aov = Aov::Final;
    renderer.setSettings(settings);
    renderer.renderFrame(scene.cameras[0]);
    const Image8 ldr = renderer.readLdr();
    images.emplace_back("aov final 8-bit", std::vector<std::uint8_t>(ldr.rgba.begin(), ldr.rgba.end()));
    settings.bricks = false;
    renderer.setSettings(settings);
    renderer.renderFrame(scene.cameras[0]);
    images.emplace_back("aov final, no bricks", bytesOf(renderer.readHdr()));
    settings.bricks = true;
    for (ViewMode view : {ViewMode::Voxels, ViewMode::Radiance}) {
        settings.view = view;
        for (int level : {0, 4}) {
            settings.voxelViewLevel = level;
            renderer.setSettings(settings);
            renderer.renderFrame(scene.cameras[0]);
            images.emplace_back(std::string("voxel view ") + (view == ViewMode::Voxels ? "albedo" : "radiance") +
                                    " level " + std::to_string(level),
                                bytesOf(renderer.readHdr()));
        }
    }
    settings.view = ViewMode::Cones;
    settings.voxelViewLevel = 0;
    for (int rays : {0, 1}) {
        settings.cones.rays = rays;
        renderer.setSettings(settings);
        renderer.renderFrame(scene.cameras[0]);
        images.emplace_back(std::string("cone view, ") + (rays ? "narrow" : "cap of the set"), bytesOf(renderer.readHdr()));
    }
    return images;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Renders `options` (a vct command line) with 1 and 3 llvmpipe threads and expects the same HDR
// bytes, more than `minBytes` of them.
void expectSameImageWithOneAndThreeThreads(const std::string& name, const std::string& options, std::size_t minBytes) {
    const auto dir = testDir();
    std::string reference;
    for (const char* threads : {"1", "3"}) {
        const auto out = dir / (name + threads);
        const CommandResult result =
            runVct(options + "--out " + out.string() + ".png --hdr-out " + out.string() + ".pfm", std::string("LP_NUM_THREADS=") + threads);
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const std::string bytes = readFile(out.string() + ".pfm");
        ASSERT_GT(bytes.size(), minBytes);
        if (reference.empty())
            reference = bytes;
        else
            EXPECT_TRUE(bytes == reference) << name << ", " << threads << " threads: the image differs from 1 thread's";
    }
}

}  // namespace

TEST(StressDeterminism, ThreeRendersGiveBitIdenticalVoxelPoolsAndImages) {
    const Scene scene = makeCornellBox();
    const auto first = snapshot(scene);
    std::size_t bytes = 0;
    for (const auto& [name, data] : first) bytes += data.size();
    for (int run = 1; run < 3; ++run) {
        const auto again = snapshot(scene);
        ASSERT_EQ(again.size(), first.size());
        for (std::size_t i = 0; i < first.size(); ++i) {
            EXPECT_EQ(again[i].second.size(), first[i].second.size()) << first[i].first;
            EXPECT_TRUE(again[i].second == first[i].second) << first[i].first << " differs in run " << run + 1;
        }
    }
    std::printf("[ determinism] 3 renders: %zu pools and images, %.2f MiB each run, bit-identical\n", first.size(),
                double(bytes) / 1048576.0);
}

TEST(StressDeterminism, BouncesAndPixelSamplesGiveBitIdenticalImages) {
    // Three bounces (gathers at every voxel, the radiance filtered three times) and eight jittered
    // samples per pixel, rendered with 1 and 3 llvmpipe threads: the same bytes.
    expectSameImageWithOneAndThreeThreads(
        "bounces", " render -q --scene cornell --width 48 --height 36 --voxel-levels 5 --light-view-res 256 --bounces 3 --samples 8 ",
        48u * 36 * 3 * 4);
    std::printf("[ determinism] 3 bounces and 8 samples per pixel: bit-identical with 1 and 3 threads\n");
}

TEST(StressDeterminism, SponzaIsBitIdenticalWithOneAndThreeThreads) {
    // Sponza has what the Cornell box lacks: thousands of sliver cells that pool their photons with
    // the cells along their triangle's pixel column. Which cells were normalized once depended on
    // whether a cell was first touched by its own photon or as another cell's partner, so the
    // indirect light changed with the order the threads ran in (and from run to run on a GPU).
    if (!findAsset("sponza/Sponza.gltf")) GTEST_SKIP() << "Sponza not found (" << assetSearchPathDescription() << ")";
    expectSameImageWithOneAndThreeThreads(
        "sponza", " render -q --scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect ", 160u * 90 * 3 * 4);
}

TEST(StressDeterminism, ThreadCountsAndBackendsGiveBitIdenticalImages) {
    const auto dir = testDir();
    const std::string options = " render -q --scene cornell --width 64 --height 48 --voxel-levels 6 --light-view-res 512 ";
    struct Run {
        std::string name, backend, threads;
    };
    const std::vector<Run> runs = {{"osmesa, 1 thread", "osmesa", "1"}, {"osmesa, 2 threads", "osmesa", "2"},
                                   {"osmesa, 3 threads", "osmesa", "3"}, {"egl, 2 threads", "egl", "2"}};
    std::string reference;
    for (const Run& r : runs) {
        const auto out = dir / (r.backend + r.threads);
        for (const char* aov : {"final", "indirect"}) {
            const CommandResult result = runVct(options + "--backend " + r.backend + " --aov " + aov + " --out " +
                                                    out.string() + aov + ".png --hdr-out " + out.string() + aov + ".pfm",
                                                "LP_NUM_THREADS=" + r.threads);
            if (r.backend == "egl" && result.exitCode != 0 && result.output.find("egl") != std::string::npos)
                GTEST_SKIP() << "EGL is not available here: " << result.output;
            ASSERT_EQ(result.exitCode, 0) << r.name << "\n" << result.output;
        }
        const std::string bytes = readFile(out.string() + "final.pfm") + readFile(out.string() + "indirect.pfm");
        ASSERT_GT(bytes.size(), 64u * 48 * 3 * 4);
        if (reference.empty())
            reference = bytes;
        else
            EXPECT_TRUE(bytes == reference) << r.name << ": HDR output differs from " << runs[0].name;
    }
    std::printf("[ determinism] final and indirect HDR bit-identical over %zu runs (llvmpipe 1/2/3 threads, OSMesa and EGL)\n",
                runs.size());
}

TEST(StressDeterminism, PoolsAndImagesMatchRecordedHashes) {
    const Scene scene = makeCornellBox();
    auto items = snapshot(scene);
    for (auto& image : imageSnapshot(scene)) items.push_back(std::move(image));
    const std::filesystem::path file = std::filesystem::path(VCT_TEST_DATA_DIR) / "determinism_hashes.txt";
    if (const char* record = std::getenv("VCT_RECORD_HASHES"); record && std::string(record) == "1") {
        std::ofstream out(file);
        out << "# FNV-1a 64 of every voxel pool and image of StressDeterminism.PoolsAndImagesMatchRecordedHashes\n"
               "# (Cornell box, 64x48, 6 voxel levels, llvmpipe). Re-record with VCT_RECORD_HASHES=1 only for a\n"
               "# change meant to alter the output, and say so in its commit message.\n";
        for (const auto& [name, data] : items) {
            char hex[17];
            std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(data)));
            out << hex << " " << name << "\n";
        }
        GTEST_SKIP() << "recorded " << items.size() << " hashes into " << file;
    }
    std::ifstream in(file);
    ASSERT_TRUE(in) << "no recorded hashes at " << file << " (record them with VCT_RECORD_HASHES=1)";
    std::map<std::string, std::string> recorded;
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') recorded[line.substr(17)] = line.substr(0, 16);
    std::size_t matched = 0;
    for (const auto& [name, data] : items) {
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(data)));
        const auto it = recorded.find(name);
        if (it == recorded.end()) {
            ADD_FAILURE() << "'" << name << "' has no recorded hash";
            continue;
        }
        EXPECT_EQ(it->second, hex) << name << " differs from its recorded hash";
        matched += it->second == hex;
    }
    EXPECT_EQ(recorded.size(), items.size()) << "recorded hashes for items the test no longer produces";
    std::printf("[ determinism] %zu of %zu pools and images match their recorded hashes\n", matched, items.size());
}
