#pragma once
// RAII owners for OpenGL objects. These are the only places in vct that create or delete GL
// names; everything else holds one of these. Move-only: a GL name has exactly one owner.
#include <utility>

#include "gl/gl.hpp"

namespace vct::gl {

template <class Traits>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Traits::destroy(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

struct BufferTraits { static void destroy(GLuint id) { glDeleteBuffers(1, &id); } };
struct TextureTraits { static void destroy(GLuint id) { glDeleteTextures(1, &id); } };
struct FramebufferTraits { static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); } };
struct VertexArrayTraits { static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); } };
struct QueryTraits { static void destroy(GLuint id) { glDeleteQueries(1, &id); } };
struct ProgramTraits { static void destroy(GLuint id) { glDeleteProgram(id); } };
struct ShaderTraits { static void destroy(GLuint id) { glDeleteShader(id); } };
struct SamplerTraits { static void destroy(GLuint id) { glDeleteSamplers(1, &id); } };

using Buffer = Handle<BufferTraits>;
using Texture = Handle<TextureTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Query = Handle<QueryTraits>;
using Program = Handle<ProgramTraits>;
using Shader = Handle<ShaderTraits>;
using Sampler = Handle<SamplerTraits>;

// Creation through DSA (GL 4.5).
Buffer createBuffer(GLsizeiptr bytes, const void* data, GLbitfield storageFlags, const char* label);
Texture createTexture(GLenum target, const char* label);
Framebuffer createFramebuffer(const char* label);
VertexArray createVertexArray();
Query createQuery(GLenum target);
Sampler createSampler();

// Storage that a pass needs anew at every rebuild of the octree (sized by its node or cell
// counts): keeps `buffer` while it holds at least `bytes` and no more than a quarter beyond
// (same storage flags), else replaces it, with an eighth to spare (rounded up to 16 bytes) when
// it replaces an earlier one, so that geometry that moves a little does not reallocate every
// frame. Allocating, and on some drivers clearing, hundreds of MB per rebuild cost more than the
// passes' own work. The contents are undefined either way (poisoned again under VCT_GL_POISON);
// returns true when the buffer was replaced.
bool fitBuffer(Buffer& buffer, GLsizeiptr bytes, GLbitfield storageFlags, const char* label);
// The buffer's size in bytes (0 for none).
GLsizeiptr bufferBytes(const Buffer& buffer);

// A 2D texture with immutable storage (levels ≥ 1), filtering set to match.
Texture createTexture2D(GLenum internalFormat, int width, int height, int levels, const char* label);

}  // namespace vct::gl
