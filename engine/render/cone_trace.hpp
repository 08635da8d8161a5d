#pragma once
// cone_trace pass (DESIGN §4 pass 12): indirect irradiance and ambient visibility per pixel by
// diffuse cones through the radiance bricks.
#include <array>
#include <memory>
#include <string>

#include "gl/compute.hpp"
#include "gl/objects.hpp"
#include "lighting/list_dispatch.hpp"
#include "lighting/radiance_volume.hpp"
#include "render/cone_carry.hpp"
#include "render/cone_reuse.hpp"
#include "render/cone_set.hpp"
#include "render/gbuffer.hpp"
#include "render/indirect_filter.hpp"
#include "render/near_detail.hpp"

namespace vct {

// tan of a narrow cone's half-angle (`--cone-rays`): about 1.7°, a voxel wide 17 voxels out. Of the
// apertures measured (tan 0.03, 0.06, 0.12; docs/benchmark.md, "Narrow cones") the narrowest came
// closest to the path tracer in RMSE on every view.
constexpr float kNarrowConeTan = 0.03f;
constexpr int kMaxNarrowCones = 64;
// The default: four narrow cones per traced pixel rather than the five-cone set. The set's few
// wide cones each make one opacity of a footprint that a surface covers only in part (a floor
// seen across the footprint collected twice over, a whole cone stopped by the shade in front of
// a sunlit strip), biases that no setting removed and that differ from view to view; narrow
// cones converge to the path tracer as the voxels shrink, and four of them, with the traced
// pixels' blocks and the edge-aware filter averaging their noise, already come closer than the
// set on most views, for a few times the set's cone tracing (docs/benchmark.md, "Four narrow
// cones by default").
constexpr int kDefaultNarrowCones = 4;
// Step length / cone diameter of each kind of cone when `--cone-step` is 0 (its default). Narrow
// cones come as close to the path tracer with a step of a whole diameter as with half, in half
// the samples; the set was tuned at half.
constexpr float kConeSetStep = 0.5f;
constexpr float kNarrowConeStep = 1.0f;
// Narrow cones traced per dispatch, each dispatch adding to the last. llvmpipe ends every loop of
// a shader invocation once all of them together have run 65535 iterations (gallivm's
// LP_MAX_TGSI_LOOP_ITERATIONS, shared by every loop), silently: a pixel's sixteen narrow cones
// in one invocation lost the light of those past the first fifteen or so. Four stay well inside.
constexpr int kNarrowConesPerDispatch = 4;
// The most narrow cones per side of a gathering voxel: an invocation gathers both sides, so two
// per side keep its cones within kNarrowConesPerDispatch.
constexpr int kMaxBounceRays = kNarrowConesPerDispatch / 2;
// Narrow cones per side of a voxel that gathers a further bounce (`--bounce-cone-rays`; 0: the
// cone set). The set's wide cones, marched from voxels across a room, read coarse nodes that hold
// the walls beside their path and stop there: a room lit only through an opening lost about a
// third of every further bounce, and its ceiling's voxels nearly all of theirs. Narrow cones from
// the voxels come close to the path tracer. Each voxel's one cone per side is noisy, but the
// camera's cones read the voxels' light averaged over their footprints: one per side measured as
// close as two or sixteen, and gathers cheaper than the cone set's (docs/benchmark.md, "Further
// bounces with narrow cones").
constexpr int kDefaultBounceRays = 1;

// A traced pixel's irradiance takes the narrow cones of the traced pixels around it as well as its
// own (render/cone_reuse.hpp): those of a window of 5×5 traced cells whose cones start on the same
// side of both surfaces, weighted by a Gaussian of this σ (voxels) over their distance. Four cones
// per pixel leave most of their noise where surfaces are small (a column's flutes, mouldings), which
// the edge-aware filter has to keep apart; directions reused across them lower that noise for a
// small part of the cone tracing's cost (docs/benchmark.md, "Cones shared between neighbours").
// A wider σ gained nothing measurable.
constexpr float kDefaultConeReuseVoxels = 4.0f;
// Pixels that trace more cones than this keep their own: their noise is already low, and what the
// neighbours' cones see differently near their own apexes (a thin surface under another one)
// weighs about as much as the noise they would remove (docs/benchmark.md).
constexpr int kMaxReusedCones = 8;

struct ConeSettings {
    int cones = 5;              // 1, 5, 6, 9 or 16 (cone_set.hpp)
    float apertureScale = 1.0f; // multiplies the derived half-angles (tan), for the benchmark sweep
    float step = 0.0f;          // step length / cone diameter; 0: the kind's own (coneStep)
    float offset = 1.5f;        // start offset along the normal, voxels
    float lift = 0.0f;          // extra normal offset per unit of cone diameter
    float maxDistance = 0.0f;   // voxels; 0 = through the whole volume
    bool bricks = true;         // false: the nearest brick sample, no interpolation (`--no-bricks`)
    int onlyCone = -1;          // diagnostic: only this cone of the set gathers (`--only-cone`); −1: all
    // Narrow cones (`--cone-rays`): this many (1..kMaxNarrowCones) of half-angle
    // atan(kNarrowConeTan × apertureScale), their axes spread anew at every pixel; 0: the cone set.
    int rays = kDefaultNarrowCones;
    // What the samples after the first of an accumulated frame trace (`--samples`, the viewer's
    // refinement): one narrow cone each (conesForSample; true, the default) or the frame's cones
    // again (`--sample-cones frame`).
    bool narrowConesAfterFirstSample = true;
    // Narrow cones per side of each voxel that gathers a further bounce (`--bounce-cone-rays`,
    // kDefaultBounceRays); 0: the cone set (`cones`). Frame cones and bounce cones are separate:
    // voxelGatherCones makes the gathers' settings from these.
    int bounceRays = kDefaultBounceRays;
    // Narrow cones shared between neighbouring traced pixels (`--cone-reuse`, shaders/cone_reuse.comp):
    // σ in voxels of the weight a neighbour's cones get by its distance; 0: each pixel its own.
    float reuseVoxels = kDefaultConeReuseVoxels;
    // Indirect light carried over camera moves (`--cone-carry`, render/cone_carry.hpp): how far
    // (voxels, beyond a pixel's footprint) the point where a pixel's light was estimated may lie
    // from the point it serves now; 0: every frame traces anew.
    float carryVoxels = kDefaultConeCarryVoxels;
    // The near field of the camera's narrow cones (`--near-field`, shaders/near_field.glsl): each
    // cone's axis is first followed against the G-buffer up to where the cone starts, and a
    // surface met there takes the cone's place; false: the cones alone.
    bool nearField = true;
    // The near field's detail at every pixel (`--near-detail`, render/near_detail.hpp): each
    // pixel's irradiance scaled by its visibility within the cones' start offset over the mean
    // of that visibility on its surface around it; false: the cones' irradiance as filtered.
    bool nearDetail = true;

