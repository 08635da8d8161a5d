// `--view cones` (render/cone_view): one cone per pixel from the eye, as wide as the cone set's cap
// or as a narrow cone, marched as the cones that gather indirect light march. What it sees of a
// uniformly lit surface must be that surface's radiance (the direct AOV of the same camera), and
// of the dark side of a lit wall nothing.
#include <cstdio>

#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// Mean luminance over the central window of an image (a quarter of each side cut off).
double centralMean(const ImageF& image) {
    double sum = 0.0;
    int n = 0;
    for (int y = image.height / 4; y < image.height * 3 / 4; ++y)
        for (int x = image.width / 4; x < image.width * 3 / 4; ++x) {
            const float* p = image.at(x, y);
            sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            ++n;
        }
    return sum / n;
}

Camera lookingAt(glm::dvec3 eye, glm::dvec3 target) {
    Camera camera;
    camera.eye = eye;
    camera.target = target;
    camera.up = {0.0, 1.0, 0.0};
    camera.fovYDeg = 40.0;
    return camera;
}

// The central mean of a debug view (`view`: the cones by default) and of the direct AOV seen by
// `camera`.
std::pair<double, double> coneViewAndDirect(Renderer& renderer, const Camera& camera, ViewMode view = ViewMode::Cones) {
    RenderSettings s = renderer.settings();
    s.view = view;
    renderer.setSettings(s);
    renderer.renderFrame(camera);
    const double cones = centralMean(renderer.readHdr());
    s.view = ViewMode::Lit;
    s.display.aov = Aov::Direct;
    renderer.setSettings(s);
    renderer.renderFrame(camera);
    return {cones, centralMean(renderer.readHdr())};
}

RenderSettings smallSettings(int narrowCones) {
    RenderSettings s;
    s.width = 64;
    s.height = 48;
    s.voxelLevels = 6;
    s.cones.rays = narrowCones;
    return s;
}

// A wall of no thickness, 4 × 3 m in the plane z = 0, lit by a sun on its +z side only.
Scene wallLitOnOneSide(const std::filesystem::path& dir) {
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.5f));
    obj.quad({-2.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {2.0f, 3.0f, 0.0f}, {-2.0f, 3.0f, 0.0f});
    Scene scene = loadModelFile(obj.write(dir));
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.0, -0.5, -1.0));
    sun.irradiance = 4.0;
    scene.lights = {sun};
    return scene;
}

// The cone set's cap (0) and a narrow cone (1).
class WhatACone : public ::testing::TestWithParam<int> {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(ConeView, WhatACone, ::testing::Values(0, 1),
                         [](const ::testing::TestParamInfo<int>& info) { return info.param ? "Narrow" : "CapOfTheSet"; });

TEST_P(WhatACone, SeesALitFloorAtItsRadiance) {
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.5f));
    obj.floor(0.0f, 4.0f);
    Scene scene = loadModelFile(obj.write(dir));
    Light sun;
    sun.direction = {0.0, -1.0, 0.0};
    sun.irradiance = 4.0;
    scene.lights = {sun};
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(scene, smallSettings(GetParam()));
    const auto [cones, direct] = coneViewAndDirect(renderer, lookingAt({0.0, 2.0, 3.0}, {0.0, 0.0, 0.0}));
    std::printf("[ cone view] %s, lit floor: cones see %.4f, its radiance %.4f (%.3fx)\n", GetParam() ? "narrow" : "cap",
                cones, direct, cones / direct);
    EXPECT_NEAR(direct, 0.5 / 3.14159265 * 4.0, 0.01);
    EXPECT_NEAR(cones / direct, 1.0, 0.1);
}

TEST_P(WhatACone, SeesNothingOfALitWallFromItsDarkSide) {
    Scene scene = wallLitOnOneSide(test::testDir());
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(scene, smallSettings(GetParam()));
    const auto [litCones, litDirect] = coneViewAndDirect(renderer, lookingAt({0.0, 1.5, 1.2}, {0.0, 1.5, 0.0}));
    const auto [darkCones, darkDirect] = coneViewAndDirect(renderer, lookingAt({0.0, 1.5, -1.2}, {0.0, 1.5, 0.0}));
    std::printf("[ cone view] %s, wall: lit side %.4f (radiance %.4f), dark side %.5f (%.2f %% of the lit side)\n",
                GetParam() ? "narrow" : "cap", litCones, litDirect, darkCones, 100.0 * darkCones / litDirect);
    EXPECT_NEAR(litCones / litDirect, 1.0, 0.1);
    EXPECT_EQ(darkDirect, 0.0);
    EXPECT_LT(darkCones, 0.02 * litDirect);
}

// The voxel radiance view at the voxels' level shows the light a voxel sends towards the eye, as
// the cones see it: a wall of no thickness lit on one side holds its light in voxels that hold
// both of its sides, and must look lit from that side only (its mean radiance is that side's).
TEST(VoxelRadianceView, ShowsALitWallOnlyFromItsLitSide) {
    Scene scene = wallLitOnOneSide(test::testDir());
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(scene, smallSettings(0));
    const auto [lit, litDirect] = coneViewAndDirect(renderer, lookingAt({0.0, 1.5, 1.2}, {0.0, 1.5, 0.0}), ViewMode::Radiance);
    const auto [dark, darkDirect] = coneViewAndDirect(renderer, lookingAt({0.0, 1.5, -1.2}, {0.0, 1.5, 0.0}), ViewMode::Radiance);
    std::printf("[ voxel view] radiance of a wall: lit side %.4f (direct %.4f), dark side %.5f\n", lit, litDirect, dark);
    EXPECT_NEAR(lit / litDirect, 1.0, 0.1);
    EXPECT_EQ(darkDirect, 0.0);
    EXPECT_LT(dark, 0.02 * litDirect);
}

TEST(VoxelRadianceView, ShowsTheFurtherBouncesAtEveryLevel) {
    // After the bounce pass the bricks hold every bounce, and so must the voxels the view shows
    // (RadianceVolume::seenCellRadiance); the voxels once showed the first bounce only, beside
    // coarser levels that showed them all. The Cornell box at 64³: a second bounce lights its
    // walls by about half as much again, at the voxels as at the level above them.
    auto context = gl::createContext(gl::defaultBackend());
    const Scene cornell = makeCornellBox();
    Renderer renderer(cornell, smallSettings(0));
    const Camera camera = lookingAt({0.0, 1.0, 3.4}, {0.0, 1.0, 0.0});
    auto viewMean = [&](int level, int bounces) {
        RenderSettings s = renderer.settings();
        s.view = ViewMode::Radiance;
        s.voxelViewLevel = level;
        s.bounces = bounces;
        renderer.setSettings(s);
        renderer.renderFrame(camera);
        return centralMean(renderer.readHdr());
    };
    const int voxels = renderer.settings().voxelLevels, above = voxels - 1;
    const double voxelOne = viewMean(voxels, 1), voxelTwo = viewMean(voxels, 2);
    const double aboveOne = viewMean(above, 1), aboveTwo = viewMean(above, 2);
    const double voxelGain = voxelTwo / voxelOne, aboveGain = aboveTwo / aboveOne;
    std::printf("[ voxel view] Cornell, second bounce: the voxels' radiance %.3fx, the level above %.3fx\n", voxelGain,
                aboveGain);
    EXPECT_GT(voxelGain, 1.2);
    EXPECT_NEAR(voxelGain / aboveGain, 1.0, 0.15);
}
