#include "render/cone_trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "gl/driver_checks.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {

ConeTrace::ConeTrace(int width, int height)
    : width_(width),
      height_(height),
      indirect_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "indirect irradiance")),
      counters_(gl::createBuffer(4 * gl::CONE_COUNTER_WORDS, nullptr, GL_DYNAMIC_STORAGE_BIT, "cone counters")),
      traceArgs_(gl::createBuffer(12, nullptr, 0, "traced cells' dispatch arguments")) {}

int coneLanes(const ConeSettings& settings) {
    const int cones = settings.rays > 0 ? std::min(settings.rays, kNarrowConesPerDispatch) : int(makeConeSet(settings.cones).size());
    bool perCone = false;
    if (const char* forced = std::getenv("VCT_CONE_LANES"); forced && *forced) {
        const std::string value = forced;
        if (value != "1" && value != "cones")
            fail("VCT_CONE_LANES must be 1 (one invocation traces all the cones of an apex) or cones (one invocation per "
                 "cone), not '", value, "'; unset it to let vct choose");
        perCone = value == "cones";
    }
    return perCone && cones <= kMaxConeLanes ? cones : 1;
}

std::string coneLanesDefine(int lanes) { return "CONE_LANES " + std::to_string(lanes); }

ConeStatistics ConeTrace::statistics() const {
    std::uint32_t c[10] = {};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof c, c);
    auto join = [&](int i) { return std::uint64_t(c[i]) | (std::uint64_t(c[i + 1]) << 32); };
    return {join(0), join(2), join(4), join(6), join(8)};
}

std::size_t ConeTrace::bytes() const {
    const std::size_t full = std::size_t(width_) * height_ * 16;
    const int b = std::max(tracedBlock_, 1);
    const std::size_t blocks = traced_.id() ? std::size_t((width_ + b - 1) / b) * ((height_ + b - 1) / b) : 0;
    const std::size_t ownTraceList = ownTracePixels_.id() ? std::size_t(width_) * height_ * (4 + 16) : 0;
    return full + blocks * (16 + 4) + ownTraceList + std::size_t(lanePartsBytes_) + (reuse_ ? reuse_->bytes() : 0) +
           (filter_ ? filter_->bytes() : 0) + (carry_ ? carry_->bytes() : 0) + (nearDetail_ ? nearDetail_->bytes() : 0);
}

GiResolution parseGiResolution(const std::string& name) {
    if (name == "auto") return GiResolution::Auto;
    if (name == "full") return GiResolution::Full;
    if (name == "half") return GiResolution::Half;
    if (name == "quarter") return GiResolution::Quarter;
    fail("unknown --gi-resolution '", name,
         "'; use auto (quarter from 360 lines up, else half), full (cones at every pixel), half (at one pixel of each "
         "2x2 block) or quarter (of each 4x4 block)");
}

const char* giResolutionName(GiResolution resolution) {
    switch (resolution) {
        case GiResolution::Full: return "full";
        case GiResolution::Half: return "half";
        case GiResolution::Quarter: return "quarter";
        case GiResolution::Auto: return "auto";
    }
    return "auto";
}

int giBlockSize(GiResolution resolution, int width, int height) {
    switch (resolution) {
        case GiResolution::Full: return 1;
        case GiResolution::Half: return 2;
        case GiResolution::Quarter: return 4;
        case GiResolution::Auto: return std::min(width, height) >= kQuarterResolutionLines ? 4 : 2;
    }
    return 2;
}

GiResolution nextGiResolution(GiResolution resolution) {
    switch (resolution) {
        case GiResolution::Auto: return GiResolution::Full;
        case GiResolution::Full: return GiResolution::Half;
        case GiResolution::Half: return GiResolution::Quarter;
        case GiResolution::Quarter: return GiResolution::Auto;
    }
    return GiResolution::Auto;
}

