// Direct lighting in physical units through the real `vct render` command: a Lambertian plane
// under a sun or a spot must show L = ρ/π · E · cosθ in the linear HDR output.
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>  // implementation in libstb

#include "core/image.hpp"
#include "gl/context.hpp"
#include "pipeline/frame_passes.hpp"
#include "scene/light.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// Mean of channel c over a square window of half-size r around (x, y).
double windowMean(const ImageF& image, int x, int y, int r, int c) {
    double sum = 0;
    int n = 0;
    for (int j = y - r; j <= y + r; ++j)
        for (int i = x - r; i <= x + r; ++i) {
            sum += image.at(i, j)[c];
            ++n;
        }
    return sum / n;
}

// Renders `model` looking straight down from above at the origin.
ImageF renderTopDown(const std::filesystem::path& model, const std::string& lightOptions, const std::string& extra = "") {
    const auto out = model.parent_path() / "out";
    const auto result = test::runVct("render -q --scene " + model.string() +
                                     " --gi off --eye 0,4,0.0001 --target 0,0,0 --fov 60 --width 96 --height 96 " +
                                     lightOptions + " " + extra + " --out " + out.string() + ".png --hdr-out " +
                                     out.string() + ".pfm");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return readHdrImage(out.string() + ".pfm");
}

// The floor's x under the centre of pixel column x of renderTopDown's view (4 m above, 60° field):
// the same pinhole the renderer uses.
double floorXAtColumn(int x) {
    const double halfExtent = 4.0 * std::tan(glm::radians(30.0));
    return ((x + 0.5) / 96.0 * 2.0 - 1.0) * halfExtent;
}

}  // namespace

TEST(DirectLighting, SunOnPlaneMatchesLambert) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("grey", {0.5f, 0.25f, 0.75f});
    obj.floor(0.0f, 3.0f);
    const auto model = obj.write(dir);
    for (double thetaDeg : {0.0, 30.0, 60.0}) {
        const double theta = glm::radians(thetaDeg);
        const double E = 2.0;
        const std::string sun = "--sun-dir " + std::to_string(std::sin(theta)) + "," + std::to_string(-std::cos(theta)) +
                                ",0 --sun-irradiance " + std::to_string(E);
        const ImageF image = renderTopDown(model, sun);
        const double expected[3] = {0.5 / glm::pi<double>() * E * std::cos(theta),
                                    0.25 / glm::pi<double>() * E * std::cos(theta),
                                    0.75 / glm::pi<double>() * E * std::cos(theta)};
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(windowMean(image, 48, 48, 10, c), expected[c], 0.01 * expected[c])
                << "theta " << thetaDeg << " channel " << c;
    }
}

TEST(DirectLighting, SpotOnPlaneMatchesInverseSquareAndFalloff) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.8f));
    obj.floor(0.0f, 3.0f);
    const auto model = obj.write(dir);
    const double I = 5.0, height = 2.0, inner = 20.0, outer = 40.0;
    const ImageF image = renderTopDown(model, "--spot-pos 0,2,0 --spot-dir 0,-1,0 --spot-intensity 5 --spot-angles 20,40");
    // Directly below: E = I / h².
    EXPECT_NEAR(windowMean(image, 48, 48, 1, 1), 0.8 / glm::pi<double>() * I / (height * height), 0.01 * 0.8 / glm::pi<double>() * I / 4);
    // Off axis, in the falloff band: check every pixel along the row against the closed form.
    int checked = 0;
    for (int x = 48; x < 96; ++x) {
        const double px = floorXAtColumn(x);
        const double d2 = px * px + height * height;
        const double cosAngle = height / std::sqrt(d2);
        const double E = I * spotFalloff(cosAngle, inner, outer) * cosAngle / d2;
        const double expected = 0.8 / glm::pi<double>() * E;
        const double got = image.at(x, 48)[1];
        // Pixel-centre sampling of a function that varies within the pixel: 2% or 2e-4 absolute.
        EXPECT_NEAR(got, expected, std::max(0.02 * expected, 2e-4)) << "x " << x << " px " << px;
        ++checked;
    }
    EXPECT_EQ(checked, 48);
}

