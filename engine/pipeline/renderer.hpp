#pragma once
// One frame of vct, pass by pass, each bracketed by the GPU timer and a KHR_debug group. The
// command line (`vct render`, `vct info`), the viewer and the tests all render through this
// class, so they share one pipeline: the pass table (frame_passes.hpp), run by the scheduler
// (pass_graph.hpp) on the frame's resources (frame_resources.hpp).
#include <optional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "gl/gpu_timer.hpp"
#include "pipeline/frame_resources.hpp"
#include "pipeline/pass_graph.hpp"
#include "pipeline/render_settings.hpp"

namespace vct {

struct MemoryPool {
    std::string name;
    std::size_t bytes = 0;
};

class Renderer {
public:
    // Validates the settings against this context's limits before creating anything. The renderer
    // reads `scene` at every frame and keeps no copy: it must outlive the renderer (a temporary
    // would dangle, hence the deleted overloads).
    Renderer(const Scene& scene, const RenderSettings& settings);
    Renderer(Scene&&, const RenderSettings&) = delete;

    // Changes take effect at the next renderFrame, which re-runs only the passes that depend on
    // what changed (engine/pipeline/pass_graph.hpp).
    void setSettings(const RenderSettings& settings);
    void setDisplay(const DisplaySettings& display);
    void setLights(const std::vector<Light>& lights);
    void setMaterial(std::size_t index, const Material& material);
    // A different scene (or the same one, edited): everything is rebuilt.
    void setScene(const Scene& scene);
    void setScene(Scene&&) = delete;

    // `sample` picks where in each pixel this frame looks (render/pixel_samples.hpp; 0 = the
    // centre). The output holds the average of the samples since the last restart: sample k > 0
    // right after sample k − 1 of the same camera, with nothing else changed, adds to the average;
    // any other frame restarts it with its own sample. A sample 0 that took light carried over a
    // camera move is traced again, anew, before sample 1 adds to it (in sample 1's timings).
    void renderFrame(const Camera& camera, int sample = 0);
    // How many samples the output averages.
    int samplesInOutput() const { return samplesInOutput_; }
    // Only the passes that build the octree (voxelize … bricks_mip), for tools that inspect it.
    void buildOctree();
    // Every pass of the last frame, ran or skipped, with the reason.
    const std::vector<PassRun>& lastFrame() const { return lastFrame_; }
    // The last frame's statistics; the cone counters are read back from the GPU here, on request.
    const FrameStatistics& statistics() const;

    ImageF readHdr() const { return frame_.composite->readHdr(); }
    Image8 readLdr() const { return frame_.composite->readLdr(); }
    GLuint outputTexture() const { return frame_.composite->ldr(); }

    gl::GpuTimer& timer() { return timer_; }
    // The octree, built on first use (nullptr until something needed it).
    const SvoBuilder* octree() const { return frame_.svo.get(); }
    const RadianceVolume* radiance() const { return frame_.radiance.get(); }
    std::vector<MemoryPool> memory() const;
    const RenderSettings& settings() const { return frame_.settings; }
    const std::vector<Light>& lights() const { return frame_.lights; }

private:
    // One timer frame of the passes that `targets` need; `everyPass`: all of them, as if the
    // geometry changed (RenderSettings::fullFrames).
    void run(const std::optional<Camera>& camera, ResourceSet targets, bool everyPass);
    // The passes that `targets` need for pixel sample `sample`, within the current timer frame.
    void execute(const std::optional<Camera>& camera, ResourceSet targets, int sample);
    void createSizedTargets();
    void bump(Input input) { ++frame_.versions[std::size_t(input)]; }

    FrameResources frame_;
    PassGraph graph_;
    gl::GpuTimer timer_;
    std::optional<Camera> lastCamera_;
    int lastSample_ = 0, samplesInOutput_ = 0;
    InputVersions versionsAfterLastFrame_{};
    std::vector<PassRun> lastFrame_;
};

}  // namespace vct