void validateConeSettings(const ConeSettings& s) {
    makeConeSet(s.cones);  // throws for an unknown set
    if (!(s.apertureScale > 0.0f && s.apertureScale <= 4.0f))
        fail("--cone-aperture ", s.apertureScale, " is out of range; use a factor in (0, 4]");
    if (!(s.step == 0.0f || (s.step >= 0.05f && s.step <= 4.0f)))
        fail("--cone-step ", s.step, " is out of range; use 0.05..4 (fraction of the cone diameter) or 0 (",
             kConeSetStep, " for the cone set, ", kNarrowConeStep, " for narrow cones)");
    if (!(s.offset >= 0.0f && s.offset <= 16.0f))
        fail("--cone-offset ", s.offset, " is out of range; use 0..16 voxels");
    if (!(s.lift >= 0.0f && s.lift <= 4.0f))
        fail("--cone-lift ", s.lift, " is out of range; use 0..4 (normal offset per unit of cone diameter)");
    if (s.rays < 0 || s.rays > kMaxNarrowCones)
        fail("--cone-rays ", s.rays, " is out of range; use 1..", kMaxNarrowCones, " narrow cones (0: the cone set)");
    if (s.bounceRays < 0 || s.bounceRays > kMaxBounceRays)
        fail("--bounce-cone-rays ", s.bounceRays, " is out of range; use 1..", kMaxBounceRays,
             " narrow cones per side of a voxel (0: the cone set)");
    if (s.onlyCone < -1 || s.onlyCone >= s.cones)
        fail("--only-cone ", s.onlyCone, " is not a cone of the ", s.cones, "-cone set; use 0..", s.cones - 1,
             " (0 is the cone along the normal)");
    if (!(s.reuseVoxels >= 0.0f && s.reuseVoxels <= 64.0f))
        fail("--cone-reuse ", s.reuseVoxels, " is out of range; use 0 (each pixel its own cones) .. 64 voxels");
    if (!(s.carryVoxels >= 0.0f && s.carryVoxels <= 4.0f))
        fail("--cone-carry ", s.carryVoxels, " is out of range; use 0 (every frame traces anew) .. 4 voxels");
    if (!(s.maxDistance >= 0.0f) || !std::isfinite(s.maxDistance))
        fail("cone maximum distance (--cone-max-distance) ", s.maxDistance,
             " must be a finite number of voxels ≥ 0 (0: the whole volume)");
}

void setConeMarchUniforms(gl::ComputeCall& call, const Octree& octree, const RadianceVolume& radiance,
                          const ConeSettings& settings) {
    const std::vector<Cone> cones = makeConeSet(settings.cones);
    std::vector<glm::vec3> directions;
    std::vector<float> tangents, weights;
    for (const Cone& c : cones) {
        directions.push_back(c.direction);
        // Wider than ~80° a cone reaches the coarsest level within a step or two. (The single
        // cone's half-angle is π/2, whose float tangent is a huge negative number.)
        tangents.push_back(std::min(std::tan(std::min(c.halfAngle, 1.5f)) * settings.apertureScale, 5.0f));
        weights.push_back(c.weight);
    }
    const GLuint p = call.program();
    octree.bind(p);
    setBrickPoolUniforms(p, octree);
    bindDirectionalTexture(call, radiance);
    glProgramUniform3fv(p, glGetUniformLocation(p, "uConeDirection"), GLsizei(cones.size()), &directions[0].x);
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeTanHalfAngle"), GLsizei(cones.size()), tangents.data());
    glProgramUniform1fv(p, glGetUniformLocation(p, "uConeWeight"), GLsizei(cones.size()), weights.data());
    const float diagonal = float(octree.grid.resolution()) * 1.7320508f;
    call.uniform("uConeCount", int(cones.size()))
        .uniform("uConeStep", coneStep(settings))
        .uniform("uConeOffset", settings.offset)
        .uniform("uConeLift", settings.lift)
        .uniform("uMaxDistance", settings.maxDistance > 0.0f ? settings.maxDistance : diagonal)
        .uniform("uUseBricks", settings.bricks ? 1 : 0)
        .uniform("uOnlyCone", settings.onlyCone)
        .uniform("uRayCount", settings.rays)
        .uniform("uRayFirst", 0)
        .uniform("uRayEnd", settings.rays)
        .uniform("uRaySequence", -1)
        .uniform("uRayTanHalfAngle", kNarrowConeTan * settings.apertureScale)
        .uniform("uVoxelOrigin", glm::vec3(octree.grid.localMin))
        .uniform("uVoxelScale", float(1.0 / octree.grid.voxelSize))
        .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity);
    // The voxels narrow cones read hold as many bounces as the bricks.
    call.storage(gl::SSBO_CELL_RADIANCE, radiance.seenCellRadiance())
        .storage(gl::SSBO_CELL_EXIT_SHARES, radiance.seenCellExitShares());
}

float coneStep(const ConeSettings& settings) {
    if (settings.step > 0.0f) return settings.step;
    return settings.rays > 0 ? kNarrowConeStep : kConeSetStep;
}