TEST(DirectLighting, PointLightOnPlaneMatchesInverseSquareAcrossItsCubeFaces) {
    // A point light is drawn as six cube faces: 2 m above the floor, the face looking down covers
    // the floor out to |x| = 2 m and the side faces the rest. The view reaches |x| = 2.31 m, so the
    // row crosses the seams between faces, where nothing may be lost or counted twice.
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.8f));
    obj.floor(0.0f, 3.0f);
    const auto model = obj.write(dir);
    const double I = 5.0, height = 2.0;
    const ImageF image = renderTopDown(model, "--point-pos 0,2,0 --point-intensity 5");
    int checked = 0, beyondSeam = 0;
    for (int x = 0; x < 96; ++x) {
        const double px = floorXAtColumn(x);
        const double d2 = px * px + height * height;
        const double E = I * (height / std::sqrt(d2)) / d2;  // I·cosθ/d²
        const double expected = 0.8 / glm::pi<double>() * E;
        EXPECT_NEAR(image.at(x, 48)[1], expected, 0.02 * expected) << "x " << x << " px " << px;
        ++checked;
        if (std::abs(px) > height) ++beyondSeam;
    }
    EXPECT_EQ(checked, 96);
    EXPECT_GE(beyondSeam, 8);  // the row does reach the side faces
}

namespace {
// The pixel of world point p in the slab scenes' view (--eye 0,2.5,3.5 --target 0,0,0 --fov 50,
// 128×96), for the shadow tests.
glm::ivec2 slabScenePixel(glm::dvec3 p, int width = 128, int height = 96) {
    const glm::dvec3 eye(0, 2.5, 3.5), forward = glm::normalize(-eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 v = p - eye;
    const double f = 1.0 / std::tan(glm::radians(25.0));
    const double x = glm::dot(v, right) / glm::dot(v, forward) * f / (double(width) / height);
    const double y = glm::dot(v, up) / glm::dot(v, forward) * f;
    return glm::ivec2(int((x * 0.5 + 0.5) * width), int((0.5 - y * 0.5) * height));
}

// One sample of the engine's direct light (GI off; `engineOptions` its own settings) and the path
// tracer's pixel average of it (bounces 0, 256 spp) for the same `view`.
struct DirectPair {
    ImageF engine, reference;
};
DirectPair directAgainstPixelAverage(const std::filesystem::path& dir, const std::string& view,
                                     const std::string& engineOptions = "") {
    const auto engine = dir / "engine.pfm", truth = dir / "reference.pfm";
    const auto r1 = test::runVct("render -q --gi off --aov direct" + engineOptions + view + "--hdr-out " +
                                 engine.string() + " --out " + (dir / "engine.png").string());
    EXPECT_EQ(r1.exitCode, 0) << r1.output;
    const auto r2 = test::runVct("reference -q --bounces 0 --spp 256" + view + "--out " + truth.string());
    EXPECT_EQ(r2.exitCode, 0) << r2.output;
    return {readHdrImage(engine), readHdrImage(truth)};
}
}  // namespace

// A shadow edge is as sharp as the shadow map's texels or the pixel, whichever is wider: with the
// photons' coarse map the slab's edge is blurred over several texels; a finer shadow map of its
// own (--shadow-res) puts it back where the geometry says, while the photons (and so the indirect
// light) stay the same. The fine map is seen at 512×384, where a pixel spans about 1.5 cm of the
// floor along the view; at 128×96 the pixel's 6 cm would be the penumbra (the filter spans it).
TEST(DirectLighting, FinerShadowMapSharpensTheShadowEdge) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.6f));
    obj.floor(0.0f, 3.0f);
    obj.box({-0.5f, 1.0f, -0.5f}, {0.5f, 1.2f, 0.5f});
    const auto model = obj.write(dir);
    const double lit = 0.6 / glm::pi<double>() * 3.0;
    // Along the floor in front of the slab (x = 0, z from 0.35 to 0.85; the edge is at z = 0.5):
    // how far the penumbra reaches, and where the light reaches half its value.
    struct Edge {
        int penumbraSteps = 0;
        double halfLightZ = 0.0;
    };
    auto edge = [&](const std::string& resolutions, const std::string& name, int width, int height) {
        const auto out = dir / name;
        const auto result = test::runVct("render -q --scene " + model.string() +
                                         " --gi off --eye 0,2.5,3.5 --target 0,0,0 --fov 50 --width " + std::to_string(width) +
                                         " --height " + std::to_string(height) + " --sun-dir 0,-1,0 --sun-irradiance 3 --aov direct " + resolutions +
                                         " --hdr-out " + out.string() + ".pfm --out " + out.string() + ".png");
        EXPECT_EQ(result.exitCode, 0) << result.output;
        const ImageF image = readHdrImage(out.string() + ".pfm");
        Edge e;
        for (int step = 0; step <= 50; ++step) {
            const double z = 0.35 + 0.01 * step;
            const glm::ivec2 p = slabScenePixel({0.0, 0.0, z}, width, height);
            const double value = image.at(p.x, p.y)[0] / lit;
            if (value > 0.1 && value < 0.9) ++e.penumbraSteps;
            if (e.halfLightZ == 0.0 && value >= 0.5) e.halfLightZ = z;
        }
        return e;
    };
    const Edge coarse = edge("--light-view-res 64 --shadow-res 64", "coarse", 128, 96);
    const Edge fine = edge("--light-view-res 64 --shadow-res 1024", "fine", 512, 384);
    std::printf("[ shadow   ] penumbra along the floor: %d cm with the photons' 64² map, %d cm with a 1024² shadow "
                "map; half light at z = %.2f and %.2f (edge at 0.50)\n",
                coarse.penumbraSteps, fine.penumbraSteps, coarse.halfLightZ, fine.halfLightZ);
    EXPECT_GE(coarse.penumbraSteps, 10);
    EXPECT_LE(fine.penumbraSteps, 4);
    EXPECT_NEAR(fine.halfLightZ, 0.5, 0.03);
}

