#include "pipeline/frame_passes.hpp"

#include "core/error.hpp"
#include "pipeline/frame_resources.hpp"
#include "render/pixel_samples.hpp"

namespace vct {

const char* inputName(Input input) {
    switch (input) {
        case Input::Geometry: return "geometry";
        case Input::Materials: return "materials";
        case Input::Lights: return "lights";
        case Input::Camera: return "camera";
        case Input::OutputSize: return "output size";
        case Input::VoxelSettings: return "voxel settings";
        case Input::ShadowSettings: return "shadow settings";
        case Input::PhotonSettings: return "photon settings";
        case Input::ConeSettings: return "cone settings";
        case Input::PixelCones: return "pixel cones";
        case Input::BounceSettings: return "bounce settings";
        case Input::GiResolution: return "GI resolution";
        case Input::GiFilter: return "GI filter";
        case Input::DisplaySettings: return "display settings";
        case Input::ViewSettings: return "view settings";
        case Input::Count: break;
    }
    return "?";
}

const char* resourceName(Resource resource) {
    switch (resource) {
        case Resource::Fragments: return "fragments";
        case Resource::Octree: return "octree";
        case Resource::CellValues: return "cell values";
        case Resource::Neighbours: return "neighbours";
        case Resource::LeafBricks: return "leaf bricks";
        case Resource::GeometryBricks: return "geometry bricks";
        case Resource::LightViewMaps: return "light-view maps";
        case Resource::CellRadiance: return "cell radiance";
        case Resource::LeafRadiance: return "leaf radiance";
        case Resource::RadianceBricks: return "radiance bricks";
        case Resource::BouncedRadiance: return "bounced radiance";
        case Resource::GBuffer: return "gbuffer";
        case Resource::DirectRadiance: return "direct radiance";
        case Resource::IndirectIrradiance: return "indirect irradiance";
        case Resource::DebugImage: return "debug image";
        case Resource::Output: return "output";
        case Resource::Count: break;
    }
    return "?";
}

const char* stageName(Stage stage) {
    switch (stage) {
        case Stage::Octree: return "octree";
        case Stage::Light: return "light";
        case Stage::Radiance: return "radiance";
        case Stage::Camera: return "camera";
        case Stage::Output: return "output";
        case Stage::Count: break;
    }
    return "?";
}

namespace {

// Why a frame with these settings does not need a pass (nullptr: it does).
const char* unlessOctree(const RenderSettings& s) { return needsOctree(s) ? nullptr : "GI off and no voxel view"; }
const char* unlessLightViews(const RenderSettings& s) {
    return s.view == ViewMode::Lit || needsRadiance(s) ? nullptr : "the voxel view shows no light";
}
const char* unlessRadiance(const RenderSettings& s) {
    if (needsRadiance(s)) return nullptr;
    return s.view == ViewMode::Lit ? "GI off" : "the voxel view shows albedo";
}
const char* unlessBounces(const RenderSettings& s) {
    if (const char* why = unlessRadiance(s)) return why;
    return s.bounces > 1 ? nullptr : "one bounce";
}
const char* unlessLitView(const RenderSettings& s) { return s.view == ViewMode::Lit ? nullptr : "debug view"; }
const char* unlessConeTrace(const RenderSettings& s) {
    if (s.view != ViewMode::Lit) return "debug view";
    return s.gi ? nullptr : "GI off";
}
const char* unlessVoxelView(const RenderSettings& s) { return s.view == ViewMode::Lit ? "lit view" : nullptr; }
const char* always(const RenderSettings&) { return nullptr; }

void renderLightViews(FrameResources& f) {
    const LightViewCache::Key key{f.version(Input::Geometry), f.version(Input::Materials),
                                  photonMapResolution(f.settings), f.settings.shadowMapResolution};
    f.statistics.lightViewsRendered = f.lightViews.update(*f.gpuScene, *f.scene, f.lights, key);
    f.statistics.lightViewsTotal = f.lightViews.mapCount();
}

void injectPhotons(FrameResources& f) {
    const Octree& octree = f.svo->octree();
    if (!f.radiance) f.radiance = std::make_unique<RadianceVolume>();
    if (f.radiance->octreeBuild != octree.geometryBricksBuild) fitRadianceVolume(octree, *f.radiance);
    if (!f.injection) f.injection = std::make_unique<PhotonInjection>();
    f.injection->run(octree, *f.radiance, *f.scene, f.lights, f.lightViews.views(), f.settings.photons);
}

void filterLeafRadiance(FrameResources& f) {
    const Octree& octree = f.svo->octree();
    if (!f.radianceFilter) f.radianceFilter = std::make_unique<RadianceFilter>();
    f.radianceFilter->leaves(octree, *f.radiance);
    const RadianceStatistics r = readRadianceStatistics(octree, *f.radiance);
    f.statistics.touchedNodesPerLevel = r.touchedPerLevel;
    f.statistics.photonsMissed = r.photonsMissed;
    f.statistics.nodesPerLevel.assign(octree.levelCount.begin(), octree.levelCount.begin() + octree.levels + 1);
}

// The cones of the frame: the cone settings with the frame's bricks on/off (one switch for cones
// and voxel views).
ConeSettings frameCones(const RenderSettings& s) {
    ConeSettings cones = s.cones;
    cones.bricks = s.bricks;
    return cones;
}

void gatherBounces(FrameResources& f) {
    if (!f.bounces) f.bounces = std::make_unique<BounceGather>();
    // The gather starts from one bounce: after an earlier run (other cone settings) the bricks hold
    // more, and the voxels still hold one, so filtering them again gives it back.
    if (f.radiance->bricksBounces != 1) {
        f.radianceFilter->leaves(f.svo->octree(), *f.radiance);
        f.radianceFilter->mip(f.svo->octree(), *f.radiance);
        f.radiance->bricksBounces = 1;
    }
    f.bounces->run(f.svo->octree(), *f.radiance, *f.radianceFilter, f.settings.bounces, frameCones(f.settings));
    f.radiance->bricksBounces = f.settings.bounces;
    f.statistics.bouncesGathered = std::uint32_t(f.settings.bounces - 1);
    f.statistics.bounceOwnGathers = f.bounces->ownGathers(*f.radiance);
}

// A number that changes whenever any input but the camera does: what the cones see and how they
// trace it (their traces carry over camera moves only while it stays the same: cone_carry.hpp).
// Every version only grows, so their sum does too.
std::uint64_t versionBesidesCamera(const FrameResources& f) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < kInputCount; ++i)
        if (Input(i) != Input::Camera) sum += f.versions[i];
    return sum;
}

