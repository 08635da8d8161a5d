#include "render/gpu_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/error.hpp"
#include "gl/shader.hpp"
#include "gl/shader_interface.hpp"

namespace vct {

namespace {
bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return GL_REPEAT;
}

// The filtering every scene texture gets (set on the texture itself and on the wrap samplers).
constexpr GLint kMinFilter = GL_LINEAR_MIPMAP_LINEAR, kMagFilter = GL_LINEAR;
constexpr float kMaxAnisotropy = 8.0f;

float maxAnisotropy() {
    if (!(GLAD_GL_ARB_texture_filter_anisotropic || GLAD_GL_EXT_texture_filter_anisotropic)) return 1.0f;
    GLfloat limit = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &limit);
    return std::min(kMaxAnisotropy, limit);
}
}  // namespace

GpuScene::GpuScene(const Scene& scene) : vertexArray_(gl::createVertexArray()) {
    // Loaders and built-in scenes are cleaned by buildSceneGeometry; a Scene filled in by hand may
    // not be, and rasterizers treat NaN vertices differently: refuse it before anything is drawn.
    std::size_t badVertices = 0;
    for (const Vertex& v : scene.vertices)
        badVertices += !finite3(v.position) || !finite3(v.normal) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y);
    if (badVertices > 0)
        fail("scene '", scene.name, "' has ", badVertices, " vertices with non-finite positions, normals or texture "
             "coordinates; build scenes through buildSceneGeometry (the loaders do), which refuses or repairs them");
    for (std::uint32_t index : scene.indices)
        if (index >= scene.vertices.size())
            fail("scene '", scene.name, "' has a vertex index ", index, " beyond its ", scene.vertices.size(), " vertices");
    for (const DrawRange& r : scene.drawRanges)
        if (std::size_t(r.firstIndex) + r.indexCount > scene.indices.size() || r.material >= scene.materials.size())
            fail("scene '", scene.name, "' has a draw range beyond its indices or materials");
    vertices_ = gl::createBuffer(GLsizeiptr(scene.vertices.size() * sizeof(Vertex)), scene.vertices.data(), 0,
                                 "scene vertices");
    indices_ = gl::createBuffer(GLsizeiptr(scene.indices.size() * sizeof(std::uint32_t)), scene.indices.data(), 0,
                                "scene indices");
    bytes_ = scene.vertices.size() * sizeof(Vertex) + scene.indices.size() * sizeof(std::uint32_t);

    const GLuint vao = vertexArray_.id();
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.id());
    // Attribute locations as in shaders/material_vertex.glsl.
    const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv),
                              offsetof(Vertex, uv1), offsetof(Vertex, color)};
    const GLint sizes[] = {3, 3, 2, 2, 3};
    for (GLuint attribute = 0; attribute < 5; ++attribute) {
        glEnableVertexArrayAttrib(vao, attribute);
        glVertexArrayAttribFormat(vao, attribute, sizes[attribute], GL_FLOAT, GL_FALSE, offsets[attribute]);
        glVertexArrayAttribBinding(vao, attribute, 0);
    }

    anisotropy_ = maxAnisotropy();
    for (const Texture& texture : scene.textures) {
        const int levels = 1 + int(std::floor(std::log2(std::max(texture.width, texture.height))));
        gl::Texture gpu = gl::createTexture(GL_TEXTURE_2D, texture.name.c_str());
        // sRGB storage: sampling returns linear values and mipmaps/filtering happen in linear space.
        glTextureStorage2D(gpu.id(), levels, GL_SRGB8_ALPHA8, texture.width, texture.height);
        // Scene textures are stored top row first; GL's t = 0 is the bottom row, matching the
        // bottom-left UV origin Assimp gives every format (glTF's v is flipped on import).
        const std::size_t rowBytes = std::size_t(texture.width) * 4;
        for (int y = 0; y < texture.height; ++y)
            glTextureSubImage2D(gpu.id(), 0, 0, texture.height - 1 - y, texture.width, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                                texture.rgba.data() + rowBytes * y);
        glGenerateTextureMipmap(gpu.id());
        glTextureParameteri(gpu.id(), GL_TEXTURE_MIN_FILTER, kMinFilter);
        glTextureParameteri(gpu.id(), GL_TEXTURE_MAG_FILTER, kMagFilter);
        glTextureParameteri(gpu.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(gpu.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
        if (anisotropy_ > 1.0f) glTextureParameterf(gpu.id(), GL_TEXTURE_MAX_ANISOTROPY, anisotropy_);
        gl::checkErrors(concat("uploading texture '", texture.name, "' (", texture.width, "x", texture.height, ")"));
        bytes_ += rowBytes * texture.height * 4 / 3;
        textures_.push_back(std::move(gpu));
    }

    if (scene.materials.size() > 65536)
        fail("the scene has ", scene.materials.size(), " materials; vct supports at most 65,536 (voxel fragments keep "
             "a 16-bit material index). Merge materials in the model");
    materialBuffer_ = gl::createBuffer(GLsizeiptr(std::max<std::size_t>(scene.materials.size(), 1) * 32), nullptr,
                                       GL_DYNAMIC_STORAGE_BIT, "materials");
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        materials_.push_back({});
        setMaterial(i, scene.materials[i]);
    }
    ranges_ = scene.drawRanges;
    for (const DrawRange& range : ranges_) {
        bool coloured = false;
        for (std::uint32_t i = range.firstIndex; i < range.firstIndex + range.indexCount && !coloured; ++i)
            coloured = scene.vertices[scene.indices[i]].color != glm::vec3(1.0f);
        rangeHasVertexColors_.push_back(coloured);
    }
}