// One sample per pixel of a shadow edge finer than the pixel: the shadow filter spans the pixel's
// footprint on the floor, so each pixel shows the share of it that is lit, as the path tracer's
// pixel-area average does, rather than whether its centre is. The edge is a triangle's diagonal
// (x + z = 0 under a vertical sun), oblique to the pixel grid, so it crosses pixels at every
// fraction; the 1024² map's texels are 6 times finer than the pixels (128×96, about 4 × 6 cm).
TEST(DirectLighting, OneSampleOfAShadowEdgeShowsTheLitShareOfItsPixel) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.6f));
    obj.floor(0.0f, 3.0f);
    obj.triangle({-1.0f, 1.0f, -1.0f}, {-1.0f, 1.0f, 1.0f}, {1.0f, 1.0f, -1.0f});
    const auto model = obj.write(dir);
    const std::string view = " --scene " + model.string() +
                             " --eye 0,2.5,3.5 --target 0,0,0 --fov 50 --width 128 --height 96"
                             " --sun-dir 0,-1,0 --sun-irradiance 3 ";
    const auto [a, b] = directAgainstPixelAverage(dir, view, " --light-view-res 64 --shadow-res 1024");
    const double lit = 0.6 / glm::pi<double>() * 3.0;
    // The pixels whose footprint the edge crosses (the reference neither lit nor dark there), away
    // from the triangle's other edges, which the camera sees at the floor's contact.
    double error = 0.0;
    int edgePixels = 0;
    for (double t = -0.6; t <= 0.6; t += 0.01) {
        const glm::ivec2 p = slabScenePixel({t, 0.0, -t});
        for (int dy = -2; dy <= 2; ++dy) {
            const double truthShare = b.at(p.x, p.y + dy)[0] / lit;
            if (truthShare < 0.05 || truthShare > 0.95) continue;
            error += std::abs(a.at(p.x, p.y + dy)[0] / lit - truthShare);
            ++edgePixels;
        }
    }
    ASSERT_GT(edgePixels, 0);
    error /= edgePixels;
    std::printf("[ shadow   ] oblique edge, one sample: %d pixel visits across it, mean |engine - reference| %.3f of "
                "the lit floor (a centre's lit-or-not would be about 0.25)\n",
                edgePixels, error);
    EXPECT_LT(error, 0.1);
}

