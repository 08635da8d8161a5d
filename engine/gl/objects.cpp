#include "gl/objects.hpp"

#include <cstring>

#include "core/error.hpp"
#include "gl/driver_checks.hpp"

namespace vct::gl {
namespace {
void label(GLenum identifier, GLuint name, const char* text) {
    if (text && *text) glObjectLabel(identifier, name, GLsizei(std::strlen(text)), text);
}
}  // namespace

Buffer createBuffer(GLsizeiptr bytes, const void* data, GLbitfield storageFlags, const char* text) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    Buffer buffer(id);
    // An empty buffer (e.g. the cells of an octree that nothing voxelized into) still gets the
    // size of the largest element vct clears or binds (RGBA32F): GL refuses size 0, and a 1-byte
    // store made glClearNamedBufferData fail with GL_INVALID_VALUE.
    glNamedBufferStorage(id, bytes > 0 ? bytes : 16, bytes > 0 ? data : nullptr, storageFlags);
    if (!data && poisonNewStorage())
        glClearNamedBufferData(id, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &kPoisonByte);
    label(GL_BUFFER, id, text);
    checkErrors(concat("allocating buffer '", text ? text : "", "' (", bytes, " bytes)"));
    return buffer;
}

GLsizeiptr bufferBytes(const Buffer& buffer) {
    if (!buffer) return 0;
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(buffer.id(), GL_BUFFER_SIZE, &size);
    return GLsizeiptr(size);
}

bool fitBuffer(Buffer& buffer, GLsizeiptr bytes, GLbitfield storageFlags, const char* text) {
    const GLsizeiptr wanted = bytes > 0 ? bytes : 16;  // createBuffer's smallest store
    if (buffer) {
        const GLsizeiptr held = bufferBytes(buffer);
        GLint flags = 0;
        glGetNamedBufferParameteriv(buffer.id(), GL_BUFFER_STORAGE_FLAGS, &flags);
        if (held >= wanted && held - wanted <= wanted / 4 && GLbitfield(flags) == storageFlags) {
            if (poisonNewStorage())
                glClearNamedBufferData(buffer.id(), GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, &kPoisonByte);
            return false;
        }
        buffer.reset();  // before the new one: both at once may not fit
        // A whole number of the largest element vct clears with (RGBA32F), like the exact size.
        const GLsizeiptr roomy = (wanted + wanted / 8 + 15) / 16 * 16;
        buffer = createBuffer(roomy, nullptr, storageFlags, text);
        return true;
    }
    buffer = createBuffer(bytes, nullptr, storageFlags, text);
    return true;
}

Texture createTexture(GLenum target, const char* text) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    Texture texture(id);
    label(GL_TEXTURE, id, text);
    return texture;
}

Texture createTexture2D(GLenum internalFormat, int width, int height, int levels, const char* text) {
    Texture texture = createTexture(GL_TEXTURE_2D, text);
    glTextureStorage2D(texture.id(), levels, internalFormat, width, height);
    poisonNewTexture(texture.id(), internalFormat, levels);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    checkErrors(concat("allocating texture '", text ? text : "", "' (", width, "x", height, ")"));
    return texture;
}

Framebuffer createFramebuffer(const char* text) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    Framebuffer framebuffer(id);
    label(GL_FRAMEBUFFER, id, text);
    return framebuffer;
}

VertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}

Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

Sampler createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return Sampler(id);
}

}  // namespace vct::gl