SampleCones conesForSample(const ConeSettings& frame, int sample) {
    SampleCones s{frame, -1};
    if (sample < 1 || !frame.narrowConesAfterFirstSample) return s;
    s.cones.rays = kNarrowConesPerLaterSample;
    s.cones.step = kNarrowConeStep;
    s.raySequence = (sample - 1) * kNarrowConesPerLaterSample;
    return s;
}

float indirectWeightOfSample(const ConeSettings& frame, int sample) {
    if (!frame.narrowConesAfterFirstSample || frame.rays <= 0) return 1.0f;
    return float(conesForSample(frame, sample).cones.rays);
}

bool parseSampleCones(const std::string& name) {
    if (name != "narrow" && name != "frame") fail("--sample-cones must be narrow or frame, not '", name, "'");
    return name == "narrow";
}

const char* sampleConesName(bool narrowConesAfterFirstSample) { return narrowConesAfterFirstSample ? "narrow" : "frame"; }

bool reusesCones(const ConeSettings& settings) {
    return settings.reuseVoxels > 0.0f && settings.rays > 0 && settings.rays <= kMaxReusedCones && settings.onlyCone < 0;
}

ConeSettings voxelGatherCones(ConeSettings settings) {
    settings.rays = settings.bounceRays;
    if (settings.rays > 0) settings.cones = ConeSettings{}.cones;  // the set is not traced: no reason to gather again
    settings.narrowConesAfterFirstSample = ConeSettings{}.narrowConesAfterFirstSample;
    settings.reuseVoxels = ConeSettings{}.reuseVoxels;
    settings.carryVoxels = ConeSettings{}.carryVoxels;
    settings.nearField = ConeSettings{}.nearField;  // a voxel's cones have no G-buffer to follow
    settings.nearDetail = ConeSettings{}.nearDetail;  // nor pixels
    settings.offset += kVoxelCentreToSurface;
    return settings;
}

