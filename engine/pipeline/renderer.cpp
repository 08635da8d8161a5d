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

Renderer::Renderer(const Scene& scene, const RenderSettings& settings)
    : scene_(scene),
      settings_((validateRenderSettings(settings), settings)),
      gpuScene_(scene),
      gbuffer_(settings.width, settings.height),
      direct_(settings.width, settings.height),
      composite_(settings.width, settings.height) {
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed depth in [0,1] (render/view.hpp)
    for (std::size_t i = 0; i < scene.lights.size(); ++i) lightViews_.emplace_back(settings.lightViewResolution);
    gl::checkErrors("creating the renderer's GPU resources");
}

void Renderer::buildOctree() {
    if (!svo_) svo_ = std::make_unique<SvoBuilder>();
    svo_->build(gpuScene_, scene_, settings_.voxelLevels, timer_);
    radiance_.reset();  // sized for the previous octree
}

void Renderer::updateRadiance() {
    if (!radiance_) {
        radiance_ = std::make_unique<RadianceVolume>();
        allocateRadianceVolume(svo_->octree(), *radiance_);
    }
    if (!injection_) injection_ = std::make_unique<PhotonInjection>();
    if (!radianceFilter_) radianceFilter_ = std::make_unique<RadianceFilter>();
    const Octree& octree = svo_->octree();
    {
        gl::GpuTimer::Scope pass(timer_, "inject");
        injection_->run(octree, *radiance_, scene_, scene_.lights, lightViews_, settings_.photons);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "radiance_mip");
        radianceFilter_->mip(octree, *radiance_);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "radiance_border");
        radianceFilter_->border(octree, *radiance_);
    }
}

void Renderer::renderFrame(const Camera& camera) {
    const ViewTransform view = cameraView(camera, scene_, settings_.width, settings_.height);
    timer_.beginFrame();
    if (needsOctree() && (!svo_ || settings_.rebuildOctreeEveryFrame)) buildOctree();
    const bool lightsNeeded = settings_.view == ViewMode::Lit || needsRadiance();
    if (lightsNeeded) {
        gl::GpuTimer::Scope pass(timer_, "light_view");
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) lightViews_[i].render(gpuScene_, scene_, scene_.lights[i]);
    }
    if (needsRadiance()) updateRadiance();

    if (settings_.view != ViewMode::Lit) {
        // Debug views: only the octree (and radiance) and the march; no shading work.
        if (!voxelView_) voxelView_ = std::make_unique<VoxelView>(settings_.width, settings_.height);
        {
            gl::GpuTimer::Scope pass(timer_, "voxel_view");
            const int level = settings_.voxelViewLevel ? settings_.voxelViewLevel : settings_.voxelLevels;
            const VoxelView::Source source = settings_.view == ViewMode::Radiance
                                                 ? VoxelView::Source{radiance_->brickRadiance.id(), radiance_->cellRadiance.id(),
                                                                     radiance_->rawRadiance.id(), true}
                                                 : VoxelView::albedo(svo_->octree());
            voxelView_->render(svo_->octree(), source, camera, scene_, level, settings_.bricks);
        }
        {
            gl::GpuTimer::Scope pass(timer_, "composite");
            composite_.render(gbuffer_, direct_.radiance(), 0, view, 1.0f, settings_.display, voxelView_->image(),
                              settings_.view == ViewMode::Radiance);
        }
        timer_.endFrame();
        gl::checkErrors("rendering a debug view");
        return;
    }

    {
        gl::GpuTimer::Scope pass(timer_, "gbuffer");
        gbuffer_.render(gpuScene_, view);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "direct_lighting");
        direct_.render(gbuffer_, scene_, scene_.lights, lightViews_, settings_.pcfRadius);
    }
    GLuint indirect = 0;
    if (settings_.gi) {
        if (!coneTrace_) coneTrace_ = std::make_unique<ConeTrace>(settings_.width, settings_.height);
        gl::GpuTimer::Scope pass(timer_, "cone_trace");
        ConeSettings cones = settings_.cones;
        cones.bricks = settings_.bricks;
        coneTrace_->render(gbuffer_, svo_->octree(), *radiance_, cones);
        indirect = coneTrace_->indirect();
    }
    {
        gl::GpuTimer::Scope pass(timer_, "composite");
        const float depthScale = float(glm::length(scene_.worldBounds.size()));
        composite_.render(gbuffer_, direct_.radiance(), indirect, view, depthScale, settings_.display);
    }
    timer_.endFrame();
    gl::checkErrors("rendering a frame");
}

std::vector<MemoryPool> Renderer::memory() const {
    std::vector<MemoryPool> pools = {{"scene geometry and textures", gpuScene_.bytes()},
                                     {"gbuffer", gbuffer_.bytes()},
                                     {"direct radiance", direct_.bytes()},
                                     {"composite output", composite_.bytes()}};
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
