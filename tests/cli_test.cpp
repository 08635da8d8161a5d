// The `vct` command as a user meets it: backends agree, and every kind of bad input ends in one
// clear message and a non-zero exit, never a crash or a black image.
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/image.hpp"
#include "test_models.hpp"
#include "test_util.hpp"
#include "xvfb.hpp"

using namespace vct;

namespace {

const std::string kSmall = " --width 64 --height 48 --light-view-res 256 --voxel-levels 5 ";

// The error line and nothing that looks like a crash.
void expectCleanError(const test::CommandResult& result, const std::string& mentions) {
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("vct: error: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(mentions), std::string::npos) << "expected '" << mentions << "' in:\n" << result.output;
    EXPECT_EQ(result.output.find("terminate called"), std::string::npos) << result.output;
}

double meanLuminance(const ImageF& image) {
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.at(x, y);
            sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        }
    return sum / (double(image.width) * image.height);
}

}  // namespace

TEST(Cli, CornellRendersThroughOSMesaAndEGLIdentically) {
    const auto dir = test::testDir();
    for (const char* backend : {"osmesa", "egl"}) {
        const auto result = test::runVct(std::string("render -q --scene cornell --backend ") + backend + kSmall +
                                         "--out " + (dir / backend).string() + ".png --hdr-out " +
                                         (dir / backend).string() + ".pfm");
        ASSERT_EQ(result.exitCode, 0) << backend << "\n" << result.output;
    }
    const ImageF a = readHdrImage(dir / "osmesa.pfm");
    const ImageF b = readHdrImage(dir / "egl.pfm");
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    double maxDifference = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) maxDifference = std::max(maxDifference, double(std::abs(a.rgba[i] - b.rgba[i])));
    EXPECT_LE(maxDifference, 1e-6);
    EXPECT_GT(meanLuminance(a), 0.01) << "the Cornell box must not render black";
}

TEST(Cli, GlfwBackendRendersInAHiddenWindowUnderX) {
    test::Xvfb xvfb;
    if (!xvfb.running()) GTEST_SKIP() << "Xvfb is not installed (apt-get install xvfb): the glfw backend is not tested";
    const auto dir = test::testDir();
    const auto result = test::runVct("render -q --scene cornell --backend glfw" + kSmall + "--hdr-out " +
                                         (dir / "g.pfm").string() + " --out " + (dir / "g.png").string(),
                                     "DISPLAY=" + xvfb.display());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    // Same llvmpipe rasterizer behind GLX: the image matches the offscreen one.
    ASSERT_EQ(test::runVct("render -q --scene cornell" + kSmall + "--hdr-out " + (dir / "o.pfm").string() +
                           " --out " + (dir / "o.png").string())
                  .exitCode,
              0);
    const ImageF glfw = readHdrImage(dir / "g.pfm"), osmesa = readHdrImage(dir / "o.pfm");
    EXPECT_GT(meanLuminance(glfw), 0.01);
    double maxDifference = 0;
    for (std::size_t i = 0; i < glfw.rgba.size(); ++i)
        maxDifference = std::max(maxDifference, double(std::abs(glfw.rgba[i] - osmesa.rgba[i])));
    EXPECT_LE(maxDifference, 1e-6);
}

