// The frame graph: exactly which passes each kind of change re-runs, and that frames produced
// incrementally are bit-identical to frames rendered from scratch in the same final state.
#include <set>

#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "render/cone_trace.hpp"
#include "scene/scene_loader.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

using Names = std::set<Pass>;

Names ran(const Renderer& renderer) {
    Names names;
    for (const PassRun& p : renderer.lastFrame())
        if (p.ran) names.insert(p.pass);
    return names;
}

RenderSettings smallSettings() {
    RenderSettings s;
    s.width = 48;
    s.height = 36;
    s.voxelLevels = 5;
    s.lightViewResolution = 256;
    return s;
}

const Names kEverything = {Pass::Voxelize, Pass::SvoBuild, Pass::SvoLeaves, Pass::SvoNeighbours, Pass::Bricks, Pass::BricksMip,
                           Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::GBuffer, Pass::DirectLighting,
                           Pass::ConeTrace, Pass::Composite};

Camera moved(Camera c) {
    c.eye += glm::dvec3(0.1, 0.0, 0.0);
    return c;
}

std::vector<Light> turned(std::vector<Light> lights) {
    lights[0].position += glm::dvec3(0.2, 0.0, 0.0);
    return lights;
}

}  // namespace

class PassGraphTest : public ::testing::Test {
protected:
    void SetUp() override { context_ = gl::createContext(gl::defaultBackend()); }
    std::unique_ptr<gl::Context> context_;
    Scene scene_ = makeCornellBox();
};

TEST_F(PassGraphTest, EachChangeRerunsExactlyItsDependentPasses) {
    Renderer renderer(scene_, smallSettings());
    const Camera camera = scene_.cameras[0];
    renderer.renderFrame(camera);
    EXPECT_EQ(ran(renderer), kEverything) << "first frame";

    renderer.renderFrame(camera);
    EXPECT_EQ(ran(renderer), Names{}) << "nothing changed: no GPU work";

    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::GBuffer, Pass::DirectLighting, Pass::ConeTrace, Pass::Composite})) << "camera moved";

    renderer.setLights(turned(renderer.lights()));
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::DirectLighting,
                                    Pass::ConeTrace, Pass::Composite}))
        << "light moved";

    std::vector<Light> brighter = renderer.lights();
    brighter[0].intensity *= 2.0;
    renderer.setLights(brighter);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::DirectLighting,
                                    Pass::ConeTrace, Pass::Composite}))
        << "light intensity changed";

    Material red = scene_.materials[0];
    red.baseColor = {0.9f, 0.1f, 0.1f};
    renderer.setMaterial(0, red);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::SvoLeaves, Pass::Bricks, Pass::BricksMip, Pass::LightView, Pass::Inject, Pass::RadianceLeaves,
                                    Pass::RadianceMip, Pass::GBuffer, Pass::DirectLighting, Pass::ConeTrace, Pass::Composite}))
        << "a material's colour changed";

    RenderSettings s = renderer.settings();
    s.cones.cones = 9;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "cone settings";

    s.cones.reuseVoxels = 0.0f;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "cones shared between neighbours";

    s.giResolution = GiResolution::Full;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "GI resolution";

    s.display.exposureEV += 1.0;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::Composite})) << "exposure";

    s.voxelLevels = 6;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::Voxelize, Pass::SvoBuild, Pass::SvoLeaves, Pass::SvoNeighbours, Pass::Bricks, Pass::BricksMip,
                                    Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::ConeTrace, Pass::Composite}))
        << "voxel levels";

    s.gi = false;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::Composite})) << "GI off: only the composite changes";
    for (const PassRun& p : renderer.lastFrame())
        if (p.pass == Pass::ConeTrace) EXPECT_EQ(p.reason, "not needed: GI off");

    const Scene other = makeCornellBox();
    s.gi = true;
    renderer.setSettings(s);
    renderer.setScene(other);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), kEverything) << "geometry changed";
}

TEST_F(PassGraphTest, OnlyTheChangedLightsMapIsRenderedAgain) {
    Scene twoLights = scene_;
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    sun.irradiance = 1.0;
    twoLights.lights.push_back(sun);
    Renderer renderer(twoLights, smallSettings());
    renderer.renderFrame(twoLights.cameras[0]);
    EXPECT_EQ(renderer.statistics().lightViewsRendered, 2u);
    std::vector<Light> lights = renderer.lights();
    lights[1].irradiance = 2.0;
    renderer.setLights(lights);
    renderer.renderFrame(twoLights.cameras[0]);
    EXPECT_EQ(renderer.statistics().lightViewsRendered, 1u);
    EXPECT_EQ(renderer.statistics().lightViewsTotal, 2u);
}