// A rod 2 cm thick half a metre above a floor, the sun straight down: its shadow is a line 2 cm
// wide, seen from 0.4 m above the floor 5.3 m away (4.4°), where one row of pixels spans 0.38 m of
// floor. Each pixel should show the lit share of its footprint, as the path tracer's pixel
// average does (about 0.95 on the line's row). The neighbouring rows' points lie 13 pixel widths
// apart there, and taken for a silhouette they left the pixels their filter of 3×3 texels: the
// pixels whose centre fell on the line went black, a whole row of them.
TEST(DirectLighting, AThinShadowOnAFloorSeenAtAGrazingAngleShowsTheLitShareOfItsPixels) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.6f));
    obj.floor(0.0f, 20.0f);
    // Centred on the floor point that the centre of pixel row 57 sees, 2.25 m ahead of the eye's foot.
    obj.box({-3.0f, 0.49f, -2.2592f}, {3.0f, 0.51f, -2.2392f});
    const auto model = obj.write(dir);
    const std::string view = " --scene " + model.string() +
                             " --eye 0,0.4,3 --target 0,0.1,-10 --fov 30 --width 128 --height 96"
                             " --sun-dir 0,-1,0 --sun-irradiance 3 ";
    const auto [a, b] = directAgainstPixelAverage(dir, view);
    const double lit = 0.6 / glm::pi<double>() * 3.0;
    // The floor's pixels in the middle columns: the largest difference, and how many pixels the
    // reference shows darkened by the line (that the line is there to be seen).
    double largest = 0.0;
    int lineRows = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 40; x < 88; ++x) {
            const double truthShare = b.at(x, y)[0] / lit;
            if (truthShare < 0.5) continue;  // the sky, the far floor's edge
            largest = std::max(largest, std::abs(a.at(x, y)[0] / lit - truthShare));
            lineRows += truthShare < 0.98;
        }
    std::printf("[ shadow   ] thin line on a grazing floor, one sample: largest |engine - reference| %.3f of the lit "
                "floor over the floor's pixels (%d of them darkened by the line in the reference)\n",
                largest, lineRows);
    EXPECT_GT(lineRows, 0);
    EXPECT_LT(largest, 0.3);
}

// A curtain with smooth normals, seen at a grazing angle on its dark side: the sun and the floor
// it lights are behind it, nothing is in front. Its vertex normals lean 60° from its plane's normal
// (away from the camera), so from the camera they point away even though the face the camera
// sees is the front. Turned to face the camera by itself, the normal would point into the
// curtain: the cones would start behind it, in the sunlit half (101 % of the lit floor's
// radiance). Turned to the side the triangle shows the camera, the ring cones that lean behind
// the curtain's plane would still reach around its edge, 1 m away (6 %); the path tracer gives
// directions behind the triangle nothing, and so do the cones, by the share of each that lies
// behind the triangle's own plane (the G-buffer's geometric normal): 1.4 %.
TEST(DirectLighting, ASmoothCurtainSeenGrazingStaysDarkOnItsUnlitSide) {
    const auto dir = test::testDir();
    std::ofstream(dir / "curtain.mtl") << "newmtl white\nKd 0.6 0.6 0.6\n";
    std::ofstream obj(dir / "curtain.obj");
    obj << "mtllib curtain.mtl\nusemtl white\n"
           // the floor behind the curtain (z < 0), facing up
           "v -3 0 -3\nv 3 0 -3\nv 3 0 0\nv -3 0 0\n"
           // the curtain at z = 0, its front (+z) towards the camera
           "v -1 0 0\nv 1 0 0\nv 1 2 0\nv -1 2 0\n"
           "vn 0 1 0\nvn 0.866 0 0.5\n"
           "f 4//1 3//1 2//1\nf 4//1 2//1 1//1\n"
           "f 5//2 6//2 7//2\nf 5//2 7//2 8//2\n";
    obj.close();
    const auto out = dir / "out";
    const auto result = test::runVct("render -q --scene " + (dir / "curtain.obj").string() +
                                     " --eye -3,1,1 --target 0,1,0 --fov 40 --width 96 --height 72 --voxel-levels 6"
                                     " --sun-dir 0,-0.6,0.8 --sun-irradiance 3 --hdr-out " + out.string() +
                                     ".pfm --out " + out.string() + ".png");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const ImageF image = readHdrImage(out.string() + ".pfm");
    const double litFloor = 0.6 / glm::pi<double>() * 3.0 * 0.6;
    const double curtain = windowMean(image, 48, 36, 2, 0);
    std::printf("[ normals  ] grazing view of a smooth curtain's unlit side: %.4f, %.2f %% of the sunlit floor\n",
                curtain, 100.0 * curtain / litFloor);
    EXPECT_LT(curtain, 0.03 * litFloor);
}

