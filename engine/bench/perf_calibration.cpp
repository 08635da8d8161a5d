#include "bench/perf_calibration.hpp"

#include <chrono>
#include <cstring>
#include <vector>

#include "core/error.hpp"
#include "gl/compute.hpp"
#include "gl/raster_state.hpp"
#include "gl/shader.hpp"

namespace vct::bench {
namespace {

// Sized so that each workload takes about as long as a middling pass of the guard's frame on
// llvmpipe (tens of milliseconds): long enough for the clock, short enough to repeat.
constexpr GLuint kComputeInvocations = 1u << 16;
constexpr GLuint kComputeIterations = 384;
constexpr GLuint kDataWords = 1u << 20;  // 4 MiB: scattered reads miss the caches, as octree walks do
constexpr int kTargetSize = 512;
constexpr int kCellsPerSide = 64;
constexpr int kLayers = 8;
constexpr int kFragmentIterations = 8;

}  // namespace

const char* workKindName(WorkKind kind) { return kind == WorkKind::Raster ? "raster" : "compute"; }

WorkKind passWorkKind(Pass pass) {
    return std::strstr(declaration(pass).shaders, ".vert") ? WorkKind::Raster : WorkKind::Compute;
}

PerfCalibration::PerfCalibration()
    : computeProgram_(gl::buildProgram({{GL_COMPUTE_SHADER, "perf_calibration.comp"}})),
      rasterProgram_(gl::buildProgram(
          {{GL_VERTEX_SHADER, "perf_calibration.vert"}, {GL_FRAGMENT_SHADER, "perf_calibration.frag"}})),
      colour_(gl::createTexture2D(GL_RGBA16F, kTargetSize, kTargetSize, 1, "calibration colour")),
      depth_(gl::createTexture2D(GL_DEPTH_COMPONENT32F, kTargetSize, kTargetSize, 1, "calibration depth")),
      framebuffer_(gl::createFramebuffer("calibration")),
      vertexArray_(gl::createVertexArray()) {
    std::vector<GLuint> words(kDataWords);
    for (GLuint i = 0; i < kDataWords; ++i) words[i] = i * 2654435761u;
    data_ = gl::createBuffer(GLsizeiptr(words.size() * sizeof(GLuint)), words.data(), GL_DYNAMIC_STORAGE_BIT,
                             "calibration data");
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, colour_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail("the calibration framebuffer is incomplete on this driver");
}

void PerfCalibration::compute() {
    gl::ComputeCall(computeProgram_)
        .storage(gl::SSBO_CALIBRATION_DATA, data_)
        .uniform("uIterations", kComputeIterations)
        .uniform("uAddressMask", kDataWords - 1)
        .dispatch1D(kComputeInvocations, 64, GL_SHADER_STORAGE_BARRIER_BIT);
}

void PerfCalibration::raster() {
    gl::beginRasterPass({framebuffer_.id(), kTargetSize, kTargetSize, true});
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, zero);
    glUseProgram(rasterProgram_.id());
    gl::setUniform(rasterProgram_.id(), "uCellsPerSide", kCellsPerSide);
    gl::setUniform(rasterProgram_.id(), "uFragmentIterations", kFragmentIterations);
    glBindVertexArray(vertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 6 * kCellsPerSide * kCellsPerSide * kLayers);
    glBindVertexArray(0);
    gl::endRasterPass();
}

double PerfCalibration::run(WorkKind kind) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    if (kind == WorkKind::Raster)
        raster();
    else
        compute();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace vct::bench
