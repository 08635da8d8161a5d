// `vct view`, the interactive viewer, driven by `--script` under a private Xvfb: keys toggle what
// they should (checked on the screenshots with numbers), the panel is drawn, the window resizes,
// the run is deterministic and ends with exit code 0. Bad scripts fail before a window opens.
#include <cmath>
#include <fstream>

#include "core/image.hpp"
#include "render/view.hpp"
#include "scene/scene_loader.hpp"
#include "test_util.hpp"
#include "xvfb.hpp"

using namespace vct;

namespace {

constexpr int kWidth = 256, kHeight = 192;
const std::string kViewOptions = " --scene cornell --width 256 --height 192 --voxel-levels 5 --light-view-res 256 ";

struct Box {
    int x0, y0, x1, y1;  // inclusive-exclusive, clipped to the image
};

double luminance(const std::uint8_t* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

double meanLuminance(const Image8& image, Box box) {
    double sum = 0;
    int n = 0;
    for (int y = std::max(0, box.y0); y < std::min(image.height, box.y1); ++y)
        for (int x = std::max(0, box.x0); x < std::min(image.width, box.x1); ++x, ++n) sum += luminance(image.at(x, y));
    return n ? sum / n : 0.0;
}

// Mean absolute difference per channel (0..255) over a box.
double meanDifference(const Image8& a, const Image8& b, Box box) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    double sum = 0;
    int n = 0;
    for (int y = std::max(0, box.y0); y < std::min(a.height, box.y1); ++y)
        for (int x = std::max(0, box.x0); x < std::min(a.width, box.x1); ++x)
            for (int c = 0; c < 3; ++c, ++n) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
    return n ? sum / n : 0.0;
}

Box whole(const Image8& image) { return {0, 0, image.width, image.height}; }

// Pixel of a world point in the Cornell box's default view, with the engine's own projection.
glm::ivec2 pixelOf(const Scene& scene, glm::dvec3 world) {
    const ViewTransform view = cameraView(scene.cameras.at(0), scene, kWidth, kHeight);
    const glm::vec4 clip = view.viewProjection * glm::vec4(glm::vec3(world - scene.origin), 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return {int((ndc.x * 0.5f + 0.5f) * kWidth), int((0.5f - ndc.y * 0.5f) * kHeight)};
}

}  // namespace

TEST(Viewer, HelpListsEveryKey) {
    const auto result = test::runVct("view --help");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    for (const char* key : {"W A S D", "Home", " G ", " B ", " P ", " V ", "Shift+V", "[ ]", "1..6", "arrow keys", "F1",
                            "F12", "Esc", "--script"})
        EXPECT_NE(result.output.find(key), std::string::npos) << "'" << key << "' missing from:\n" << result.output;
}

TEST(Viewer, BadScriptsFailClearlyBeforeAWindowOpens) {
    const auto dir = test::testDir();
    struct Case {
        const char* script;
        const char* mentions;
    };
    for (const Case& c : {Case{"wait 2\njump 3\n", "line 2: unknown command 'jump'"},
                          Case{"key Hyper+Q\n", "line 1: unknown key 'Hyper+Q'"},
                          Case{"wait 0\n", "line 1: wait must be a whole number of frames"},
                          Case{"hold W\n", "line 1: expected 'hold NAME FRAMES'"},
                          Case{"mouse drag 3\n", "line 1: expected 'mouse drag DX DY'"},
                          Case{"screenshot /no/such/folder/a.png\n", "line 1: "}}) {
        std::ofstream(dir / "bad.txt") << c.script;
        // No DISPLAY: the script must be refused before the window is even tried.
        const auto result = test::runVct("view --scene cornell --script " + (dir / "bad.txt").string(), "DISPLAY=");
        EXPECT_EQ(result.exitCode, 1) << c.script << result.output;
        EXPECT_NE(result.output.find("vct: error: script "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find(c.mentions), std::string::npos) << "expected '" << c.mentions << "' in\n" << result.output;
    }
    const auto missing = test::runVct("view --scene cornell --script " + (dir / "none.txt").string(), "DISPLAY=");
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("cannot read the script"), std::string::npos) << missing.output;
}

TEST(Viewer, WithoutADisplayItSaysSo) {
    const auto result = test::runVct("view --scene cornell", "DISPLAY= WAYLAND_DISPLAY=");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("vct: error: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("DISPLAY"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("terminate called"), std::string::npos) << result.output;
}

TEST(Viewer, ScriptedSessionOnCornell) {
    test::Xvfb xvfb;
    if (!xvfb.running()) GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): the viewer is not tested";
    const auto dir = test::testDir();
    auto shot = [&](const char* name) { return (dir / (std::string(name) + ".png")).string(); };
    std::ofstream(dir / "session.txt") << "# vct view test session\n"
                                       << "wait 2\n"
                                       << "screenshot " << shot("panel") << "\n"
                                       << "key F1\n"
                                       << "screenshot " << shot("lit_few_samples") << "\n"
                                       << "wait 70\n"  // at rest: the viewer averages up to 64 samples
                                       << "screenshot " << shot("lit") << "\n"
                                       << "key G\n"
                                       << "screenshot " << shot("gi_off") << "\n"
                                       << "key G\nkey P\n"
                                       << "screenshot " << shot("photons_off") << "\n"
                                       << "key P\nkey B\n"
                                       << "screenshot " << shot("raw_nodes") << "\n"
                                       << "key B\nkey V\n"
                                       << "screenshot " << shot("voxels") << "\n"
                                       << "key [\nkey [\n"
                                       << "screenshot " << shot("voxels_coarse") << "\n"
                                       << "key ]\nkey ]\nkey Shift+V\n"
                                       << "screenshot " << shot("radiance") << "\n"
                                       << "key 2\n"
                                       << "screenshot " << shot("direct") << "\n"
                                       << "key 3\n"
                                       << "screenshot " << shot("indirect") << "\n"
                                       << "key 5\n"
                                       << "screenshot " << shot("albedo") << "\n"
                                       << "key 1\nhold W 10\nmouse drag 40 -10\n"
                                       << "screenshot " << shot("moved") << "\n"
                                       << "key Home\nwait 70\n"
                                       << "screenshot " << shot("home") << "\n"
                                       << "hold Down 20\n"
                                       << "screenshot " << shot("light_tilted") << "\n"
                                       << "resize 200 150\nwait 2\n"
                                       << "screenshot " << shot("resized") << "\n"
                                       << "key Esc\nwait 5\n"
                                       << "screenshot " << shot("after_esc") << "\n";
    const auto result = test::runVct("view" + kViewOptions + "--script " + (dir / "session.txt").string(),
                                     "DISPLAY=" + xvfb.display() + " VCT_LOG=warn");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output.find("GL debug error"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("screenshot " + shot("panel") + " (256x192)"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(shot("after_esc"))) << "Esc must end the session";

    const Image8 panel = readPng(shot("panel")), lit = readPng(shot("lit")), giOff = readPng(shot("gi_off"));
    const Image8 photonsOff = readPng(shot("photons_off")), rawNodes = readPng(shot("raw_nodes"));
    const Image8 voxels = readPng(shot("voxels")), voxelsCoarse = readPng(shot("voxels_coarse"));
    const Image8 radiance = readPng(shot("radiance")), direct = readPng(shot("direct"));
    const Image8 indirect = readPng(shot("indirect")), albedo = readPng(shot("albedo"));
    const Image8 moved = readPng(shot("moved")), home = readPng(shot("home")), tilted = readPng(shot("light_tilted"));
    const Image8 resized = readPng(shot("resized"));
    ASSERT_EQ(lit.width, kWidth);
    ASSERT_EQ(lit.height, kHeight);
    EXPECT_GT(meanLuminance(lit, whole(lit)), 20.0) << "the lit Cornell box must not be black";

    const Scene scene = loadScene("cornell");
    // The panel (top left, F1) against the same frame without it.
    const Box panelBox{8, 8, kWidth - 8, 60};
    const double panelDifference = meanDifference(panel, lit, panelBox);
    EXPECT_GT(panelDifference, 10.0);

    // GI: the ceiling gets no direct light from the downward spot, only indirect light.
    const glm::ivec2 c = pixelOf(scene, {0.0, 2.0, -0.3});
    const Box ceiling{c.x - 12, c.y - 3, c.x + 12, c.y + 3};
    const double ceilingOn = meanLuminance(lit, ceiling), ceilingOff = meanLuminance(giOff, ceiling);
    EXPECT_GT(ceilingOn, ceilingOff + 10.0);
    EXPECT_LT(ceilingOff, 3.0) << "without GI the ceiling is black";
    // P: no photons, so the cones see no light and the ceiling is dark again.
    EXPECT_LT(meanLuminance(photonsOff, ceiling), ceilingOn - 10.0);
    // B: raw node values give a different (blockier) indirect image.
    const double rawDifference = meanDifference(rawNodes, lit, whole(lit));
    EXPECT_GT(rawDifference, 0.2);

    // V: the octree's albedo is neither the lit image nor black; [ [ shows coarser voxels.
    const double voxelDifference = meanDifference(voxels, lit, whole(lit));
    EXPECT_GT(voxelDifference, 5.0);
    EXPECT_GT(meanLuminance(voxels, whole(voxels)), 20.0);
    EXPECT_GT(meanDifference(voxelsCoarse, voxels, whole(voxels)), 2.0);
    // Shift+V: the octree's radiance, not black, not the albedo view.
    EXPECT_GT(meanLuminance(radiance, whole(radiance)), 5.0);
    EXPECT_GT(meanDifference(radiance, voxels, whole(voxels)), 5.0);

    // Output views: direct light and albedo differ; direct has the ceiling black, albedo does not.
    const double directAlbedo = meanDifference(direct, albedo, whole(direct));
    EXPECT_GT(directAlbedo, 10.0);
    EXPECT_LT(meanLuminance(direct, ceiling), 3.0);
    EXPECT_GT(meanLuminance(albedo, ceiling), 100.0);
    EXPECT_GT(meanLuminance(indirect, ceiling), 3.0);

    // At rest the viewer averages jittered samples: the converged frame differs from the first
    // few a little, at edges (anti-aliasing), not as a whole.
    const Image8 fewSamples = readPng(shot("lit_few_samples"));
    const double accumulated = meanDifference(fewSamples, lit, whole(lit));
    EXPECT_GT(accumulated, 0.02);
    EXPECT_LT(accumulated, 3.0);
    // Camera: moving changes the view, Home brings back exactly the start frame (converged alike).
    EXPECT_GT(meanDifference(moved, lit, whole(lit)), 5.0);
    EXPECT_LE(meanDifference(home, lit, whole(lit)), 0.01);
    // Arrow keys tilt the light (Cornell has one spot, pointing down): the lit pool moves.
    EXPECT_GT(meanDifference(tilted, lit, whole(lit)), 1.0);
    // The window resized, and the renderer with it.
    EXPECT_EQ(resized.width, 200);
    EXPECT_EQ(resized.height, 150);
    EXPECT_GT(meanLuminance(resized, whole(resized)), 20.0);

    std::printf("[ viewer   ] panel diff %.1f; ceiling %.1f with GI, %.1f without, %.1f without photons; raw-node diff %.2f; "
                "voxel diff %.1f; direct/albedo diff %.1f; converged against the first samples %.2f\n",
                panelDifference, ceilingOn, ceilingOff, meanLuminance(photonsOff, ceiling), rawDifference, voxelDifference,
                directAlbedo, accumulated);
}
