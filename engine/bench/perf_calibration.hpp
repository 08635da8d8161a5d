#pragma once
// Fixed workloads that the performance guard measures every pass against (bench/pass_ratios.hpp,
// docs/benchmark.md "The performance guard"). Run in the same process, moments apart, they meet
// the same CPU or GPU, clock and load as the passes, so a pass's time divided by a calibration's
// describes the engine's code rather than the machine: a ratio recorded on one machine still
// means something on a slower, busier or different one.
//
// Two kinds, because drivers run them on different machinery (llvmpipe: compute as compiled loops
// over the invocations, triangles through its binner and tile threads; a GPU: other units):
//   compute: integer hashing, float arithmetic, scattered buffer reads and atomics;
//   raster: layers of small overlapping quads, depth-tested, with some arithmetic per fragment.
#include "gl/objects.hpp"
#include "pipeline/frame_passes.hpp"

namespace vct::bench {

enum class WorkKind { Compute, Raster };
const char* workKindName(WorkKind kind);

// A pass that draws triangles (one of its shaders is a vertex shader) is raster work; the rest
// is compute.
WorkKind passWorkKind(Pass pass);

class PerfCalibration {
public:
    PerfCalibration();

    // Wall-clock milliseconds of one run of the workload, from an idle GPU (glFinish before) to
    // the end of its work (glFinish after).
    double run(WorkKind kind);

private:
    void compute();
    void raster();

    gl::Program computeProgram_, rasterProgram_;
    gl::Buffer data_;
    gl::Texture colour_, depth_;
    gl::Framebuffer framebuffer_;
    gl::VertexArray vertexArray_;
};

}  // namespace vct::bench