void traceCones(FrameResources& f, const FrameView& v) {
    if (!f.coneTrace) f.coneTrace = std::make_unique<ConeTrace>(f.settings.width, f.settings.height);
    f.coneTrace->render(*f.gbuffer, f.svo->octree(), *f.radiance, frameCones(f.settings), f.settings.giResolution,
                        v.sample, f.settings.giFilter, v.transform, versionBesidesCamera(f), f.direct->radiance());
    f.coneStatisticsPending = true;
}

void renderVoxelView(FrameResources& f, const FrameView& v) {
    if (f.settings.view == ViewMode::Cones) {
        if (!f.coneView) f.coneView = std::make_unique<ConeView>(f.settings.width, f.settings.height);
        f.coneView->render(f.svo->octree(), *f.radiance, *v.camera, *f.scene, frameCones(f.settings));
        return;
    }
    if (!f.voxelView) f.voxelView = std::make_unique<VoxelView>(f.settings.width, f.settings.height);
    const int level = f.settings.voxelViewLevel ? f.settings.voxelViewLevel : f.settings.voxelLevels;
    const RadianceVolume* radiance = f.settings.view == ViewMode::Radiance ? f.radiance.get() : nullptr;
    f.voxelView->render(f.svo->octree(), radiance, *v.camera, *f.scene, level, f.settings.bricks);
}

