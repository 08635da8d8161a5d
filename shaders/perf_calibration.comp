#version 450
// The compute half of the performance guard's calibration (engine/bench/perf_calibration.hpp): a
// fixed amount of the work vct's compute passes are made of (integer hashing, float arithmetic
// with a square root, reads at scattered addresses, an atomic per invocation), so that a pass's
// time divided by this one's does not depend on how fast the machine is.
layout(local_size_x = 64) in;

layout(std430, binding = SSBO_CALIBRATION_DATA) buffer Data { uint data[]; };

uniform uint uIterations;
uniform uint uAddressMask;  // the buffer's length − 1 (a power of two)

void main() {
    const uint id = gl_GlobalInvocationID.x;
    uint h = id * 747796405u + 2891336453u;
    float sum = 0.0;
    for (uint i = 0u; i < uIterations; ++i) {
        h ^= h >> 16;
        h *= 0x7feb352du;
        h ^= h >> 15;
        sum = sqrt(sum * sum * 0.5 + float(data[h & uAddressMask] & 1023u));
    }
    atomicAdd(data[id & uAddressMask], uint(sum) & 7u);
}