// `--dark-material` takes a material's reflected light out of the engine and the path tracer alike,
// so the two can be compared light source by light source: without the red wall's light, the red
// share of the indirect light falls, and falls the same way in both.
TEST(Cli, DarkMaterialTakesItsLightOutOfEngineAndReferenceAlike) {
    const auto dir = test::testDir();
    auto redOverGreen = [](const std::filesystem::path& path) {
        const ImageF image = readHdrImage(path);
        double red = 0, green = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                red += image.at(x, y)[0];
                green += image.at(x, y)[1];
            }
        return red / green;
    };
    double engine[2], reference[2];
    for (int dark = 0; dark < 2; ++dark) {
        const std::string option = dark ? " --dark-material 'r*d' " : " ";  // matches "red" only
        const auto engineOut = dir / ("engine" + std::to_string(dark) + ".pfm");
        const auto referenceOut = dir / ("reference" + std::to_string(dark) + ".pfm");
        ASSERT_EQ(test::runVct("render -q --scene cornell" + kSmall + option + "--aov gi --hdr-out " + engineOut.string() +
                               " --out " + (dir / "e.png").string())
                      .exitCode,
                  0);
        const auto result = test::runVct("reference -q --scene cornell --width 64 --height 48 --spp 16 --bounces 1" +
                                         option + "--out " + (dir / "r.pfm").string() + " --indirect-out " +
                                         referenceOut.string());
        ASSERT_EQ(result.exitCode, 0) << result.output;
        engine[dark] = redOverGreen(engineOut);
        reference[dark] = redOverGreen(referenceOut);
    }
    EXPECT_LT(engine[1], 0.8 * engine[0]) << "the red wall's bleeding must leave the engine's indirect light";
    EXPECT_LT(reference[1], 0.8 * reference[0]) << "and the reference's";
    EXPECT_NEAR(engine[1] / reference[1], 1.0, 0.1) << "engine " << engine[1] << ", reference " << reference[1];
}

TEST(Cli, InfoPrintsCountsAndBounds) {
    const auto result = test::runVct("info --scene cornell");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("triangles  34"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("bounds"), std::string::npos);
    EXPECT_NE(result.output.find("spot"), std::string::npos) << result.output;
}

TEST(CliBadInput, MissingModelFile) {
    expectCleanError(test::runVct("render --scene /no/such/model.gltf" + kSmall + "--out /tmp/x.png"), "/no/such/model.gltf");
}

TEST(CliBadInput, CorruptModelFile) {
    const auto dir = test::testDir();
    std::ofstream(dir / "broken.gltf") << "{ \"asset\": {\"version\": \"2.0\"}, \"meshes\": [ {";
    expectCleanError(test::runVct("render --scene " + (dir / "broken.gltf").string() + kSmall + "--out " +
                                  (dir / "x.png").string()),
                     "broken.gltf");
    std::ofstream(dir / "binary.obj", std::ios::binary) << std::string("\x00\x01\x02\xff\xfe garbage \x7f", 16);
    const auto result = test::runVct("render --scene " + (dir / "binary.obj").string() + kSmall + "--out " +
                                     (dir / "y.png").string());
    expectCleanError(result, "binary.obj");
}

TEST(CliBadInput, ModelWithoutTriangles) {
    const auto dir = test::testDir();
    std::ofstream(dir / "points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0\nf 1 2 4\n";  // only a degenerate face
    expectCleanError(test::runVct("render --scene " + (dir / "points.obj").string() + kSmall + "--out " +
                                  (dir / "x.png").string()),
                     "no triangles");
}

TEST(CliBadInput, NonFiniteVerticesAreReportedOrDropped) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.5f));
    obj.floor(0.0f, 1.0f);
    obj.triangle({0, 1, 0}, {NAN, 1, 0}, {0, 1, 1});
    const auto model = obj.write(dir);
    expectCleanError(test::runVct("render --scene " + model.string() + kSmall + "--out " + (dir / "x.png").string()),
                     "non-finite");
    // With --sanitize the bad triangle is dropped, the rest renders, nothing NaN reaches the image.
    const auto result = test::runVct("render --sanitize --scene " + model.string() + kSmall + "--eye 0,3,0.01 --target 0,0,0 --out " +
                                     (dir / "x.png").string() + " --hdr-out " + (dir / "x.pfm").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("dropped"), std::string::npos) << result.output;
    const ImageF image = readHdrImage(dir / "x.pfm");
    for (float v : image.rgba) ASSERT_TRUE(std::isfinite(v));
    EXPECT_GT(meanLuminance(image), 0.01);
}

