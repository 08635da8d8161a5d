#include "gl/prefix_sum.hpp"

#include "gl/compute.hpp"
#include "gl/shader_interface.hpp"

namespace vct::gl {

PrefixSum::PrefixSum() : program_(buildProgram({{GL_COMPUTE_SHADER, "prefix_sum.comp"}})) {}

void PrefixSum::scanLevel(GLuint buffer, std::uint32_t count, std::size_t depth) {
    const std::uint32_t blocks = (count + 255) / 256;
    if (blockSums_.size() <= depth) {
        blockSums_.emplace_back();
        blockSumCapacity_.push_back(0);
    }
    if (blockSumCapacity_[depth] < blocks) {
        blockSums_[depth] = createBuffer(GLsizeiptr(blocks) * 4, nullptr, GL_DYNAMIC_STORAGE_BIT, "prefix sum blocks");
        blockSumCapacity_[depth] = blocks;
    }
    auto pass = [&](int phase) {
        ComputeCall(program_)
            .storage(SSBO_PREFIX_VALUES, buffer)
            .storage(SSBO_PREFIX_BLOCK_SUMS, blockSums_[depth])
            .uniform("uCount", count)
            .uniform("uPhase", phase)
            .dispatch1D(count, 256, GL_SHADER_STORAGE_BARRIER_BIT);
    };
    pass(0);
    if (blocks > 1) {
        scanLevel(blockSums_[depth].id(), blocks, depth + 1);
        pass(1);
    }
}

std::uint32_t PrefixSum::scan(GLuint buffer, std::uint32_t count) {
    if (count == 0) return 0;
    // The total is the last exclusive value plus the last input value.
    std::uint32_t last = 0;
    glGetNamedBufferSubData(buffer, GLintptr(count - 1) * 4, 4, &last);
    scanLevel(buffer, count, 0);
    std::uint32_t lastPrefix = 0;
    glGetNamedBufferSubData(buffer, GLintptr(count - 1) * 4, 4, &lastPrefix);
    return lastPrefix + last;
}

}  // namespace vct::gl
