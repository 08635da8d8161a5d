#pragma once
// The frame as a graph of passes (DESIGN §4). Each pass declares the external inputs it depends
// on (geometry, materials, lights, camera, settings, output size — each with a version number
// bumped whenever it changes) and the resources it reads and writes. Before a frame the graph
// decides, in declaration (= dependency) order, which passes must run:
//   - a pass that never ran runs ("first frame");
//   - a pass runs if one of its inputs changed since it last ran ("camera changed");
//   - a pass runs if a resource it reads was rewritten since it last read it ("reads gbuffer,
//     rewritten by gbuffer");
//   - otherwise it is skipped ("nothing it depends on changed"), and passes the frame does not
//     need at all are skipped as "not needed: …".
// So a static scene is voxelized once, a moving light re-runs only the light-dependent passes
// and a moving camera only the camera-dependent ones; the report says which ran and why.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vct {

enum class Input {
    Geometry,        // triangles (and textures)
    Materials,       // material colours, alpha, emission
    Lights,          // light positions, directions, intensities, colours
    Camera,
    OutputSize,
    VoxelSettings,   // voxel levels
    ShadowSettings,  // light-view resolution, PCF radius
    PhotonSettings,  // photons on/off
    ConeSettings,    // cone set, aperture, step, offset, lift, bricks on/off
    DisplaySettings, // AOV, exposure, tone curve, GI scale, GI on/off (what composite shows)
    ViewSettings,    // debug view mode, level, bricks
    Count
};
constexpr std::size_t kInputCount = std::size_t(Input::Count);
const char* inputName(Input input);

using InputVersions = std::array<std::uint64_t, kInputCount>;

struct PassRun {
    std::string name;
    bool ran = false;
    std::string reason;
};

class PassGraph {
public:
    // Passes must be added in an order where writers come before readers.
    void addPass(const std::string& name, std::vector<Input> inputs, std::vector<std::string> reads,
                 std::vector<std::string> writes);
    // Which passes run this frame. `whyNotNeeded(name)` returns a non-empty reason for passes
    // the frame does not need at all (e.g. "GI off"); they are neither run nor marked seen.
    std::vector<PassRun> plan(const InputVersions& versions,
                              const std::function<std::string(const std::string&)>& whyNotNeeded) const;
    // Records that the passes of `plan` that ran have seen `versions` and the current resources.
    void commit(const std::vector<PassRun>& plan, const InputVersions& versions);
    // Forget everything (a new scene): every pass runs next frame.
    void reset();

private:
    struct Pass {
        std::string name;
        std::vector<Input> inputs;
        std::vector<std::string> reads, writes;
        bool everRan = false;
        InputVersions seenInputs{};
        std::map<std::string, std::uint64_t> seenResources;
    };
    std::vector<Pass> passes_;
    std::map<std::string, std::uint64_t> resourceVersion_;
    std::map<std::string, std::string> lastWriter_;
};

}  // namespace vct
