#include "gl/gl.hpp"

#include "core/error.hpp"

namespace vct::gl {

const char* errorName(GLenum error) {
    switch (error) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
        case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
        default: return "unknown GL error";
    }
}

void checkErrors(const std::string& what) {
    GLenum first = glGetError();
    if (first == GL_NO_ERROR) return;
    while (glGetError() != GL_NO_ERROR) {
    }
    if (first == GL_OUT_OF_MEMORY)
        fail("the GPU ran out of memory while ", what,
             "; lower the resolution or --voxel-levels, or close other GPU programs");
    fail("OpenGL error ", errorName(first), " while ", what, " (an engine bug: please report it with the command line)");
}

}  // namespace vct::gl
