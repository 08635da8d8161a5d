#include "lighting/list_dispatch.hpp"

#include "gl/shader.hpp"

namespace vct {

ListDispatch::ListDispatch() : args_(gl::buildProgram({{GL_COMPUTE_SHADER, "indirect_args.comp"}})) {}

void bindRadianceVolume(const RadianceVolume& v) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, v.listCounts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 13, v.accumulators.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 14, v.touchedFlag.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 15, v.touchedList.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 16, v.borderFlag.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 17, v.borderList.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 18, v.cellRadiance.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 19, v.indirectArgs.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 23, v.cellDirection.id());
}

void ListDispatch::dispatch(const RadianceVolume& volume, unsigned countSlot) {
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glUseProgram(args_.id());
    gl::setUniform(args_.id(), "uCountSlot", countSlot);
    gl::setUniform(args_.id(), "uArgsSlot", countSlot);
    // Only what indirect_args.comp reads: the caller's other bindings (e.g. which channel's cell
    // values sit at binding 18) must survive to its own dispatch.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, volume.listCounts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 19, volume.indirectArgs.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(GLuint(current));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, volume.indirectArgs.id());
    glDispatchComputeIndirect(GLintptr(countSlot) * 12);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

}  // namespace vct