void GpuScene::setMaterial(std::size_t index, const Material& material) {
    if (!finite3(material.baseColor) || !finite3(material.emissive) || !std::isfinite(material.baseAlpha) ||
        !std::isfinite(material.alphaCutoff) || glm::any(glm::lessThan(material.baseColor, glm::vec3(0.0f))) ||
        glm::any(glm::lessThan(material.emissive, glm::vec3(0.0f))))
        fail("material '", material.name, "': colour (", material.baseColor.x, ", ", material.baseColor.y, ", ",
             material.baseColor.z, "), alpha ", material.baseAlpha, ", emission (", material.emissive.x, ", ",
             material.emissive.y, ", ", material.emissive.z, ") and cutoff ", material.alphaCutoff,
             " must be finite and not negative");
    GpuMaterial& m = materials_.at(index);
    m.baseColor = material.baseColor;
    m.baseAlpha = material.baseAlpha;
    m.emissive = material.emissive;
    m.alphaCutoff = material.alphaMode == AlphaMode::Mask ? material.alphaCutoff : -1.0f;
    m.texture = material.baseColorTexture;
    m.texCoordSet = material.baseColorMapping.texCoord;
    m.uvTransform = material.baseColorMapping.transform;
    m.sampler = samplerFor(material.baseColorMapping.wrapS, material.baseColorMapping.wrapT, Filtering::Anisotropic);
    m.isotropicSampler = samplerFor(material.baseColorMapping.wrapS, material.baseColorMapping.wrapT, Filtering::Isotropic);
    const glm::vec4 values[2] = {glm::vec4(material.baseColor, material.baseAlpha), glm::vec4(material.emissive, 0.0f)};
    glNamedBufferSubData(materialBuffer_.id(), GLintptr(index * sizeof values), sizeof values, values);
}

GLuint GpuScene::samplerFor(TextureWrap wrapS, TextureWrap wrapT, Filtering filtering) {
    // Anisotropic plain repeat is what the textures themselves are set to: no sampler object, so
    // scenes without wrap modes are sampled exactly as before.
    const bool anisotropic = filtering == Filtering::Anisotropic;
    if (anisotropic && wrapS == TextureWrap::Repeat && wrapT == TextureWrap::Repeat) return 0;
    gl::Sampler& sampler = samplers_[anisotropic ? 0 : 1][3 * int(wrapS) + int(wrapT)];
    if (sampler.id() == 0) {
        sampler = gl::createSampler();
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MIN_FILTER, kMinFilter);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_MAG_FILTER, kMagFilter);
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_S, glWrap(wrapS));
        glSamplerParameteri(sampler.id(), GL_TEXTURE_WRAP_T, glWrap(wrapT));
        if (anisotropic && anisotropy_ > 1.0f) glSamplerParameterf(sampler.id(), GL_TEXTURE_MAX_ANISOTROPY, anisotropy_);
    }
    return sampler.id();
}

bool GpuScene::hasEmission() const { return maxEmission() > 0.0f; }

float GpuScene::maxEmission() const {
    float m = 0.0f;
    for (const GpuMaterial& material : materials_) m = std::max({m, material.emissive.x, material.emissive.y, material.emissive.z});
    return m;
}

void GpuScene::draw(GLuint program, Materials which, Filtering filtering) const {
    glBindVertexArray(vertexArray_.id());
    for (std::size_t r = 0; r < ranges_.size(); ++r) {
        const DrawRange& range = ranges_[r];
        const GpuMaterial& m = materials_[range.material];
        const bool masked = m.alphaCutoff >= 0.0f;
        if ((which == Materials::Opaque && masked) || (which == Materials::Masked && !masked)) continue;
        gl::setUniform(program, "uVertexColors", rangeHasVertexColors_[r] ? 1 : 0);
        gl::setUniform(program, "uMaterialIndex", int(range.material));
        gl::setUniform(program, "uBaseColor", glm::vec4(m.baseColor, m.baseAlpha));
        gl::setUniform(program, "uEmissive", m.emissive);
        gl::setUniform(program, "uAlphaCutoff", m.alphaCutoff);
        gl::setUniform(program, "uHasTexture", m.texture >= 0 ? 1 : 0);
        gl::setUniform(program, "uTexCoordSet", m.texCoordSet);
        gl::setUniform(program, "uUvTransform", m.uvTransform);
        glBindTextureUnit(gl::TEXTURE_BASE_COLOR, m.texture >= 0 ? textures_[std::size_t(m.texture)].id() : 0);
        glBindSampler(gl::TEXTURE_BASE_COLOR, filtering == Filtering::Anisotropic ? m.sampler : m.isotropicSampler);
        glDrawElements(GL_TRIANGLES, GLsizei(range.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(std::uintptr_t(range.firstIndex) * sizeof(std::uint32_t)));
    }
    glBindVertexArray(0);
    glBindSampler(gl::TEXTURE_BASE_COLOR, 0);  // later passes use the unit with their textures' own settings
}

}  // namespace vct