TEST(CliBadInput, MissingTextureWarnsAndKeepsGoing) {
    const auto dir = test::testDir();
    std::ofstream(dir / "m.mtl") << "newmtl tex\nKd 0.5 0.5 0.5\nmap_Kd does_not_exist.png\n";
    std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                    "usemtl tex\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
    const auto result = test::runVct("render --scene " + (dir / "m.obj").string() + kSmall +
                                     "--eye 0,3,0.01 --target 0,0,0 --out " + (dir / "x.png").string() + " --hdr-out " +
                                     (dir / "x.pfm").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("does_not_exist.png"), std::string::npos) << result.output;
    EXPECT_GT(meanLuminance(readHdrImage(dir / "x.pfm")), 0.01) << "material colour must be used instead";
}

TEST(CliBadInput, ImageSizeZeroOrAbsurd) {
    expectCleanError(test::runVct("render --scene cornell --width 0 --height 48 --out /tmp/x.png"), "width");
    expectCleanError(test::runVct("render --scene cornell --width 100000 --height 100000 --out /tmp/x.png"), "16384");
    expectCleanError(test::runVct("render --scene cornell --width 64 --height -5 --out /tmp/x.png"), "64x-5");
}

TEST(CliBadInput, UnknownPresetBackendAndValues) {
    expectCleanError(test::runVct("render --scene cornell --camera nope" + kSmall + "--out /tmp/x.png"), "default");
    expectCleanError(test::runVct("render --scene cornell --backend vulkan" + kSmall + "--out /tmp/x.png"), "osmesa");
    expectCleanError(test::runVct("render --scene cornell --aov shiny" + kSmall + "--out /tmp/x.png"), "albedo");
    expectCleanError(test::runVct("render --scene cornell --eye nan,1,2" + kSmall + "--out /tmp/x.png"), "camera");
    expectCleanError(test::runVct("render --scene cornell --sun-irradiance inf" + kSmall + "--out /tmp/x.png"), "irradiance");
    expectCleanError(test::runVct("render --scene cornell --spot-angles 50,20" + kSmall + "--out /tmp/x.png"), "inner");
    expectCleanError(test::runVct("render --scene cornell" + kSmall + "--out /no/such/dir/x.png"), "/no/such/dir");
    expectCleanError(test::runVct("render --scene cornell --cone-rays 65" + kSmall + "--out /tmp/x.png"), "1..64");
    expectCleanError(test::runVct("render --scene cornell --bounce-cone-rays 3" + kSmall + "--out /tmp/x.png"),
                     "--bounce-cone-rays 3 is out of range");
    expectCleanError(test::runVct("render --scene cornell --sample-cones wide" + kSmall + "--out /tmp/x.png"),
                     "--sample-cones must be narrow or frame");
    expectCleanError(test::runVct("render --scene cornell --dark-material Red" + kSmall + "--out /tmp/x.png"),
                     "white, red, green");
    expectCleanError(test::runVct("render --scene cornell --cone-rays 8 --only-cone 5" + kSmall + "--out /tmp/x.png"),
                     "--only-cone");
}

TEST(CliBadInput, OutputNamesMustSayTheirFormat) {
    // Every output whose name says another format than the one written is refused up front.
    expectCleanError(test::runVct("render --scene cornell" + kSmall + "--out /tmp/x.bmp"), "--out writes a PNG image");
    expectCleanError(test::runVct("render --scene cornell" + kSmall + "--out /tmp/x.png --hdr-out /tmp/x.tiff"),
                     "--hdr-out writes linear HDR");
    expectCleanError(test::runVct("reference --scene cornell --width 8 --height 8 --spp 1 --out /tmp/x.png"),
                     "--out writes linear HDR");
    expectCleanError(test::runVct("reference --scene cornell --width 8 --height 8 --spp 1 --out /tmp/x.pfm --png /tmp/x.jpg"),
                     "--png writes a PNG image");
    expectCleanError(test::runVct("compare /tmp/a.pfm /tmp/b.pfm --ratio-image /tmp/r.jpg"), "--ratio-image writes a PNG");
    expectCleanError(test::runVct("compare /tmp/a.pfm /tmp/b.pfm --error-image /tmp/e"), "--error-image writes a PNG");
}

TEST(CliBadInput, UsageErrorsExitWithTwo) {
    EXPECT_EQ(test::runVct("render --no-such-option").exitCode, 2);
    EXPECT_EQ(test::runVct("").exitCode, 2);
}
