#include "pipeline/renderer.hpp"

#include "core/error.hpp"

namespace vct {

ViewMode parseViewMode(const std::string& name) {
    if (name == "lit") return ViewMode::Lit;
    if (name == "voxels") return ViewMode::Voxels;
    if (name == "radiance") return ViewMode::Radiance;
    fail("unknown --view '", name, "'; use lit, voxels or radiance");
}

void validateRenderSettings(const RenderSettings& s) {
    GLint maxTexture = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int maxWidth = std::min(maxTexture, maxViewport[0]);
    const int maxHeight = std::min(maxTexture, maxViewport[1]);
    if (s.width < 1 || s.height < 1 || s.width > maxWidth || s.height > maxHeight)
        fail("image size ", s.width, "x", s.height, " is not possible on this GPU; width and height must be within 1..",
             maxWidth, " and 1..", maxHeight);
    if (s.lightViewResolution < 16 || s.lightViewResolution > maxTexture)
        fail("--light-view-res ", s.lightViewResolution, " is out of range; use 16..", maxTexture);
    if (s.pcfRadius < 0 || s.pcfRadius > 8) fail("--pcf-radius ", s.pcfRadius, " is out of range; use 0..8");
    if (s.voxelLevels < kMinVoxelLevels || s.voxelLevels > kMaxVoxelLevels)
        fail("--voxel-levels ", s.voxelLevels, " is out of range; use ", kMinVoxelLevels, "..", kMaxVoxelLevels);
    if (s.voxelViewLevel < 0 || s.voxelViewLevel > s.voxelLevels)
        fail("--voxel-level ", s.voxelViewLevel, " is out of range; use 1..", s.voxelLevels, " (", s.voxelLevels,
             " = the voxels themselves)");
    makeConeSet(s.cones.cones);  // throws for an unknown set
    if (!(s.cones.apertureScale > 0.0f && s.cones.apertureScale <= 4.0f))
        fail("--cone-aperture ", s.cones.apertureScale, " is out of range; use a factor in (0, 4]");
    if (!(s.cones.step >= 0.05f && s.cones.step <= 4.0f))
        fail("--cone-step ", s.cones.step, " is out of range; use 0.05..4 (fraction of the cone diameter)");
    if (!(s.cones.offset >= 0.0f && s.cones.offset <= 16.0f))
        fail("--cone-offset ", s.cones.offset, " is out of range; use 0..16 voxels");
    if (!std::isfinite(s.display.giScale) || s.display.giScale < 0.0f)
        fail("--gi-scale ", s.display.giScale, " must be a finite number ≥ 0");
}

namespace {
bool sameLight(const Light& a, const Light& b) {
    return a.type == b.type && a.position == b.position && a.direction == b.direction && a.color == b.color &&
           a.irradiance == b.irradiance && a.intensity == b.intensity && a.innerAngleDeg == b.innerAngleDeg &&
           a.outerAngleDeg == b.outerAngleDeg;
}
bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovYDeg == b.fovYDeg;
}
bool sameCones(const ConeSettings& a, const ConeSettings& b) {
    return a.cones == b.cones && a.apertureScale == b.apertureScale && a.step == b.step && a.offset == b.offset &&
           a.lift == b.lift && a.maxDistance == b.maxDistance;
}
bool sameDisplay(const DisplaySettings& a, const DisplaySettings& b) {
    return a.aov == b.aov && a.giScale == b.giScale && a.toneCurve == b.toneCurve && a.exposureEV == b.exposureEV;
}
}  // namespace

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : scene_(&scene), settings_((validateRenderSettings(settings), settings)), lights_(scene.lights) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth in [0,1] (render/view.hpp)
    gpuScene_ = std::make_unique<GpuScene>(scene);
    createSizedTargets();
    declarePasses();
    gl::checkErrors("creating the renderer's GPU resources");
}