    bool operator==(const ConeSettings&) const = default;
};

// The step length of `settings`' cones, in cone diameters: its own, or the kind's (kConeSetStep,
// kNarrowConeStep).
float coneStep(const ConeSettings& settings);

// The narrow cones that the later samples of an accumulated frame trace. The cone set's errors
// are biases of its few wide cones (light collected across a footprint, blocked by a wall beside
// the path), the same at every sample, so averaging samples of it converges to its bias; narrow
// cones err much less and spread the rest as noise, which averaging removes. One cone per traced
// pixel and sample, whatever the frame traces: over N samples a block of pixels has traced N
// directions more, stratified (SampleCones::raySequence), for less than a frame's cones per sample.
constexpr int kNarrowConesPerLaterSample = 1;

// What pixel sample `sample` of a frame traces.
struct SampleCones {
    ConeSettings cones;
    // >= 0: where this sample's narrow cones start in a sequence of directions that each block of
    // traced pixels continues from sample to sample, so that the directions of all samples
    // together cover the hemisphere evenly; -1: every apex draws its own (shaders/cone_march.glsl).
    int raySequence = -1;
};
// Sample 0, alone in a plain frame, traces `frame` as it is. With narrowConesAfterFirstSample,
// every later sample k traces kNarrowConesPerLaterSample narrow cones, the (k−1)-th of the
// sequence. Without, every sample traces `frame`.
SampleCones conesForSample(const ConeSettings& frame, int sample);
// The weight of sample `sample`'s indirect light in the average of an accumulated frame (the
// composite pass; direct light averages with equal weights): the narrow cones it traced per
// traced pixel, so that a frame's own four cones count as four later samples' one each. Weighted
// 1/N like its direct light, the first sample's four cones would hold no more than one later
// cone, and 2 or 4 samples came out noisier than one. 1 where every sample traces alike.
float indirectWeightOfSample(const ConeSettings& frame, int sample);
// `--sample-cones`: "narrow" (narrowConesAfterFirstSample) or "frame"; throws naming the option.
bool parseSampleCones(const std::string& name);
const char* sampleConesName(bool narrowConesAfterFirstSample);

// The cones that gathers at the voxels (further bounces) trace: `settings.bounceRays` narrow cones
// per side (0: the cone set), with the frame's aperture, step and diagnostic cone, and its offset
// plus kVoxelCentreToSurface. What the later pixel samples trace, the cones shared between pixels
// and the near field are the pixels' alone.
ConeSettings voxelGatherCones(ConeSettings settings);
// A gather starts from its voxel's centre, which lies up to half a voxel behind the surface the
// voxel holds; a pixel's cones start from the surface itself. So the gathers start that much
// farther out, to keep the same distance from their own surface: from 1.5 voxels, the first
// samples' trilinear reads still took opacity from the voxel's own surface and its neighbours',
// and further bounces came out darker (four bounces against the path tracer: CameraBalcony 0.689
// at the pixels' offset, 0.701 at this one; CameraAlcove 0.844, 0.857; CameraMain 0.967, 0.972).
constexpr float kVoxelCentreToSurface = 0.5f;

// Whether a frame's pixels share their narrow cones with their neighbours (shaders/cone_reuse.comp):
// narrow cones, at most kMaxReusedCones of them, all (not one region's, `--only-cone`), and
// reuseVoxels > 0. Only the first sample of a frame: the later samples' one cone each continues a
// sequence of directions per block instead (conesForSample).
bool reusesCones(const ConeSettings& settings);

// How many pixels one trace of the cone set serves: each pixel its own, or one pixel of each 2×2
// (half) or 4×4 (quarter) block, the others taking theirs from the traced pixels that share their
// surface (shaders/cone_upsample.comp; a pixel that shares its surface with none traces its own).
// Auto: quarter for images of at least kQuarterResolutionLines lines (and columns), half below.
// The indirect light varies on the scale of voxels, not pixels: at 640×360 a Sponza voxel covers
// several pixels, and tracing one pixel in 16 is as close to the path tracer as one in 4; in a
// small image a block of 4×4 pixels spans more of the scene, and half keeps the finer detail.
enum class GiResolution { Full, Half, Quarter, Auto };
constexpr int kQuarterResolutionLines = 360;
GiResolution parseGiResolution(const std::string& name);  // "auto", "full", "half" or "quarter"; throws naming the option
const char* giResolutionName(GiResolution resolution);
// Pixels per side of the block one trace serves (1, 2 or 4) in an image of width × height.
int giBlockSize(GiResolution resolution, int width, int height);
// The viewer's key: auto, every pixel, 2×2, 4×4, auto.
GiResolution nextGiResolution(GiResolution resolution);

// Throws naming the option for a setting out of its range (an unknown cone set, aperture,
// step, offset, lift, maximum distance).
void validateConeSettings(const ConeSettings& settings);

// The uniforms and textures of shaders/cone_march.glsl on `call`: the octree, the brick layout,
// the six radiance pools, the voxels' own light and opacity (which narrow cones thinner than a
// voxel read while the bricks hold one bounce, as the voxels do) and the cone set with its
// aperture, step, offsets and reach.
void setConeMarchUniforms(gl::ComputeCall& call, const Octree& octree, const RadianceVolume& radiance,
                          const ConeSettings& settings);

// How many invocations share one apex's cones, each tracing every n-th (shaders/cone_lanes.glsl,
// CONE_LANES). One per cone (the narrow cones of a dispatch, or the cone set's cones) keeps more
// invocations in flight where few apexes trace (a frame's one pixel per block, a bounce's
// gathering voxels), which made cone_trace twice as fast on an H200; but there the group's sum of
// the lanes' parts came out wrong, and different from run to run, with narrow cones
// (docs/benchmark.md, "Cone lanes on the H200"), so every device keeps one lane until a GPU
// shows the remedy right: cone_trace's lanes now store their parts and a second dispatch adds
// them, with no shared memory and no barrier (the pixels that trace their own cones take one
// lane; the bounce gathers still add their lanes' parts in shared memory). VCT_CONE_LANES forces
// one lane ("1") or one per cone ("cones"), so that both are checked on any machine: both must
// give the same bits, as each lane then traces at most one cone of a dispatch (with two lanes for
// four cones, each lane's two would add up before the lanes do, in another order). Sets of more
// than kMaxConeLanes cones keep one lane.
constexpr int kMaxConeLanes = 9;
int coneLanes(const ConeSettings& settings);
// The shader define that builds a tracing program for `lanes` lanes.
std::string coneLanesDefine(int lanes);

struct ConeStatistics {
    std::uint64_t samples = 0;       // brick samples taken
    std::uint64_t samplesSaved = 0;  // samples empty-space skipping made unnecessary
    std::uint64_t skyPixels = 0;     // pixels with no GI work
    std::uint64_t tracedPixels = 0;  // pixels whose own cones were traced
    std::uint64_t carriedPixels = 0; // pixels that took the last frame's indirect light (cone_carry.hpp)
};

class ConeTrace {
public:
    ConeTrace(int width, int height);
    // `sample`: the pixel sample of an accumulated frame. It turns which pixel of each block is
    // traced, so that accumulated samples trace every pixel in turn, and chooses the cones
    // (conesForSample). `filterVoxels`: the width of the edge-aware filter of what the cones traced
    // (indirect_filter.hpp), 0: none. `view`: the camera's; `sceneVersion` changes whenever anything
    // but the camera does (geometry, lights, settings): a frame of another version never takes
    // the last frame's light (cone_carry.hpp). `directRadiance`: the direct light shaded on this
    // G-buffer (DirectLighting), what a surface in the narrow cones' near field sends back.
    void render(const GBuffer& gbuffer, const Octree& octree, const RadianceVolume& radiance, const ConeSettings& frame,
                GiResolution resolution, int sample, float filterVoxels, const ViewTransform& view,
                std::uint64_t sceneVersion, GLuint directRadiance);
    GLuint indirect() const { return result_; }  // RGBA32F: irradiance, visibility
    // Whether the last render took light from the frame before it (cone_carry.hpp).
    bool carried() const { return carry_ && carry_->carries(); }
    ConeStatistics statistics() const;  // of the last render (reads back 40 bytes)
    std::size_t bytes() const;

private:
    int width_, height_;
    gl::Texture indirect_;
    gl::Texture traced_, tracedPixel_;  // half or quarter resolution only, made on first use
    int tracedBlock_ = 0;               // the block size they were made for
    // The tracing programs for each count of lanes (coneLanes), without and with the near field
    // (ConeSettings::nearField), made on first use, and the pass that adds the lanes' parts of
    // each listed cell; the upsampling, and the tracing of the pixels it lists (one lane: they
    // are few, and their lanes' parts would need a buffer the size of the image).
    std::array<std::array<gl::Program, kMaxConeLanes + 1>, 2> tracePrograms_;
    std::array<gl::Program, kMaxConeLanes + 1> sumLanesPrograms_;
    std::array<gl::Program, 2> traceListedPrograms_;
    gl::Buffer laneParts_;  // with lanes: each listed cell's lanes' parts, made on first use
    GLsizeiptr lanePartsBytes_ = 0;
    gl::Program upsampleProgram_, smoothListedProgram_;
    gl::Buffer counters_;
    gl::Buffer ownTracePixels_, dispatchArgs_;  // cone_upsample's list of pixels that trace their own
    gl::Buffer ownTraceSmoothed_;               // and their light averaged over their surface
    gl::Buffer traceArgs_;                      // the dispatch arguments of cone_carry's list of cells
    ListDispatch listDispatch_;
    std::unique_ptr<ConeCarry> carry_;        // sized for the traced image
    std::unique_ptr<ConeReuse> reuse_;        // sized for the traced image and cones, made on first use
    std::unique_ptr<IndirectFilter> filter_;  // sized for the traced image, made on first use
    std::unique_ptr<NearDetail> nearDetail_;  // made on first use
    GLuint result_ = 0;  // indirect_, or at full resolution the filter's image; or the near detail's
};

}  // namespace vct
