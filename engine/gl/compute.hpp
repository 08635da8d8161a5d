#pragma once
// Helpers for compute dispatches over 1D work that may exceed the 65535-group limit per axis.
#include <cstdint>

#include "gl/gl.hpp"

namespace vct::gl {

struct DispatchSize {
    GLuint x = 0, y = 0;
};

// Groups of `groupSize` covering `items`, laid out as x ≤ 65535, y as needed. Shaders recover
// the linear index with linearInvocation() (octree.glsl) and bounds-check against the count.
inline DispatchSize dispatchSize(std::uint64_t items, GLuint groupSize) {
    const std::uint64_t groups = (items + groupSize - 1) / groupSize;
    DispatchSize size;
    size.x = GLuint(groups < 65535 ? groups : 65535);
    size.y = size.x ? GLuint((groups + size.x - 1) / size.x) : 0;
    return size;
}

inline void dispatch1D(std::uint64_t items, GLuint groupSize) {
    const DispatchSize size = dispatchSize(items, groupSize);
    if (size.x) glDispatchCompute(size.x, size.y, 1);
}

}  // namespace vct::gl