void composite(FrameResources& f, const FrameView& v) {
    if (f.settings.view != ViewMode::Lit) {
        const GLuint debugImage = f.settings.view == ViewMode::Cones ? f.coneView->image() : f.voxelView->image();
        f.composite->render(*f.gbuffer, f.direct->radiance(), 0, v.transform, 1.0f, f.settings.display,
                            v.samplesInAverage, 1.0f, debugImage, f.settings.view != ViewMode::Voxels);
        return;
    }
    const GLuint indirect = f.settings.gi && f.coneTrace ? f.coneTrace->indirect() : 0;
    const float depthScale = float(glm::length(f.scene->worldBounds.size()));
    f.composite->render(*f.gbuffer, f.direct->radiance(), indirect, v.transform, depthScale, f.settings.display,
                        v.samplesInAverage, indirectWeightOfSample(frameCones(f.settings), v.sample));
}

using I = Input;
using R = Resource;

// clang-format off
const PassTable kFramePasses = {{
    {Pass::Voxelize, "voxelize", Stage::Octree,
     {I::Geometry, I::VoxelSettings}, {}, {R::Fragments}, unlessOctree,
     "voxelize.vert, voxelize.geom, voxelize.frag",
     [](FrameResources& f, const FrameView&) {
         if (!f.svo) f.svo = std::make_unique<SvoBuilder>();
         f.svo->voxelize(*f.gpuScene, *f.scene, f.settings.voxelLevels);
     }},
    {Pass::SvoBuild, "svo_build", Stage::Octree,
     {}, {R::Fragments}, {R::Octree}, unlessOctree,
     "svo_flag.comp, svo_alloc.comp, prefix_sum.comp, svo_init.comp, svo_descend.comp",
     [](FrameResources& f, const FrameView&) {
         f.svo->buildStructure();  // inject fits the radiance volume to it (fitRadianceVolume)
     }},
    {Pass::SvoLeaves, "svo_leaves", Stage::Octree,
     {I::Materials}, {R::Fragments, R::Octree}, {R::CellValues}, unlessOctree,
     "svo_leaves_accumulate.comp, svo_leaves_normalize.comp",
     [](FrameResources& f, const FrameView&) { f.svo->leaves(*f.gpuScene); }},
    {Pass::SvoNeighbours, "svo_neighbours", Stage::Octree,
     {}, {R::Octree}, {R::Neighbours}, unlessOctree,
     "svo_neighbours.comp",
     [](FrameResources& f, const FrameView&) { f.svo->neighbours(); }},
    {Pass::Bricks, "bricks", Stage::Octree,
     {}, {R::CellValues, R::Neighbours}, {R::LeafBricks}, unlessOctree,
     "bricks_leaf.comp, bricks_opacity.comp, bricks_complete.comp",
     [](FrameResources& f, const FrameView&) { f.svo->bricks(); }},
    {Pass::BricksMip, "bricks_mip", Stage::Octree,
     {}, {R::LeafBricks}, {R::GeometryBricks}, unlessOctree,
     "bricks_mip.comp, bricks_opacity.comp, bricks_share.comp, bricks_complete.comp",
     [](FrameResources& f, const FrameView&) { f.svo->bricksMip(); }},
    {Pass::LightView, "light_view", Stage::Light,
     {I::Geometry, I::Materials, I::Lights, I::ShadowSettings}, {}, {R::LightViewMaps}, unlessLightViews,
     "scene.vert, light_view.frag, shadow_depth.frag",
     [](FrameResources& f, const FrameView&) { renderLightViews(f); }},
    {Pass::Inject, "inject", Stage::Radiance,
     {I::PhotonSettings}, {R::LightViewMaps, R::CellValues}, {R::CellRadiance}, unlessRadiance,
     "inject.comp, inject_emissive.comp, radiance_normalize.comp",
     [](FrameResources& f, const FrameView&) { injectPhotons(f); }},
    {Pass::RadianceLeaves, "radiance_leaves", Stage::Radiance,
     {I::BounceSettings}, {R::CellValues, R::GeometryBricks, R::CellRadiance}, {R::LeafRadiance}, unlessRadiance,
     "border_age.comp, touch_parents.comp, touch_border.comp, radiance_clear.comp, radiance_leaves.comp",
     [](FrameResources& f, const FrameView&) { filterLeafRadiance(f); }},
    {Pass::RadianceMip, "radiance_mip", Stage::Radiance,
     {}, {R::LeafRadiance, R::GeometryBricks}, {R::RadianceBricks}, unlessRadiance,
     "radiance_mip.comp, radiance_share.comp",
     [](FrameResources& f, const FrameView&) {
         f.radianceFilter->mip(f.svo->octree(), *f.radiance);
         f.radiance->bricksBounces = 1;
     }},
    {Pass::Bounce, "bounce", Stage::Radiance,
     {I::BounceSettings, I::ConeSettings}, {R::RadianceBricks, R::CellValues, R::CellRadiance}, {R::BouncedRadiance},
     unlessBounces,
     "bounce_gather.comp, border_age.comp, touch_parents.comp, touch_border.comp, radiance_clear.comp, radiance_leaves.comp, "
     "radiance_mip.comp, radiance_share.comp",
     [](FrameResources& f, const FrameView&) { gatherBounces(f); }},
    {Pass::GBuffer, "gbuffer", Stage::Camera,
     {I::Geometry, I::Materials, I::Camera, I::OutputSize}, {}, {R::GBuffer}, unlessLitView,
     "scene.vert, gbuffer.frag",
     [](FrameResources& f, const FrameView& v) {
         f.gbuffer->render(*f.gpuScene, v.transform, pixelSampleFootprint(v.sample));
     }},
    {Pass::DirectLighting, "direct_lighting", Stage::Camera,
     {I::Lights, I::ShadowSettings}, {R::GBuffer, R::LightViewMaps}, {R::DirectRadiance}, unlessLitView,
     "direct_lighting.comp",
     [](FrameResources& f, const FrameView& v) {
         f.direct->render(*f.gbuffer, *f.scene, f.lights, f.lightViews.views(), f.settings.pcfRadius, v.transform,
                          v.sample);
     }},
    {Pass::ConeTrace, "cone_trace", Stage::Camera,
     {I::ConeSettings, I::PixelCones, I::GiResolution, I::GiFilter},
     {R::GBuffer, R::DirectRadiance, R::CellValues, R::CellRadiance, R::RadianceBricks, R::BouncedRadiance},
     {R::IndirectIrradiance}, unlessConeTrace,
     "cone_carry.comp, cone_trace.comp, cone_reuse.comp, indirect_filter.comp, cone_upsample.comp, near_detail.comp",
     traceCones},
    {Pass::VoxelView, "voxel_view", Stage::Camera,
     {I::Camera, I::OutputSize, I::ViewSettings, I::ConeSettings, I::PixelCones},
     {R::CellValues, R::GeometryBricks, R::CellRadiance, R::RadianceBricks, R::BouncedRadiance},
     {R::DebugImage},
     unlessVoxelView,
     "voxel_view.comp, cone_view.comp",
     renderVoxelView},
    {Pass::Composite, "composite", Stage::Output,
     {I::DisplaySettings, I::ViewSettings, I::OutputSize},
     {R::GBuffer, R::DirectRadiance, R::IndirectIrradiance, R::DebugImage}, {R::Output}, always,
     "composite.comp",
     composite},
}};
// clang-format on

// The table is indexed by Pass, and a pass reads only what an earlier pass writes.
bool tableIsConsistent() {
    ResourceSet written;
    for (std::size_t i = 0; i < kPassCount; ++i) {
        const PassDeclaration& d = kFramePasses[i];
        if (std::size_t(d.pass) != i) return false;
        bool readsUnwritten = false;
        d.reads.forEach([&](Resource r) { readsUnwritten |= !written.contains(r); });
        if (readsUnwritten) return false;
        written |= d.writes;
    }
    return true;
}

}  // namespace

const PassTable& framePasses() {
    static const bool consistent = tableIsConsistent();
    if (!consistent) fail("the frame's pass table is out of order (engine bug: engine/pipeline/frame_passes.cpp)");
    return kFramePasses;
}

}  // namespace vct