// A wall lit at 15° from its plane under a ledge that sticks out 0.4 m at 2 m: the ledge shadows
// the wall down to y = 2 − 0.4·cot 15° = 0.507 m. Moving a shadow lookup off the wall by a texel
// (the usual normal offset against acne) lets it see past the ledge and lifts that edge by
// cot 15° = 3.7 texels per texel; the edge must stay where the geometry puts it.
TEST(DirectLighting, ALedgeShadowsAGrazingLitWallDownToWhereTheRaysSay) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.6f));
    obj.box({-1.5f, 0.0f, -0.2f}, {1.5f, 3.0f, 0.0f});  // the wall, its face at z = 0
    obj.box({-1.5f, 2.0f, 0.0f}, {1.5f, 2.2f, 0.4f});   // the ledge
    const auto model = obj.write(dir);
    const double towardSun = glm::radians(15.0);
    const double expectedEdge = 2.0 - 0.4 / std::tan(towardSun);
    const double lit = 0.6 / glm::pi<double>() * 3.0 * std::sin(towardSun);
    // The camera faces the wall from 4 m: row r of 96 shows height 1 + (0.5 − (r + ½)/96)·2·4·tan 25°.
    auto heightAtRow = [](int row) { return 1.0 + (0.5 - (row + 0.5) / 96.0) * 8.0 * std::tan(glm::radians(25.0)); };
    for (const char* shadowRes : {"256", "1024"}) {
        const auto out = dir / (std::string("ledge") + shadowRes);
        const auto result = test::runVct(
            "render -q --scene " + model.string() + " --gi off --eye 0,1,4 --target 0,1,0 --fov 50 --width 96"
            " --height 96 --sun-dir 0," + std::to_string(-std::cos(towardSun)) + "," + std::to_string(-std::sin(towardSun)) +
            " --sun-irradiance 3 --aov direct --light-view-res 256 --shadow-res " + shadowRes + " --hdr-out " +
            out.string() + ".pfm --out " + out.string() + ".png");
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const ImageF image = readHdrImage(out.string() + ".pfm");
        // Up the middle column from the wall's foot to the first row under half the lit value; the
        // edge is where the light crosses one half between that row and the one below it.
        double edge = 0.0;
        for (int row = 94; row >= 0 && edge == 0.0; --row) {
            const double below = image.at(48, row + 1)[0], here = image.at(48, row)[0];
            if (heightAtRow(row + 1) < 0.2 || here >= 0.5 * lit) continue;
            const double t = (below - 0.5 * lit) / (below - here);
            edge = heightAtRow(row + 1) + t * (heightAtRow(row) - heightAtRow(row + 1));
        }
        std::printf("[ shadow   ] ledge over a wall lit at 15 degrees, %s² shadow map: edge at %.3f m (%.3f expected)\n",
                    shadowRes, edge, expectedEdge);
        EXPECT_NEAR(edge, expectedEdge, 0.03) << shadowRes;
        // Under the edge the wall is lit everywhere, as much as Lambert says (no acne at 15°).
        double darkest = lit;
        for (int row = 0; row < 96; ++row)
            if (heightAtRow(row) > 0.2 && heightAtRow(row) < 0.4)
                for (int x = 24; x < 72; ++x) darkest = std::min(darkest, double(image.at(x, row)[0]));
        EXPECT_GT(darkest, 0.98 * lit) << shadowRes;
    }
}