TEST_F(PassGraphTest, AMovedPointLightRendersItsSixFacesAndNoOctreePass) {
    Scene lit = scene_;
    Light point;
    point.type = LightType::Point;
    point.position = {0.1, 1.4, 0.2};
    point.intensity = 3.0;
    lit.lights.push_back(point);  // beside the box's spot
    Renderer renderer(lit, smallSettings());
    const Camera camera = lit.cameras[0];
    renderer.renderFrame(camera);
    EXPECT_EQ(renderer.statistics().lightViewsTotal, 7u);  // the spot's map and the point light's cube
    EXPECT_EQ(renderer.statistics().lightViewsRendered, 7u);

    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::GBuffer, Pass::DirectLighting, Pass::ConeTrace, Pass::Composite})) << "camera moved";

    std::vector<Light> lights = renderer.lights();
    lights[1].position.x += 0.2;
    renderer.setLights(lights);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::DirectLighting,
                                    Pass::ConeTrace, Pass::Composite}))
        << "point light moved";
    EXPECT_EQ(renderer.statistics().lightViewsRendered, 6u) << "only the point light's six faces";

    lights[1].type = LightType::Spot;  // a cube of maps becomes one map
    renderer.setLights(lights);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(renderer.statistics().lightViewsRendered, 1u);
    EXPECT_EQ(renderer.statistics().lightViewsTotal, 2u);
}

TEST_F(PassGraphTest, PixelSamplesRerunOnlyTheCameraPassesAndAverage) {
    Renderer renderer(scene_, smallSettings());
    const Camera camera = scene_.cameras[0];
    renderer.renderFrame(camera, 0);
    EXPECT_EQ(renderer.samplesInOutput(), 1);
    renderer.renderFrame(camera, 1);
    EXPECT_EQ(ran(renderer), (Names{Pass::GBuffer, Pass::DirectLighting, Pass::ConeTrace, Pass::Composite}))
        << "a new sample re-runs the camera's passes and nothing that lights or builds the octree";
    EXPECT_EQ(renderer.samplesInOutput(), 2);
    const ImageF averaged = renderer.readHdr();
    renderer.renderFrame(camera, 1);
    EXPECT_EQ(ran(renderer), Names{}) << "the same sample again: nothing to do";
    EXPECT_EQ(renderer.samplesInOutput(), 2);

    // The output is the mean of the samples: sample 1 alone (a fresh average) and the centre. Their
    // direct light counts alike, their indirect light by the narrow cones each traced (four at the
    // centre, one after it); seen AOV by AOV, each is that mean.
    const ConeSettings cones = renderer.settings().cones;
    const double centreWeight = indirectWeightOfSample(cones, 0), laterWeight = indirectWeightOfSample(cones, 1);
    EXPECT_EQ(centreWeight, double(cones.rays));
    EXPECT_EQ(laterWeight, 1.0);
    for (Aov aov : {Aov::Direct, Aov::Gi}) {
        RenderSettings s = smallSettings();
        s.display.aov = aov;
        Renderer both(scene_, s), single(scene_, s);
        both.renderFrame(camera, 0);
        const ImageF centreAov = both.readHdr();
        both.renderFrame(camera, 1);
        const ImageF averaged = both.readHdr();
        single.renderFrame(camera, 1);
        EXPECT_EQ(single.samplesInOutput(), 1);
        const ImageF jittered = single.readHdr();
        const double w = aov == Aov::Gi ? centreWeight / (centreWeight + laterWeight) : 0.5;
        double largest = 0.0, differs = 0.0;
        for (std::size_t i = 0; i < averaged.rgba.size(); ++i) {
            const double mean = w * double(centreAov.rgba[i]) + (1.0 - w) * double(jittered.rgba[i]);
            largest = std::max(largest, std::abs(double(averaged.rgba[i]) - mean));
            differs = std::max(differs, std::abs(double(centreAov.rgba[i]) - double(jittered.rgba[i])));
        }
        EXPECT_LE(largest, 1e-6) << aovName(aov);
        EXPECT_GT(differs, 1e-3) << aovName(aov) << ": sample 1 must look at another point of the pixel than sample 0";
    }
    // The final image adds the two.
    {
        RenderSettings s = smallSettings();
        s.display.aov = Aov::Direct;
        Renderer direct(scene_, s);
        s.display.aov = Aov::Gi;
        Renderer gi(scene_, s);
        for (int sample : {0, 1}) {
            direct.renderFrame(camera, sample);
            gi.renderFrame(camera, sample);
        }
        const ImageF d = direct.readHdr(), g = gi.readHdr();
        double largest = 0.0;
        for (std::size_t i = 0; i < averaged.rgba.size(); ++i)
            if (i % 4 != 3)
                largest = std::max(largest, std::abs(double(averaged.rgba[i]) - double(d.rgba[i]) - double(g.rgba[i])));
        EXPECT_LE(largest, 1e-6) << "final = direct + indirect, each averaged";
    }

    // Any other change starts a new average; so does a camera move.
    RenderSettings s = renderer.settings();
    s.display.exposureEV += 1.0;
    renderer.setSettings(s);
    renderer.renderFrame(camera, 2);
    EXPECT_EQ(renderer.samplesInOutput(), 1);
    renderer.renderFrame(camera, 3);
    EXPECT_EQ(renderer.samplesInOutput(), 2);
    renderer.renderFrame(moved(camera), 4);
    EXPECT_EQ(renderer.samplesInOutput(), 1);
}

