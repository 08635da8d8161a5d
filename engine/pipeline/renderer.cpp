#include "pipeline/renderer.hpp"

#include "core/error.hpp"
#include "gl/debug_group.hpp"
#include "render/pixel_samples.hpp"

namespace vct {

Renderer::Renderer(const Scene& scene, const RenderSettings& settings) {
    validateRenderSettingsForContext(settings);
    frame_.scene = &scene;
    frame_.settings = settings;
    frame_.lights = scene.lights;
    frame_.gpuScene = std::make_unique<GpuScene>(scene);
    createSizedTargets();
    gl::checkErrors("creating the renderer's GPU resources");
}

void Renderer::createSizedTargets() {
    const int width = frame_.settings.width, height = frame_.settings.height;
    frame_.gbuffer = std::make_unique<GBuffer>(width, height);
    frame_.direct = std::make_unique<DirectLighting>(width, height);
    frame_.composite = std::make_unique<Composite>(width, height);
    frame_.coneTrace.reset();
    frame_.voxelView.reset();
    frame_.coneView.reset();
}

void Renderer::setSettings(const RenderSettings& s) {
    validateRenderSettingsForContext(s);
    const RenderSettings old = frame_.settings;
    frame_.settings = s;
    if (s.width != old.width || s.height != old.height) {
        createSizedTargets();
        bump(Input::OutputSize);
    }
    if (s.voxelLevels != old.voxelLevels) bump(Input::VoxelSettings);
    if (photonMapResolution(s) != photonMapResolution(old) || s.shadowMapResolution != old.shadowMapResolution ||
        s.pcfRadius != old.pcfRadius)
        bump(Input::ShadowSettings);
    if (s.photons != old.photons) bump(Input::PhotonSettings);
    if (s.bounces != old.bounces) bump(Input::BounceSettings);
    if (voxelGatherCones(s.cones) != voxelGatherCones(old.cones) || s.bricks != old.bricks) bump(Input::ConeSettings);
    if (s.cones != old.cones) bump(Input::PixelCones);
    if (s.giResolution != old.giResolution) bump(Input::GiResolution);
    if (s.giFilter != old.giFilter) bump(Input::GiFilter);
    if (s.display != old.display || s.gi != old.gi) bump(Input::DisplaySettings);
    if (s.view != old.view || s.voxelViewLevel != old.voxelViewLevel || s.bricks != old.bricks)
        bump(Input::ViewSettings);
}

void Renderer::setDisplay(const DisplaySettings& display) {
    RenderSettings s = frame_.settings;
    s.display = display;
    setSettings(s);
}

void Renderer::setLights(const std::vector<Light>& lights) {
    for (std::size_t i = 0; i < lights.size(); ++i) validateLight(lights[i], concat("light ", i));
    std::vector<Light> normalized = lights;
    for (Light& l : normalized) l.direction = glm::normalize(l.direction);
    if (normalized != frame_.lights) bump(Input::Lights);
    frame_.lights = std::move(normalized);
}

void Renderer::setMaterial(std::size_t index, const Material& material) {
    if (index >= frame_.scene->materials.size())
        fail("material ", index, " does not exist; the scene has ", frame_.scene->materials.size());
    frame_.gpuScene->setMaterial(index, material);
    bump(Input::Materials);
}

void Renderer::setScene(const Scene& scene) {
    frame_.scene = &scene;
    frame_.gpuScene = std::make_unique<GpuScene>(scene);
    frame_.lights = scene.lights;
    frame_.lightViews.clear();
    frame_.svo.reset();
    frame_.radiance.reset();
    bump(Input::Geometry);
    bump(Input::Materials);
    bump(Input::Lights);
}

void Renderer::renderFrame(const Camera& camera, int sample) {
    validateCamera(camera);
    if (sample < 0) fail("sample index ", sample, " is negative; samples count from 0 (the pixel centre)");
    const bool othersUnchanged = frame_.versions == versionsAfterLastFrame_ && samplesInOutput_ > 0;
    const bool sameCamera = lastCamera_ == camera;
    const bool continues = othersUnchanged && sameCamera && sample == lastSample_ + 1;
    timer_.beginFrame();
    // Light carried over a camera move is the last frames' estimate (render/cone_carry.hpp): an
    // image that goes on to average samples at rest first traces its first sample again, anew (a
    // new version of the pixels' cones carries nothing and re-runs only cone_trace and composite,
    // on the G-buffer sample 0 left), so that what it converges to does not depend on how the
    // camera got there.
    if (continues && lastSample_ == 0 && frame_.coneTrace && frame_.coneTrace->carried()) {
        bump(Input::PixelCones);
        samplesInOutput_ = 1;
        execute(camera, {Resource::Output}, 0);
    }
    if (!sameCamera || sample != lastSample_) {
        bump(Input::Camera);
        samplesInOutput_ = continues ? samplesInOutput_ + 1 : 1;
    } else if (!othersUnchanged) {
        samplesInOutput_ = 1;  // the same sample again, but something else changed: a fresh average
    }
    lastCamera_ = camera;
    lastSample_ = sample;
    // With fullFrames every image is built from scratch; its further samples re-run only the
    // camera's passes, as after any other change.
    if (frame_.settings.fullFrames && !continues) bump(Input::Geometry);
    execute(camera, {Resource::Output}, sample);
    timer_.endFrame();
    gl::checkErrors("rendering a frame");
    versionsAfterLastFrame_ = frame_.versions;
}

void Renderer::buildOctree() { run(std::nullopt, {Resource::GeometryBricks}, frame_.settings.fullFrames); }

void Renderer::run(const std::optional<Camera>& camera, ResourceSet targets, bool everyPass) {
    if (everyPass) bump(Input::Geometry);
    timer_.beginFrame();
    execute(camera, targets, 0);
    timer_.endFrame();
    gl::checkErrors("rendering a frame");
}

void Renderer::execute(const std::optional<Camera>& camera, ResourceSet targets, int sample) {
    FrameView view;
    if (camera) {
        view.camera = &*camera;
        view.transform = cameraView(*camera, *frame_.scene, frame_.settings.width, frame_.settings.height,
                                    pixelSampleOffset(sample));
        view.sample = sample;
        view.samplesInAverage = samplesInOutput_;
    }
    const std::vector<PassRun> plan = graph_.plan(frame_.versions, frame_.settings, targets);
    for (const PassRun& pass : plan) {
        if (!pass.ran) continue;
        gl::DebugGroup group(pass.name);
        gl::GpuTimer::Scope scope(timer_, pass.name);
        declaration(pass.pass).run(frame_, view);
    }
    graph_.commit(plan, frame_.versions);
    lastFrame_ = plan;
}

const FrameStatistics& Renderer::statistics() const {
    if (frame_.coneStatisticsPending && frame_.coneTrace) {
        frame_.statistics.cones = frame_.coneTrace->statistics();
        frame_.coneStatisticsPending = false;
    }
    return frame_.statistics;
}

std::vector<MemoryPool> Renderer::memory() const {
    std::vector<MemoryPool> pools = {{"scene geometry and textures", frame_.gpuScene->bytes()},
                                     {"gbuffer", frame_.gbuffer->bytes()},
                                     {"direct radiance", frame_.direct->bytes()},
                                     {"composite output", frame_.composite->bytes()},
                                     {"light-view maps", frame_.lightViews.bytes()}};
    if (frame_.svo) {
        const VoxelMemoryReport voxels = frame_.svo->memory();
        pools.push_back({"voxel fragment list", voxels.fragmentList});
        pools.push_back({"octree node pool", voxels.nodePool});
        pools.push_back({"octree neighbour links", voxels.neighbourLinks});
        pools.push_back({"octree voxel values", voxels.cells});
        pools.push_back({"brick pool", voxels.brickPools});
    }
    if (frame_.radiance)
        pools.push_back({"radiance volume (voxels, lists, six radiance pools)",
                         frame_.radiance->bytes()});
    if (frame_.bounces) pools.push_back({"first-bounce radiance and the bounce being gathered (further bounces)", frame_.bounces->bytes()});
    if (frame_.coneTrace) pools.push_back({"indirect irradiance", frame_.coneTrace->bytes()});
    if (frame_.voxelView) pools.push_back({"voxel view", frame_.voxelView->bytes()});
    if (frame_.coneView) pools.push_back({"cone view", frame_.coneView->bytes()});
    return pools;
}

}  // namespace vct