TEST(DirectLighting, AlphaMaskedHolesLetTheSunThroughEitherShadowMap) {
    // A quad 1 m above the floor whose texture is transparent on its left half (x < 0): the sun
    // straight down lights the floor under that half and not under the other, whether the shadow
    // map is the photons' map or a finer one of its own (drawn depth only, masked materials apart).
    const auto dir = test::testDir();
    std::vector<std::uint8_t> texels(16 * 16 * 4, 255);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 8; ++x) texels[std::size_t(y * 16 + x) * 4 + 3] = 0;
    ASSERT_NE(stbi_write_png((dir / "mask.png").c_str(), 16, 16, 4, texels.data(), 16 * 4), 0);
    std::ofstream(dir / "masked.mtl") << "newmtl white\nKd 0.6 0.6 0.6\nnewmtl leaf\nKd 0.6 0.6 0.6\nmap_Kd mask.png\n";
    std::ofstream(dir / "masked.obj") << "mtllib masked.mtl\n"
                                         "v -3 0 -3\nv 3 0 -3\nv 3 0 3\nv -3 0 3\n"
                                         "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                         "usemtl white\nf 1 4 3 2\n"
                                         "usemtl leaf\nf 5/4 8/1 7/2 6/3\n";
    const double lit = 0.6 / glm::pi<double>() * 3.0;
    for (const std::string resolutions : {"--light-view-res 256 --shadow-res 256", "--light-view-res 64 --shadow-res 1024"}) {
        const auto out = dir / "masked";
        const auto result = test::runVct("render -q --scene " + (dir / "masked.obj").string() +
                                         " --gi off --eye 0,2.5,3.5 --target 0,0,0 --fov 50 --width 128 --height 96"
                                         " --sun-dir 0,-1,0 --sun-irradiance 3 --aov direct " + resolutions +
                                         " --hdr-out " + out.string() + ".pfm --out " + out.string() + ".png");
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const ImageF image = readHdrImage(out.string() + ".pfm");
        const glm::ivec2 underHole = slabScenePixel({-0.25, 0.0, 0.2}), underLeaf = slabScenePixel({0.25, 0.0, 0.45});
        const double hole = image.at(underHole.x, underHole.y)[0] / lit, leaf = image.at(underLeaf.x, underLeaf.y)[0] / lit;
        std::printf("[ shadow   ] %s: floor under the mask's hole %.3f, under its opaque half %.3f of the lit floor\n",
                    resolutions.c_str(), hole, leaf);
        EXPECT_NEAR(hole, 1.0, 0.02) << resolutions;
        EXPECT_LT(leaf, 0.02) << resolutions;
    }
}

TEST(DirectLighting, BoxCastsAShadowOnTheFloor) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.6f));
    obj.floor(0.0f, 3.0f);
    obj.box({-0.5f, 1.0f, -0.5f}, {0.5f, 1.2f, 0.5f});  // a slab floating above the floor
    const auto model = obj.write(dir);
    // Camera looks from the side-top so the floor under the slab is visible; sun straight down.
    const auto out = dir / "shadow";
    const auto result = test::runVct("render -q --scene " + model.string() +
                                     " --gi off --eye 0,2.5,3.5 --target 0,0,0 --fov 50 --width 128 --height 96"
                                     " --sun-dir 0,-1,0 --sun-irradiance 3 --aov direct --hdr-out " + out.string() +
                                     ".pfm --out " + out.string() + ".png");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const ImageF image = readHdrImage(out.string() + ".pfm");
    // The shadowed and lit floor, found by projecting world points with the same camera.
    const double lit = 0.6 / glm::pi<double>() * 3.0;
    const glm::ivec2 litPixel = slabScenePixel({2.0, 0.0, 1.5});
    EXPECT_NEAR(image.at(litPixel.x, litPixel.y)[0], lit, 0.01 * lit);
    // The floor under the slab's centre is hidden by the slab from this camera, so look at the
    // part of the shadow in front of it: z in (0.35, 0.5) is shadowed and visible.
    const glm::ivec2 shadowPixel = slabScenePixel({0.0, 0.0, 0.45});
    EXPECT_LT(image.at(shadowPixel.x, shadowPixel.y)[0], 0.02 * lit) << shadowPixel.x << "," << shadowPixel.y;
    const glm::ivec2 besideShadow = slabScenePixel({0.0, 0.0, 0.7});
    EXPECT_NEAR(image.at(besideShadow.x, besideShadow.y)[0], lit, 0.02 * lit);
}

