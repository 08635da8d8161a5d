#pragma once
// The scheduler of the frame's passes (DESIGN §4, docs/frame.md). It reads the pass table
// (frame_passes.hpp) and decides, in table (= dependency) order, which passes a frame runs:
//   - a pass the settings do not need is skipped as "not needed: <why>" (and not marked seen);
//   - a pass that never ran runs ("first run");
//   - a pass runs if one of its inputs changed since it last ran ("camera changed");
//   - a pass runs if a resource it reads was rewritten since it last read it ("reads gbuffer,
//     rewritten");
//   - otherwise it is skipped ("nothing it depends on changed").
// So a static scene is voxelized once, a moving light re-runs only the light-dependent passes
// and a moving camera only the camera-dependent ones; the report says which ran and why.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/frame_passes.hpp"
#include "pipeline/render_settings.hpp"

namespace vct {

struct PassRun {
    Pass pass = Pass::Count;
    std::string name;  // passName(pass)
    bool ran = false;
    std::string reason;
};

class PassGraph {
public:
    // Which passes run this frame. With `targets`, only the passes that produce them (and what
    // those read) are considered; the others are skipped as not asked for.
    std::vector<PassRun> plan(const InputVersions& versions, const RenderSettings& settings,
                              ResourceSet targets = {Resource::Output}) const;
    // Records that the passes of `plan` that ran have seen `versions` and the current resources.
    void commit(const std::vector<PassRun>& plan, const InputVersions& versions);
    // Forget everything (a new scene): every pass runs next frame.
    void reset();

private:
    static constexpr std::size_t kResourceCount = std::size_t(Resource::Count);
    static constexpr std::uint64_t kNeverRead = ~std::uint64_t(0);
    struct PassState {
        bool everRan = false;
        InputVersions seenInputs{};
        std::array<std::uint64_t, kResourceCount> seenResources{};  // kNeverRead until read
    };
    std::array<PassState, kPassCount> state_ = freshState();
    std::array<std::uint64_t, kResourceCount> resourceVersion_{};

    static std::array<PassState, kPassCount> freshState();
};

}  // namespace vct
