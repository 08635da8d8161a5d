#pragma once
// One frame of vct, pass by pass, each bracketed by the GPU timer. The command line (`vct
// render`), the viewer and the tests all render through this class, so they share one pipeline.
//
// Passes (DESIGN §4): the octree passes voxelize … bricks_mip (once per scene, only when GI or a
// voxel view needs the octree), light_view (per light), inject, radiance_mip, radiance_border
// (GI only), gbuffer, direct_lighting, cone_trace (GI only) or voxel_view (debug), composite.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"
#include "gl/gpu_timer.hpp"
#include "lighting/inject.hpp"
#include "lighting/radiance_filter.hpp"
#include "pipeline/pass_graph.hpp"
#include "render/composite.hpp"
#include "render/cone_trace.hpp"
#include "render/direct_lighting.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view.hpp"
#include "render/voxel_view.hpp"
#include "scene/scene.hpp"
#include "voxel/svo_builder.hpp"

namespace vct {

enum class ViewMode { Lit, Voxels, Radiance };
ViewMode parseViewMode(const std::string& name);

struct RenderSettings {
    int width = 1280;
    int height = 720;
    int lightViewResolution = 2048;  // texels per side of each light-view (shadow) map
    int pcfRadius = 1;               // shadow filter: (2r+1)² hardware-bilinear taps
    DisplaySettings display;
    ViewMode view = ViewMode::Lit;
    bool gi = true;          // indirect light by cone tracing
    bool photons = true;     // inject light (false: only emission and ambient occlusion)
    ConeSettings cones;
    int voxelLevels = 8;     // octree resolution 2^voxelLevels
    int voxelViewLevel = 0;  // level shown by the voxel views; 0 = voxelLevels (the voxels)
    bool bricks = true;      // filtered bricks (else raw node values) in cone tracing and voxel views
    bool fullFrames = false;  // every pass every frame, as if the geometry changed (benchmarks)
};

// Throws a clear error when the settings cannot work on this context (size 0, beyond GL limits).
void validateRenderSettings(const RenderSettings& settings);

struct MemoryPool {
    std::string name;
    std::size_t bytes = 0;
};

// Work each pass did or saved in the last frame that ran it.
struct FrameStatistics {
    std::uint32_t lightViewsRendered = 0, lightViewsTotal = 0;  // only changed lights re-render
    std::vector<std::uint32_t> touchedNodesPerLevel;           // radiance filtered through these
    std::vector<std::uint32_t> nodesPerLevel;
    std::uint32_t photonsMissed = 0;
    ConeStatistics cones;
};

class Renderer {
public:
    Renderer(const Scene& scene, const RenderSettings& settings);

    // Changes take effect at the next renderFrame, which re-runs only the passes that depend on
    // what changed (engine/pipeline/pass_graph.hpp).
    void setSettings(const RenderSettings& settings);
    void setLights(const std::vector<Light>& lights);
    void setMaterial(std::size_t index, const Material& material);
    // A different scene (or the same one, edited): everything is rebuilt.
    void setScene(const Scene& scene);

    void renderFrame(const Camera& camera);
    // Every pass of the last frame, ran or skipped, with the reason.
    const std::vector<PassRun>& lastFrame() const { return lastFrame_; }
    const FrameStatistics& statistics() const { return statistics_; }

    ImageF readHdr() const { return composite_->readHdr(); }
    Image8 readLdr() const { return composite_->readLdr(); }
    GLuint outputTexture() const { return composite_->ldr(); }

    gl::GpuTimer& timer() { return timer_; }
    // The octree, built on first use (nullptr until something needed it).
    const SvoBuilder* octree() const { return svo_.get(); }
    const RadianceVolume* radiance() const { return radiance_.get(); }
    std::vector<MemoryPool> memory() const;
    const RenderSettings& settings() const { return settings_; }
    const std::vector<Light>& lights() const { return lights_; }
    void setDisplay(const DisplaySettings& display);

private:
    void declarePasses();
    std::string whyNotNeeded(const std::string& pass) const;
    void runPass(const std::string& pass, const Camera& camera, const ViewTransform& view);
    void createSizedTargets();
    void bump(Input input) { ++versions_[std::size_t(input)]; }
    bool needsOctree() const { return settings_.view != ViewMode::Lit || settings_.gi; }
    bool needsRadiance() const { return settings_.view == ViewMode::Radiance || (settings_.view == ViewMode::Lit && settings_.gi); }

    const Scene* scene_;
    RenderSettings settings_;
    std::vector<Light> lights_;
    std::unique_ptr<GpuScene> gpuScene_;
    std::unique_ptr<GBuffer> gbuffer_;
    std::vector<LightViewMap> lightViews_;
    std::vector<std::optional<Light>> lightViewRendered_;  // the light each map was rendered for
    std::unique_ptr<DirectLighting> direct_;
    std::unique_ptr<Composite> composite_;
    gl::GpuTimer timer_;
    std::unique_ptr<SvoBuilder> svo_;
    std::unique_ptr<RadianceVolume> radiance_;
    std::unique_ptr<PhotonInjection> injection_;
    std::unique_ptr<RadianceFilter> radianceFilter_;
    std::unique_ptr<ConeTrace> coneTrace_;
    std::unique_ptr<VoxelView> voxelView_;

    PassGraph graph_;
    InputVersions versions_{};
    std::optional<Camera> lastCamera_;
    std::uint64_t lightViewInputsSeen_ = ~0ull;  // geometry/materials/shadow versions the maps saw
    std::vector<PassRun> lastFrame_;
    FrameStatistics statistics_;
};

}  // namespace vct