namespace {
nlohmann::json renderTimings(const std::string& options) {
    const auto dir = test::testDir();
    const auto json = dir / "t.json";
    const auto result = test::runVct("render -q --scene cornell --width 64 --height 48 --light-view-res 256 " + options +
                                     " --out " + (dir / "c.png").string() + " --timings " + json.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    std::ifstream file(json);
    return nlohmann::json::parse(file);
}
std::vector<std::string> passNames(const nlohmann::json& timings) {
    std::vector<std::string> names;
    for (const auto& pass : timings["passes"]) names.push_back(pass["name"]);
    return names;
}
std::vector<std::string> passNames(std::initializer_list<Pass> passes) {
    std::vector<std::string> names;
    for (Pass p : passes) names.push_back(passName(p));
    return names;
}
}  // namespace

TEST(DirectLighting, TimingsJsonListsEveryPassOfTheGiFrame) {
    // First frame: the octree is built; every pass of DESIGN §4 runs once.
    const auto first = renderTimings("--voxel-levels 5 --frames 1");
    EXPECT_EQ(passNames(first),
              passNames({Pass::Voxelize, Pass::SvoBuild, Pass::SvoLeaves, Pass::SvoNeighbours, Pass::Bricks, Pass::BricksMip,
                                        Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::GBuffer,
                                        Pass::DirectLighting, Pass::ConeTrace, Pass::Composite}));
    EXPECT_EQ(first["voxels"]["levels"], 5);
    // Second frame of a static scene: nothing changed, so no pass runs at all, and the graph says so.
    const auto second = renderTimings("--voxel-levels 5 --frames 2");
    EXPECT_TRUE(passNames(second).empty());
    ASSERT_EQ(second["graph"].size(), kPassCount);
    for (const auto& pass : second["graph"]) {
        EXPECT_FALSE(pass["ran"].get<bool>()) << pass["name"];
        EXPECT_FALSE(pass["reason"].get<std::string>().empty());
    }
}

TEST(DirectLighting, TimingsJsonCountsTheVoxelsThatGatherTheirOwnBounce) {
    // Cornell's corners and box edges hold voxels whose first sibling faces another way: they
    // gather their own bounce; flat walls share. One bounce gathers nothing.
    const auto one = renderTimings("--voxel-levels 6");
    EXPECT_EQ(one["statistics"]["bounce_own_gathers"], 0);
    const auto two = renderTimings("--voxel-levels 6 --bounces 2");
    const std::uint32_t own = two["statistics"]["bounce_own_gathers"];
    const auto& nodesPerLevel = two["voxels"]["nodes_per_level"];
    const std::uint32_t voxels = nodesPerLevel.back(), leafNodes = nodesPerLevel[nodesPerLevel.size() - 2];
    std::printf("[ bounce   ] Cornell 64^3: %u of %u voxels gather their own bounce (%u leaf nodes gather for their first child)\n",
                own, voxels, leafNodes);
    EXPECT_EQ(two["statistics"]["bounces_gathered"], 1);
    EXPECT_GT(own, 0u);
    EXPECT_LT(own, (voxels - leafNodes) / 2);
}

TEST(DirectLighting, TimingsJsonListsEveryPass) {
    const auto timings = renderTimings("--gi off --full-frames --frames 2");
    EXPECT_EQ(timings["backend"], gl::defaultBackendName());  // osmesa unless VCT_BACKEND says otherwise
    EXPECT_EQ(timings["width"], 64);
    EXPECT_EQ(timings["height"], 48);
    EXPECT_EQ(timings["frame"], 1);
    std::vector<std::string> names;
    double sum = 0;
    for (const auto& pass : timings["passes"]) {
        names.push_back(pass["name"]);
        EXPECT_GE(pass["gpu_ms"].get<double>(), 0.0);
        EXPECT_GE(pass["cpu_ms"].get<double>(), 0.0);
        sum += pass["gpu_ms"].get<double>();
    }
    EXPECT_EQ(names, passNames({Pass::LightView, Pass::GBuffer, Pass::DirectLighting, Pass::Composite}));
    EXPECT_GT(timings["total_gpu_ms"].get<double>(), 0.0);
    // Passes run back to back: their sum cannot exceed the frame span by more than rounding.
    EXPECT_LE(sum, timings["total_gpu_ms"].get<double>() + 1e-3);
    EXPECT_GT(timings["memory_total_bytes"].get<double>(), 64 * 48 * 16);
}

TEST(DirectLighting, FinishEachPassKeepsEveryPassInsideItsWallTime) {
    // Without it, llvmpipe rasterizes a raster pass's triangles when a later pass flushes, so that
    // pass's GPU span can be many times its CPU time; finished passes hold all their own work.
    const auto timings = renderTimings("--voxel-levels 5 --full-frames --frames 2 --finish-each-pass");
    EXPECT_EQ(timings["passes"].size(), 14u);
    for (const auto& pass : timings["passes"]) {
        const double gpu = pass["gpu_ms"].get<double>(), cpu = pass["cpu_ms"].get<double>();
        EXPECT_LE(gpu, cpu * 1.05 + 0.5) << pass["name"];
    }
}
