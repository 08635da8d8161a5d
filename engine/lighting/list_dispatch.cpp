#include "lighting/list_dispatch.hpp"

#include "gl/driver_checks.hpp"

namespace vct {

ListDispatch::ListDispatch() : args_(gl::buildProgram({{GL_COMPUTE_SHADER, "indirect_args.comp"}})) {}

void bindRadianceVolume(const RadianceVolume& v) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_LIST_COUNTS, v.listCounts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_RADIANCE_ACCUMULATORS, v.accumulators.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_TOUCHED_FLAG, v.touchedFlag.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_TOUCHED_LIST, v.touchedList.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_BORDER_FLAG, v.borderFlag.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_BORDER_LIST, v.borderList.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_CELL_RADIANCE, v.cellRadiance.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_INDIRECT_ARGS, v.indirectArgs.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_CELL_EXIT_SHARES, v.cellExitShares.id());
}

void ListDispatch::dispatch(const gl::ComputeCall& call, const RadianceVolume& volume, unsigned countSlot,
                            GLbitfield barriers, unsigned itemsPerGroup) {
    dispatch(call, volume.listCounts, countSlot, volume.indirectArgs, countSlot, barriers, itemsPerGroup);
}

void ListDispatch::dispatch(const gl::ComputeCall& call, const gl::Buffer& counts, unsigned countSlot,
                            const gl::Buffer& args, unsigned argsSlot, GLbitfield barriers, unsigned itemsPerGroup) {
    // Only what indirect_args.comp reads is bound: the caller's other bindings (e.g. which
    // channel's cell values sit at SSBO_CELL_RADIANCE) must survive to its own dispatch.
    gl::ComputeCall(args_)
        .uniform("uCountSlot", countSlot)
        .uniform("uArgsSlot", argsSlot)
        .uniform("uItemsPerGroup", itemsPerGroup)
        .storage(gl::SSBO_LIST_COUNTS, counts)
        .storage(gl::SSBO_INDIRECT_ARGS, args)
        .dispatch(1, 1, 1, GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(call.program());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, args.id());
    glDispatchComputeIndirect(GLintptr(argsSlot) * 12);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    gl::memoryBarrier(barriers);
}

}  // namespace vct
