#pragma once
// One frame of vct, pass by pass, each bracketed by the GPU timer. The command line (`vct
// render`), the viewer and the tests all render through this class, so they share one pipeline.
//
// Passes today (DESIGN §4): the octree passes (voxelize … bricks_mip, once per scene, only when
// a view needs the octree), light_view (per light), gbuffer, direct_lighting, voxel_view (debug),
// composite.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "gl/gpu_timer.hpp"
#include "render/composite.hpp"
#include "render/direct_lighting.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view.hpp"
#include "render/voxel_view.hpp"
#include "voxel/svo_builder.hpp"
#include "scene/scene.hpp"

namespace vct {

enum class ViewMode { Lit, Voxels };
ViewMode parseViewMode(const std::string& name);

struct RenderSettings {
    int width = 1280;
    int height = 720;
    int lightViewResolution = 2048;  // texels per side of each light-view (shadow) map
    int pcfRadius = 1;               // shadow filter: (2r+1)² hardware-bilinear taps
    DisplaySettings display;
    ViewMode view = ViewMode::Lit;
    int voxelLevels = 8;     // octree resolution 2^voxelLevels
    int voxelViewLevel = 0;  // level shown by the voxel view; 0 = voxelLevels (the voxels)
    bool bricks = true;      // voxel view samples filtered bricks (else raw node values)
    bool rebuildOctreeEveryFrame = false;  // for benchmarks: time a warm octree build
};

// Throws a clear error when the settings cannot work on this context (size 0, beyond GL limits).
void validateRenderSettings(const RenderSettings& settings);

struct MemoryPool {
    std::string name;
    std::size_t bytes = 0;
};

class Renderer {
public:
    Renderer(const Scene& scene, const RenderSettings& settings);

    void renderFrame(const Camera& camera);
    ImageF readHdr() const { return composite_.readHdr(); }
    Image8 readLdr() const { return composite_.readLdr(); }
    GLuint outputTexture() const { return composite_.ldr(); }

    gl::GpuTimer& timer() { return timer_; }
    // The octree, built on first use (nullptr until a view needed it).
    const SvoBuilder* octree() const { return svo_.get(); }
    void buildOctree();
    std::vector<MemoryPool> memory() const;
    const RenderSettings& settings() const { return settings_; }
    void setDisplay(const DisplaySettings& display) { settings_.display = display; }

private:
    const Scene& scene_;
    RenderSettings settings_;
    GpuScene gpuScene_;
    GBuffer gbuffer_;
    std::vector<LightViewMap> lightViews_;
    DirectLighting direct_;
    Composite composite_;
    gl::GpuTimer timer_;
    std::unique_ptr<SvoBuilder> svo_;
    std::unique_ptr<VoxelView> voxelView_;
};

}  // namespace vct