// The passes and what they depend on (DESIGN §4), writers before readers.
void Renderer::declarePasses() {
    using I = Input;
    graph_.addPass("voxelize", {I::Geometry, I::VoxelSettings}, {}, {"fragments"});
    graph_.addPass("svo_build", {}, {"fragments"}, {"octree"});
    graph_.addPass("svo_leaves", {I::Materials}, {"fragments", "octree"}, {"voxels"});
    graph_.addPass("svo_neighbours", {}, {"octree"}, {"neighbours"});
    graph_.addPass("bricks", {}, {"voxels", "neighbours"}, {"leaf bricks"});
    graph_.addPass("bricks_mip", {}, {"leaf bricks"}, {"albedo bricks"});
    graph_.addPass("light_view", {I::Geometry, I::Materials, I::Lights, I::ShadowSettings}, {}, {"light-view maps"});
    graph_.addPass("inject", {I::PhotonSettings}, {"light-view maps", "voxels"}, {"voxel radiance"});
    graph_.addPass("radiance_mip", {}, {"voxel radiance"}, {"radiance partials"});
    graph_.addPass("radiance_border", {}, {"radiance partials", "neighbours"}, {"radiance bricks"});
    graph_.addPass("gbuffer", {I::Geometry, I::Materials, I::Camera, I::OutputSize}, {}, {"gbuffer"});
    graph_.addPass("direct_lighting", {I::Lights, I::ShadowSettings}, {"gbuffer", "light-view maps"}, {"direct"});
    graph_.addPass("cone_trace", {I::ConeSettings}, {"gbuffer", "radiance bricks", "albedo bricks"}, {"indirect"});
    graph_.addPass("voxel_view", {I::Camera, I::OutputSize, I::ViewSettings}, {"albedo bricks", "radiance bricks"},
                   {"debug image"});
    graph_.addPass("composite", {I::DisplaySettings, I::ViewSettings, I::OutputSize},
                   {"gbuffer", "direct", "indirect", "debug image"}, {"output"});
}

std::string Renderer::whyNotNeeded(const std::string& pass) const {
    const bool lit = settings_.view == ViewMode::Lit;
    if (pass == "voxelize" || pass == "svo_build" || pass == "svo_leaves" || pass == "svo_neighbours" ||
        pass == "bricks" || pass == "bricks_mip")
        return needsOctree() ? "" : "GI off and no voxel view";
    if (pass == "light_view") return lit || needsRadiance() ? "" : "the voxel view shows no light";
    if (pass == "inject" || pass == "radiance_mip" || pass == "radiance_border")
        return needsRadiance() ? "" : (lit ? "GI off" : "the voxel view shows albedo");
    if (pass == "gbuffer" || pass == "direct_lighting") return lit ? "" : "debug view";
    if (pass == "cone_trace") return !lit ? "debug view" : (settings_.gi ? "" : "GI off");
    if (pass == "voxel_view") return lit ? "lit view" : "";
    return "";
}

void Renderer::createSizedTargets() {
    gbuffer_ = std::make_unique<GBuffer>(settings_.width, settings_.height);
    direct_ = std::make_unique<DirectLighting>(settings_.width, settings_.height);
    composite_ = std::make_unique<Composite>(settings_.width, settings_.height);
    coneTrace_.reset();
    voxelView_.reset();
}

void Renderer::setSettings(const RenderSettings& s) {
    validateRenderSettings(s);
    const RenderSettings old = settings_;
    settings_ = s;
    if (s.width != old.width || s.height != old.height) {
        createSizedTargets();
        bump(Input::OutputSize);
    }
    if (s.voxelLevels != old.voxelLevels) bump(Input::VoxelSettings);
    if (s.lightViewResolution != old.lightViewResolution || s.pcfRadius != old.pcfRadius) {
        if (s.lightViewResolution != old.lightViewResolution) lightViews_.clear();
        bump(Input::ShadowSettings);
    }
    if (s.photons != old.photons) bump(Input::PhotonSettings);
    if (!sameCones(s.cones, old.cones) || s.bricks != old.bricks) bump(Input::ConeSettings);
    if (!sameDisplay(s.display, old.display) || s.gi != old.gi) bump(Input::DisplaySettings);
    if (s.view != old.view || s.voxelViewLevel != old.voxelViewLevel || s.bricks != old.bricks)
        bump(Input::ViewSettings);
}

void Renderer::setDisplay(const DisplaySettings& display) {
    RenderSettings s = settings_;
    s.display = display;
    setSettings(s);
}

