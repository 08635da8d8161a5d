#pragma once
// Exclusive prefix sum of a uint buffer on the GPU. Used to give each octree node the place of
// its children without atomics, so the node pool is the same on every run (DESIGN 5.2).
#include <cstdint>
#include <vector>

#include "gl/objects.hpp"

namespace vct::gl {

class PrefixSum {
public:
    PrefixSum();
    // Replaces values[0..count) by their exclusive prefix sum; returns the total (read back).
    std::uint32_t scan(GLuint buffer, std::uint32_t count);

private:
    void scanLevel(GLuint buffer, std::uint32_t count, std::size_t depth);
    Program program_;
    std::vector<Buffer> blockSums_;  // one per recursion depth, grown on demand
    std::vector<std::uint32_t> blockSumCapacity_;
};

}  // namespace vct::gl
