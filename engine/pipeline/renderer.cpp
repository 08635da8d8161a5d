#include "pipeline/renderer.hpp"

#include "core/error.hpp"

namespace vct {

ViewMode parseViewMode(const std::string& name) {
    if (name == "lit") return ViewMode::Lit;
    if (name == "voxels") return ViewMode::Voxels;
    fail("unknown --view '", name, "'; use lit or voxels");
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
}

void Renderer::renderFrame(const Camera& camera) {
    const ViewTransform view = cameraView(camera, scene_, settings_.width, settings_.height);
    timer_.beginFrame();
    if (settings_.view == ViewMode::Voxels) {
        // Only the octree and the march: no lighting work for a view that shows none.
        if (!svo_ || settings_.rebuildOctreeEveryFrame) buildOctree();
        if (!voxelView_) voxelView_ = std::make_unique<VoxelView>(settings_.width, settings_.height);
        {
            gl::GpuTimer::Scope pass(timer_, "voxel_view");
            const int level = settings_.voxelViewLevel ? settings_.voxelViewLevel : settings_.voxelLevels;
            voxelView_->render(svo_->octree(), camera, scene_, level, settings_.bricks);
        }
        {
            gl::GpuTimer::Scope pass(timer_, "composite");
            composite_.render(gbuffer_, direct_.radiance(), view, 1.0f, settings_.display, voxelView_->image());
        }
        timer_.endFrame();
        gl::checkErrors("rendering the voxel view");
        return;
    }
    {
        gl::GpuTimer::Scope pass(timer_, "light_view");
        for (std::size_t i = 0; i < scene_.lights.size(); ++i) lightViews_[i].render(gpuScene_, scene_, scene_.lights[i]);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "gbuffer");
        gbuffer_.render(gpuScene_, view);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "direct_lighting");
        direct_.render(gbuffer_, scene_, scene_.lights, lightViews_, settings_.pcfRadius);
    }
    {
        gl::GpuTimer::Scope pass(timer_, "composite");
        const float depthScale = float(glm::length(scene_.worldBounds.size()));
        composite_.render(gbuffer_, direct_.radiance(), view, depthScale, settings_.display);
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
    if (voxelView_) pools.push_back({"voxel view", voxelView_->bytes()});
    return pools;
}

}  // namespace vct