TEST_F(PassGraphTest, BouncesFollowTheLightsAndTheirCountNeverTheCamera) {
    RenderSettings s = smallSettings();
    s.bounces = 2;
    Renderer renderer(scene_, s);
    const Camera camera = scene_.cameras[0];
    renderer.renderFrame(camera);
    Names everything = kEverything;
    everything.insert(Pass::Bounce);
    EXPECT_EQ(ran(renderer), everything) << "first frame";
    EXPECT_EQ(renderer.statistics().bouncesGathered, 1u);

    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::GBuffer, Pass::DirectLighting, Pass::ConeTrace, Pass::Composite}))
        << "camera moved: no bounce is gathered again";

    renderer.setLights(turned(renderer.lights()));
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::LightView, Pass::Inject, Pass::RadianceLeaves, Pass::RadianceMip, Pass::Bounce,
                                    Pass::DirectLighting, Pass::ConeTrace, Pass::Composite}))
        << "light moved";

    s.bounces = 3;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::RadianceLeaves, Pass::RadianceMip, Pass::Bounce, Pass::ConeTrace, Pass::Composite}))
        << "one more bounce: back to one bounce, then gathered again";
    EXPECT_EQ(renderer.statistics().bouncesGathered, 2u);
    const ImageF threeBounces = renderer.readHdr();

    s.giResolution = GiResolution::Full;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "cones at every pixel: no bounce again";
    s.giResolution = GiResolution::Auto;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_TRUE(renderer.readHdr().rgba == threeBounces.rgba) << "back to the default resolution, as before";

    // What only the pixels trace: the voxels keep gathering with the cone set.
    s.cones.rays = 0;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "the cone set: no bounce again";
    s.cones.narrowConesAfterFirstSample = false;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "the cones of later samples: no bounce again";
    s.cones.reuseVoxels = 0.0f;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "cones shared or not: no bounce again";
    s.cones.nearField = false;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "the near field or not: no bounce again";
    s.cones.nearDetail = false;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::ConeTrace, Pass::Composite})) << "the near field's detail or not: no bounce again";
    s.cones.rays = kDefaultNarrowCones;
    s.cones.narrowConesAfterFirstSample = true;
    s.cones.reuseVoxels = kDefaultConeReuseVoxels;
    s.cones.nearField = true;
    s.cones.nearDetail = true;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_TRUE(renderer.readHdr().rgba == threeBounces.rgba) << "back to the narrow cones, as before";

    s.bounces = 1;
    renderer.setSettings(s);
    renderer.renderFrame(moved(camera));
    EXPECT_EQ(ran(renderer), (Names{Pass::RadianceLeaves, Pass::RadianceMip, Pass::ConeTrace, Pass::Composite}))
        << "back to one bounce";
    for (const PassRun& p : renderer.lastFrame())
        if (p.pass == Pass::Bounce) EXPECT_EQ(p.reason, "not needed: one bounce");

    // The same state rendered from scratch: the same image, whatever came before.
    Scene turnedScene = scene_;
    turnedScene.lights = turned(scene_.lights);
    for (int bounces : {1, 3}) {
        s.bounces = bounces;
        renderer.setSettings(s);
        renderer.renderFrame(moved(camera));
        Renderer fresh(turnedScene, s);
        fresh.renderFrame(moved(camera));
        EXPECT_TRUE(fresh.readHdr().rgba == renderer.readHdr().rgba) << bounces << " bounces";
    }
    EXPECT_TRUE(renderer.readHdr().rgba == threeBounces.rgba) << "3 bounces again, as before";
}

TEST_F(PassGraphTest, IncrementalFramesAreBitIdenticalToFreshOnes) {
    const Camera camera = scene_.cameras[0];
    Renderer incremental(scene_, smallSettings());
    incremental.renderFrame(camera);
    incremental.setLights(turned(incremental.lights()));
    incremental.renderFrame(moved(camera));
    Material red = scene_.materials[1];
    red.baseColor = {0.3f, 0.6f, 0.9f};
    incremental.setMaterial(1, red);
    incremental.renderFrame(moved(camera));
    const ImageF a = incremental.readHdr();

    Scene edited = scene_;
    edited.lights = turned(scene_.lights);
    edited.materials[1] = red;
    Renderer fresh(edited, smallSettings());
    fresh.renderFrame(moved(camera));
    const ImageF b = fresh.readHdr();
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t different = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) different += a.rgba[i] != b.rgba[i];
    EXPECT_EQ(different, 0u) << "values differ between the incremental and the fresh frame";
}

