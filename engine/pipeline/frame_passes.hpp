#pragma once
// The frame, pass by pass: the one table of vct's passes (frame_passes.cpp, docs/frame.md).
//
// Every pass is declared there once, with
//   - its name (timings, reports, the viewer panel, KHR_debug groups in RenderDoc/apitrace),
//   - the stage of the frame it belongs to (what the benchmark groups its cost by),
//   - the external inputs whose versions it depends on (Input),
//   - the resources it reads and writes (Resource): a pass re-runs when a resource it reads
//     was rewritten, so the order of the table is the order writers come before readers,
//   - why a frame may not need it at all (whyNotNeeded: nullptr when it is needed),
//   - the shaders it runs (for people: find a pass's GLSL from here),
//   - and what it runs (`run`, on the frame's resources).
// The scheduler (pass_graph.hpp) reads this table; nothing else lists the passes.
#include <array>
#include <cstdint>
#include <string>

#include "core/enum_set.hpp"

namespace vct {

struct FrameResources;
struct FrameView;
struct RenderSettings;

enum class Pass {
    Voxelize,
    SvoBuild,
    SvoLeaves,
    SvoNeighbours,
    Bricks,
    BricksMip,
    LightView,
    Inject,
    RadianceLeaves,
    RadianceMip,
    Bounce,
    GBuffer,
    DirectLighting,
    ConeTrace,
    VoxelView,
    Composite,
    Count
};
constexpr std::size_t kPassCount = std::size_t(Pass::Count);

// What the frame depends on from outside, each with a version number bumped when it changes.
enum class Input {
    Geometry,        // triangles (and textures)
    Materials,       // material colours, alpha, emission
    Lights,          // light positions, directions, intensities, colours
    Camera,
    OutputSize,
    VoxelSettings,   // voxel levels
    ShadowSettings,  // light-view resolution, PCF radius
    PhotonSettings,  // photons on/off
    ConeSettings,    // cone set, aperture, step, offset, lift, bricks on/off (voxelGatherCones)
    PixelCones,      // what only the pixels trace: narrow cones, narrow cones in later samples
    BounceSettings,  // the number of bounces
    GiResolution,    // cones at every pixel or one per 2×2 block
    GiFilter,        // the width of the cones' edge-aware filter
    DisplaySettings, // AOV, exposure, tone curve, GI scale, GI on/off (what composite shows)
    ViewSettings,    // debug view mode, level, bricks
    Count
};
constexpr std::size_t kInputCount = std::size_t(Input::Count);
const char* inputName(Input input);
using InputVersions = std::array<std::uint64_t, kInputCount>;

// What passes hand to each other (the GPU objects behind them: FrameResources).
enum class Resource {
    Fragments,          // voxel-fragment list
    Octree,             // node pool: child, mask, coordinate, parent
    CellValues,         // per occupied voxel: albedo, opacity, normal, area, emission
    Neighbours,         // six neighbour links per node
    LeafBricks,         // leaf partial bricks (albedo and opacity)
    GeometryBricks,     // complete albedo and opacity bricks of every level
    LightViewMaps,      // per light: shadow map and photons
    CellRadiance,       // per voxel: outgoing radiance and its direction
    LeafRadiance,       // the radiance bricks, filled at the leaves, and which nodes are near light
    RadianceBricks,     // the radiance bricks of every level
    BouncedRadiance,    // the same bricks with the further bounces added (in place)
    GBuffer,
    DirectRadiance,
    IndirectIrradiance,
    DebugImage,         // a voxel view
    Output,             // HDR and 8-bit images
    Count
};
const char* resourceName(Resource resource);

using InputSet = EnumSet<Input>;
using ResourceSet = EnumSet<Resource>;

// Parts of the frame, in order; a part re-runs for the kind of change named.
enum class Stage {
    Octree,    // geometry or voxel settings changed
    Light,     // lights changed
    Radiance,  // lights changed (GI)
    Camera,    // camera changed
    Output,    // display settings changed
    Count
};
const char* stageName(Stage stage);

struct PassDeclaration {
    Pass pass;
    const char* name;
    Stage stage;
    InputSet inputs;
    ResourceSet reads, writes;
    // nullptr when `settings` need the pass, else why not ("GI off").
    const char* (*whyNotNeeded)(const RenderSettings& settings);
    const char* shaders;
    void (*run)(FrameResources& frame, const FrameView& view);
};

using PassTable = std::array<PassDeclaration, kPassCount>;
const PassTable& framePasses();
inline const PassDeclaration& declaration(Pass pass) { return framePasses()[std::size_t(pass)]; }
inline const char* passName(Pass pass) { return declaration(pass).name; }

}  // namespace vct