void Renderer::setLights(const std::vector<Light>& lights) {
    for (std::size_t i = 0; i < lights.size(); ++i) validateLight(lights[i], concat("light ", i));
    const bool changed = lights.size() != lights_.size() ||
                         !std::equal(lights.begin(), lights.end(), lights_.begin(), sameLight);
    lights_ = lights;
    for (Light& l : lights_) l.direction = glm::normalize(l.direction);
    if (changed) bump(Input::Lights);
}

void Renderer::setMaterial(std::size_t index, const Material& material) {
    if (index >= scene_->materials.size())
        fail("material ", index, " does not exist; the scene has ", scene_->materials.size());
    gpuScene_->setMaterial(index, material);
    bump(Input::Materials);
}

void Renderer::setScene(const Scene& scene) {
    scene_ = &scene;
    gpuScene_ = std::make_unique<GpuScene>(scene);
    lights_ = scene.lights;
    lightViews_.clear();
    svo_.reset();
    radiance_.reset();
    bump(Input::Geometry);
    bump(Input::Materials);
    bump(Input::Lights);
}

void Renderer::renderFrame(const Camera& camera) {
    validateCamera(camera);
    if (!lastCamera_ || !sameCamera(*lastCamera_, camera)) bump(Input::Camera);
    lastCamera_ = camera;
    if (settings_.fullFrames) bump(Input::Geometry);
    const ViewTransform view = cameraView(camera, *scene_, settings_.width, settings_.height);
    const std::vector<PassRun> plan = graph_.plan(versions_, [this](const std::string& p) { return whyNotNeeded(p); });
    timer_.beginFrame();
    for (const PassRun& pass : plan) {
        if (!pass.ran) continue;
        gl::GpuTimer::Scope scope(timer_, pass.name);
        runPass(pass.name, camera, view);
    }
    timer_.endFrame();
    graph_.commit(plan, versions_);
    lastFrame_ = plan;
    gl::checkErrors("rendering a frame");
}