TEST_F(PassGraphTest, ChangingVoxelLevelsBackAndForthKeepsTheImageOfAFreshRender) {
    // The benchmark's path through settings: levels down, up, back, then a cone change.
    const Camera camera = scene_.cameras[0];
    RenderSettings s = smallSettings();
    Renderer incremental(scene_, s);
    incremental.renderFrame(camera);
    for (int levels : {6, 7, 5}) {
        s.voxelLevels = levels;
        incremental.setSettings(s);
        incremental.renderFrame(camera);
    }
    s.cones.cones = 9;
    incremental.setSettings(s);
    incremental.renderFrame(camera);
    const ImageF a = incremental.readHdr();
    Renderer fresh(scene_, s);
    fresh.renderFrame(camera);
    const ImageF b = fresh.readHdr();
    std::size_t different = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) different += a.rgba[i] != b.rgba[i];
    EXPECT_EQ(different, 0u);
}
// The benchmark's path through settings (full frames, direct AOV, nudged lights and camera, a level
// change and back, then a cone change): GI must be what a fresh renderer gives.
TEST_F(PassGraphTest, BenchmarkSequenceKeepsGi) {
    const Camera camera = scene_.cameras[0];
    RenderSettings base = smallSettings();
    Renderer r(scene_, base);
    r.renderFrame(camera);
    RenderSettings full = base; full.fullFrames = true;
    r.setSettings(full); r.renderFrame(camera);
    r.setSettings(base); r.renderFrame(camera);
    const std::vector<Light> lights = r.lights();
    std::vector<Light> nudged = lights; for (Light& l : nudged) { l.irradiance *= 1.0001; l.intensity *= 1.0001; }
    Camera nc = camera; nc.eye += (camera.target - camera.eye) * 1e-4;
    RenderSettings p = base; p.voxelLevels = 6;
    r.setSettings(p); r.renderFrame(camera);
    RenderSettings pd = p; pd.display.aov = Aov::Direct; r.setSettings(pd); r.renderFrame(camera);
    RenderSettings pf = p; pf.fullFrames = true; r.setSettings(pf); r.renderFrame(camera); r.renderFrame(camera);
    r.setSettings(p);
    for (int i = 0; i < 2; ++i) { r.setLights(i % 2 == 0 ? nudged : lights); r.renderFrame(i % 2 == 0 ? nc : camera); }
    r.setLights(lights);
    r.setSettings(base); r.renderFrame(camera);
    RenderSettings c = base; c.cones.cones = 1; c.display.aov = Aov::Indirect;
    r.setSettings(c); r.renderFrame(camera);
    const ImageF a = r.readHdr();
    Renderer fresh(scene_, c); fresh.renderFrame(camera);
    const ImageF b = fresh.readHdr();
    double sa = 0, sb = 0; for (std::size_t i = 0; i < a.rgba.size(); ++i) { sa += a.rgba[i]; sb += b.rgba[i]; }
    EXPECT_GT(sa, 0.0); EXPECT_NEAR(sa, sb, 1e-6 * sb) << sa << " vs " << sb;
}

// A new filtering clears only the bricks the last one lit (RadianceFilter::leaves): a narrow spot
// moved from the left wall to the right one must leave nothing of its old light behind, in the
// cones' image and in the octree's radiance view.
TEST_F(PassGraphTest, ASpotMovedAwayLeavesNoLightWhereItWas) {
    const Camera camera = scene_.cameras[0];
    Light spot = scene_.lights[0];
    spot.type = LightType::Spot;
    spot.position = {0.0, 1.8, 0.0};
    spot.innerAngleDeg = 10.0;
    spot.outerAngleDeg = 15.0;
    auto aimedAt = [&](double x) {
        Light l = spot;
        l.direction = glm::normalize(glm::dvec3(x, -0.6, -0.3));
        return std::vector<Light>{l};
    };
    for (ViewMode view : {ViewMode::Lit, ViewMode::Radiance}) {
        RenderSettings s = smallSettings();
        s.view = view;
        Renderer incremental(scene_, s);
        incremental.setLights(aimedAt(-1.0));
        incremental.renderFrame(camera);
        incremental.setLights(aimedAt(1.0));
        incremental.renderFrame(camera);
        EXPECT_EQ(ran(incremental).count(Pass::SvoBuild), 0u);
        Scene moved = scene_;
        moved.lights = aimedAt(1.0);
        Renderer fresh(moved, s);
        fresh.renderFrame(camera);
        EXPECT_TRUE(incremental.readHdr().rgba == fresh.readHdr().rgba) << "view " << int(view);
    }
}