void ConeTrace::render(const GBuffer& gbuffer, const Octree& octree, const RadianceVolume& radiance,
                       const ConeSettings& frame, GiResolution resolution, int sample, float filterVoxels,
                       const ViewTransform& view, std::uint64_t sceneVersion, GLuint directRadiance) {
    const SampleCones sampleCones = conesForSample(frame, sample);
    const ConeSettings& settings = sampleCones.cones;
    const int block = giBlockSize(resolution, width_, height_);
    const bool inBlocks = block > 1;  // one pixel of each block traced, the others upsampled
    const int tracedWidth = (width_ + block - 1) / block, tracedHeight = (height_ + block - 1) / block;
    if (inBlocks && tracedBlock_ != block) {
        traced_ = gl::createTexture2D(GL_RGBA32F, tracedWidth, tracedHeight, 1, "indirect irradiance, traced blocks");
        tracedPixel_ = gl::createTexture2D(GL_R32UI, tracedWidth, tracedHeight, 1, "traced pixel of each block");
        tracedBlock_ = block;
    }
    const int lanes = coneLanes(settings);
    // Only narrow cones follow their axes through the near field: the cone set's wide cones stay as they were tuned.
    const int nearField = settings.nearField && settings.rays > 0 ? 1 : 0;
    auto withNearField = [&](std::vector<std::string> defines) {
        if (nearField) defines.push_back("SCREEN_NEAR_FIELD 1");
        return defines;
    };
    gl::Program& traceProgram = tracePrograms_[nearField][lanes];
    if (!traceProgram.id())
        traceProgram = gl::buildProgram({{GL_COMPUTE_SHADER, "cone_trace.comp"}},
                                        withNearField({coneLanesDefine(lanes), "STORE_CONE_SAMPLES 1"}));
    // With lanes each listed cell's lanes store their parts, which a second dispatch adds in the
    // cones' order: no shared memory and no barrier inside the trace.
    if (lanes > 1 && !sumLanesPrograms_[lanes].id())
        sumLanesPrograms_[lanes] =
            gl::buildProgram({{GL_COMPUTE_SHADER, "cone_trace.comp"}}, {coneLanesDefine(lanes), "SUM_CONE_LANES 1"});
    const GLsizeiptr lanePartsBytes = lanes > 1 ? GLsizeiptr(16) * lanes * tracedWidth * tracedHeight : 0;
    if (lanePartsBytes > lanePartsBytes_) {
        laneParts_ = gl::createBuffer(lanePartsBytes, nullptr, 0, "cone lanes' parts of the listed cells");
        lanePartsBytes_ = lanePartsBytes;
    }
    gl::Program& traceListedProgram = traceListedPrograms_[nearField];
    if (inBlocks && !traceListedProgram.id())
        traceListedProgram =
            gl::buildProgram({{GL_COMPUTE_SHADER, "cone_upsample.comp"}}, withNearField({"TRACE_LISTED 1"}));
    if (inBlocks && !upsampleProgram_.id()) {
        upsampleProgram_ = gl::buildProgram({{GL_COMPUTE_SHADER, "cone_upsample.comp"}});
        smoothListedProgram_ = gl::buildProgram({{GL_COMPUTE_SHADER, "cone_upsample.comp"}}, {"SMOOTH_LISTED 1"});
        ownTracePixels_ = gl::createBuffer(GLsizeiptr(4) * width_ * height_, nullptr, 0, "pixels that trace their own cones");
        ownTraceSmoothed_ = gl::createBuffer(GLsizeiptr(16) * width_ * height_, nullptr, 0,
                                             "own-traced pixels' light averaged over their surface");
        dispatchArgs_ = gl::createBuffer(12, nullptr, 0, "own traces' dispatch arguments");
    }
    const std::uint32_t zero = 0;
    glClearNamedBufferData(counters_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

    // Every pass that traces cones reads the cone set, the pixels' surfaces and the counters.
    auto tracingCall = [&](const gl::Program& program) {
        gl::ComputeCall call(program);
        setConeMarchUniforms(call, octree, radiance, settings);
        call.texture(gl::TEXTURE_GBUFFER_NORMAL, gbuffer.normal())
            .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, gbuffer.geometricNormal())
            .texture(gl::TEXTURE_GBUFFER_POSITION, gbuffer.position())
            .storage(gl::SSBO_CONE_COUNTERS, counters_)
            .uniform("uDownscale", block)
            .uniform("uRaySequence", sampleCones.raySequence)
            .texture(gl::TEXTURE_NEAR_FIELD_DIRECT, directRadiance)
            .texture(gl::TEXTURE_NEAR_FIELD_EMISSIVE, gbuffer.emissive())
            .uniform("uViewProjection", view.viewProjection)
            .uniform("uEye", view.eye);
        return call;
    };
    // Narrow cones go a few per dispatch (kNarrowConesPerDispatch), each dispatch adding to what
    // the ones before stored; the cone set in one.
    const int rayBatches = settings.rays > 0 ? (settings.rays + kNarrowConesPerDispatch - 1) / kNarrowConesPerDispatch : 1;
    auto selectBatch = [&](gl::ComputeCall& call, int batch) {
        if (settings.rays > 0)
            call.uniform("uRayFirst", batch * kNarrowConesPerDispatch)
                .uniform("uRayEnd", std::min((batch + 1) * kNarrowConesPerDispatch, settings.rays));
    };
    // Neighbours share the frame's own narrow cones (the later samples' one cone each continues a
    // sequence per block instead); a different traced image or cone count makes a new ConeReuse.
    const bool reuse = reusesCones(settings) && sampleCones.raySequence < 0 &&
                       ConeReuse::coneBytes(tracedWidth, tracedHeight, settings.rays) <= kMaxConeReuseBytes;
    if (reuse && (!reuse_ || reuse_->width() != tracedWidth || reuse_->height() != tracedHeight ||
                  reuse_->rays() != settings.rays))
        reuse_ = std::make_unique<ConeReuse>(tracedWidth, tracedHeight, settings.rays);
    // The cells that trace are listed (cone_carry.comp): in a frame after a camera move, not those
    // whose pixels all take the last frame's light. Only a frame's first sample carries it and is
    // remembered: the later ones trace other pixels of each block with other cones.
    const GLuint tracedImage = inBlocks ? traced_.id() : indirect_.id();
    if (!carry_ || carry_->tracedWidth() != tracedWidth || carry_->tracedHeight() != tracedHeight)
        carry_ = std::make_unique<ConeCarry>(width_, height_, tracedWidth, tracedHeight);
    carry_->listCells(gbuffer, tracedImage, inBlocks ? tracedPixel_.id() : 0, counters_, {block, sceneVersion}, view,
                      sample & (block * block - 1), octree.grid.voxelSize, sample == 0 ? settings.carryVoxels : 0.0f);
    // A dispatch over the listed cells (the trace, and with lanes the sum of their parts): it reads
    // the list and adds to what the batches before stored in the traced image.
    auto dispatchOverListedCells = [&](gl::ComputeCall& call, int batch) {
        selectBatch(call, batch);
        call.storage(gl::SSBO_CONE_COUNTERS, counters_)
            .storage(gl::SSBO_TRACE_CELLS, carry_->traceCells())
            .image(gl::IMAGE_INDIRECT, tracedImage, GL_READ_WRITE, GL_RGBA32F)
            .uniform("uDownscale", block);
        if (lanes > 1) call.storage(gl::SSBO_CONE_LANE_PARTS, laneParts_);
        listDispatch_.dispatch(call, counters_, gl::TRACE_CELL_COUNT_SLOT, traceArgs_, 0,
                               GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                   GL_SHADER_STORAGE_BARRIER_BIT);
    };
    for (int batch = 0; batch < rayBatches; ++batch) {
        gl::ComputeCall call = tracingCall(traceProgram);
        call.uniform("uStoreConeSamples", reuse ? 1 : 0).uniform("uConeSampleRowLength", tracedWidth);
        if (reuse) call.storage(gl::SSBO_CONE_SAMPLES, reuse_->cones());
        dispatchOverListedCells(call, batch);
        if (lanes > 1) {
            gl::ComputeCall sum(sumLanesPrograms_[lanes]);
            dispatchOverListedCells(sum, batch);
        }
    }
    // The sharing and the filter run on the traced image; a different image size (another GI
    // resolution) makes a new filter.
    GLuint traced = tracedImage;
    if (reuse)
        traced = reuse_->render(gbuffer, traced, inBlocks ? tracedPixel_.id() : 0, octree.grid.voxelSize, settings.offset,
                                settings.reuseVoxels);
    if (filterVoxels > 0.0f) {
        if (!filter_ || filter_->width() != tracedWidth || filter_->height() != tracedHeight)
            filter_ = std::make_unique<IndirectFilter>(tracedWidth, tracedHeight);
        traced = filter_->render(gbuffer, traced, inBlocks ? tracedPixel_.id() : 0, octree.grid.voxelSize, filterVoxels);
    }
    result_ = inBlocks ? indirect_.id() : traced;
    if (inBlocks) {
        // Every pixel from the traced blocks, or listed to trace its own cones; then the listed.
        auto upsampleCall = [&](const gl::Program& program) {
            gl::ComputeCall call = tracingCall(program);
            call.texture(gl::TEXTURE_TRACED_IRRADIANCE, traced)
                .texture(gl::TEXTURE_TRACED_PIXEL, tracedPixel_.id())
                .storage(gl::SSBO_OWN_TRACE_PIXELS, ownTracePixels_)
                .image(gl::IMAGE_INDIRECT, indirect_.id(), GL_READ_WRITE, GL_RGBA32F);
            return call;
        };
        gl::ComputeCall upsample = upsampleCall(upsampleProgram_);
        carry_->bindCarried(upsample);
        upsample.dispatchImage(width_, height_,
                               GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        for (int batch = 0; batch < rayBatches; ++batch) {
            gl::ComputeCall call = upsampleCall(traceListedProgram);
            selectBatch(call, batch);
            listDispatch_.dispatch(call, counters_, gl::OWN_TRACE_COUNT_SLOT, dispatchArgs_, 0,
                                   GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        // Then each listed pixel averaged with the pixels around it on its own surface, into a
        // buffer, and written back.
        for (int writeBack = 0; writeBack < 2; ++writeBack) {
            gl::ComputeCall call = upsampleCall(smoothListedProgram_);
            call.storage(gl::SSBO_OWN_TRACE_SMOOTHED, ownTraceSmoothed_).uniform("uWriteBack", writeBack);
            listDispatch_.dispatch(call, counters_, gl::OWN_TRACE_COUNT_SLOT, dispatchArgs_, 0,
                                   GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                       GL_TEXTURE_FETCH_BARRIER_BIT);
        }
        if (sample == 0) carry_->remember(indirect_.id());
    }
    // After the carry remembers the cones' light: a later frame that carries it adds the detail of
    // its own pixels.
    if (frame.nearDetail) {
        if (!nearDetail_) nearDetail_ = std::make_unique<NearDetail>(width_, height_);
        result_ = nearDetail_->render(gbuffer, result_, directRadiance, view, octree.grid.voxelSize, settings.offset);
    }
    gl::checkErrors("tracing cones");
}

}  // namespace vct
