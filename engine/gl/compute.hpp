#pragma once
// Compute dispatches: the sequence every compute pass repeats (use the program, bind what it
// reads and writes, set its uniforms, dispatch, make the results visible to what comes next) as
// one small object, and 1D work that may exceed the 65535-group limit per axis.
#include <cstdint>

#include "gl/driver_checks.hpp"
#include "gl/objects.hpp"
#include "gl/shader.hpp"
#include "gl/shader_interface.hpp"

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

// One use of a compute program. Bindings name the slots of gl/shader_interface.hpp:
//   ComputeCall(program_).storage(SSBO_CELL_AREA, octree.cellArea).uniform("uLevel", level)
//       .dispatch1D(count, 64, GL_SHADER_STORAGE_BARRIER_BIT);
// Every dispatch ends with the memory barrier its results need, so no pass forgets one.
class ComputeCall {
public:
    explicit ComputeCall(const Program& program) : program_(program.id()) { glUseProgram(program_); }

    ComputeCall& storage(GLuint binding, GLuint buffer) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
        return *this;
    }
    ComputeCall& storage(GLuint binding, const Buffer& buffer) { return storage(binding, buffer.id()); }
    // A buffer texture or a 2D image; `layered` for a whole 3D texture.
    ComputeCall& image(GLuint unit, GLuint texture, GLenum access, GLenum format, bool layered = false) {
        glBindImageTexture(unit, texture, 0, layered ? GL_TRUE : GL_FALSE, 0, access, format);
        return *this;
    }
    ComputeCall& texture(GLuint unit, GLuint texture) {
        glBindTextureUnit(unit, texture);
        return *this;
    }
    template <class T>
    ComputeCall& uniform(const char* name, const T& value) {
        setUniform(program_, name, value);
        return *this;
    }

    void dispatch(GLuint x, GLuint y, GLuint z, GLbitfield barriers) const {
        glUseProgram(program_);
        if (x && y && z) glDispatchCompute(x, y, z);
        memoryBarrier(barriers);
    }
    // One invocation per item, in groups of `groupSize` (the shader's local size).
    void dispatch1D(std::uint64_t items, GLuint groupSize, GLbitfield barriers) const {
        const DispatchSize size = dispatchSize(items, groupSize);
        dispatch(size.x, size.y, 1, barriers);
    }
    // One invocation per pixel of a width × height image, in 8 × 8 groups.
    void dispatchImage(int width, int height, GLbitfield barriers) const {
        dispatch(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1, barriers);
    }

    GLuint program() const { return program_; }

private:
    GLuint program_;
};

}  // namespace vct::gl