void Renderer::runPass(const std::string& pass, const Camera& camera, const ViewTransform& view) {
    const Scene& scene = *scene_;
    if (pass == "voxelize") {
        if (!svo_) svo_ = std::make_unique<SvoBuilder>();
        svo_->voxelize(*gpuScene_, scene, settings_.voxelLevels);
    } else if (pass == "svo_build") {
        svo_->buildStructure();
        radiance_.reset();  // sized for the previous octree
    } else if (pass == "svo_leaves") {
        svo_->leaves(*gpuScene_);
    } else if (pass == "svo_neighbours") {
        svo_->neighbours();
    } else if (pass == "bricks") {
        svo_->bricks();
    } else if (pass == "bricks_mip") {
        svo_->bricksMip();
    } else if (pass == "light_view") {
        // Only maps whose light changed are rendered again (all of them when the geometry,
        // materials or shadow settings changed).
        const std::uint64_t inputs = versions_[std::size_t(Input::Geometry)] * 1000003u +
                                     versions_[std::size_t(Input::Materials)] * 1009u +
                                     versions_[std::size_t(Input::ShadowSettings)];
        if (inputs != lightViewInputsSeen_ || lightViews_.size() != lights_.size()) {
            lightViews_.clear();
            lightViewRendered_.assign(lights_.size(), std::nullopt);
            for (std::size_t i = 0; i < lights_.size(); ++i) lightViews_.emplace_back(settings_.lightViewResolution);
            lightViewInputsSeen_ = inputs;
        }
        statistics_.lightViewsRendered = 0;
        statistics_.lightViewsTotal = std::uint32_t(lights_.size());
        for (std::size_t i = 0; i < lights_.size(); ++i) {
            if (lightViewRendered_[i] && sameLight(*lightViewRendered_[i], lights_[i])) continue;
            lightViews_[i].render(*gpuScene_, scene, lights_[i]);
            lightViewRendered_[i] = lights_[i];
            ++statistics_.lightViewsRendered;
        }
    } else if (pass == "inject") {
        if (!radiance_) {
            radiance_ = std::make_unique<RadianceVolume>();
            allocateRadianceVolume(svo_->octree(), *radiance_);
        }
        if (!injection_) injection_ = std::make_unique<PhotonInjection>();
        injection_->run(svo_->octree(), *radiance_, scene, lights_, lightViews_, settings_.photons);
    } else if (pass == "radiance_mip") {
        if (!radianceFilter_) radianceFilter_ = std::make_unique<RadianceFilter>();
        radianceFilter_->mip(svo_->octree(), *radiance_);
    } else if (pass == "radiance_border") {
        radianceFilter_->border(svo_->octree(), *radiance_);
        const RadianceStatistics r = readRadianceStatistics(svo_->octree(), *radiance_);
        statistics_.touchedNodesPerLevel = r.touchedPerLevel;
        statistics_.photonsMissed = r.photonsMissed;
        statistics_.nodesPerLevel.assign(svo_->octree().levelCount.begin(),
                                         svo_->octree().levelCount.begin() + svo_->octree().levels + 1);
    } else if (pass == "gbuffer") {
        gbuffer_->render(*gpuScene_, view);
    } else if (pass == "direct_lighting") {
        direct_->render(*gbuffer_, scene, lights_, lightViews_, settings_.pcfRadius);
    } else if (pass == "cone_trace") {
        if (!coneTrace_) coneTrace_ = std::make_unique<ConeTrace>(settings_.width, settings_.height);
        ConeSettings cones = settings_.cones;
        cones.bricks = settings_.bricks;
        coneTrace_->render(*gbuffer_, svo_->octree(), *radiance_, cones);
        statistics_.cones = coneTrace_->statistics();
    } else if (pass == "voxel_view") {
        if (!voxelView_) voxelView_ = std::make_unique<VoxelView>(settings_.width, settings_.height);
        const int level = settings_.voxelViewLevel ? settings_.voxelViewLevel : settings_.voxelLevels;
        const VoxelView::Source source =
            settings_.view == ViewMode::Radiance
                ? VoxelView::Source{radiance_->brickRadiance.id(), radiance_->cellRadiance.id(), radiance_->rawRadiance.id(), true}
                : VoxelView::albedo(svo_->octree());
        voxelView_->render(svo_->octree(), source, camera, scene, level, settings_.bricks);
    } else if (pass == "composite") {
        if (settings_.view != ViewMode::Lit) {
            composite_->render(*gbuffer_, direct_->radiance(), 0, view, 1.0f, settings_.display, voxelView_->image(),
                               settings_.view == ViewMode::Radiance);
        } else {
            const GLuint indirect = settings_.gi && coneTrace_ ? coneTrace_->indirect() : 0;
            const float depthScale = float(glm::length(scene.worldBounds.size()));
            composite_->render(*gbuffer_, direct_->radiance(), indirect, view, depthScale, settings_.display);
        }
    } else {
        fail("unknown pass '", pass, "' (engine bug)");
    }
}

std::vector<MemoryPool> Renderer::memory() const {
    std::vector<MemoryPool> pools = {{"scene geometry and textures", gpuScene_->bytes()},
                                     {"gbuffer", gbuffer_->bytes()},
                                     {"direct radiance", direct_->bytes()},
                                     {"composite output", composite_->bytes()}};
    std::size_t lightBytes = 0;
    for (const auto& map : lightViews_) lightBytes += map.bytes();
    pools.push_back({"light-view maps", lightBytes});
    if (svo_) {
        const VoxelMemoryReport voxels = svo_->memory();
        pools.push_back({"voxel fragment list", voxels.fragmentList});
        pools.push_back({"octree node pool", voxels.nodePool});
        pools.push_back({"octree neighbour links", voxels.neighbourLinks});
        pools.push_back({"octree voxel values", voxels.cells});
        pools.push_back({"brick pool", voxels.brickPools});
    }
    if (radiance_) pools.push_back({"radiance volume (voxels, lists, partial and complete bricks)", radiance_->bytes(svo_->octree())});
    if (coneTrace_) pools.push_back({"indirect irradiance", coneTrace_->bytes()});
    if (voxelView_) pools.push_back({"voxel view", voxelView_->bytes()});
    return pools;
}

}  // namespace vct
