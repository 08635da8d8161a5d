#pragma once
// The scene's geometry and materials on the GPU: one interleaved vertex buffer, one index
// buffer sorted by material, and one mipmapped sRGB texture per base-colour image, sampled with
// the material's wrap modes (a sampler object per combination other than repeat) and read at
// the material's texture coordinates (set and transform: shaders/material_vertex.glsl). Every pass
// that rasterizes the scene (G-buffer, light-view map, voxelization) draws it through draw(),
// which sets the material uniforms declared in shaders/material.glsl. The same material values
// also live in a storage buffer (gl::SSBO_MATERIALS, one {baseColor, emissive} pair per material)
// for the passes that look materials up by index (svo_leaves), so that changing a material's
// colour needs no new voxelization.
#include <cstddef>
#include <vector>

#include "gl/objects.hpp"
#include "scene/scene.hpp"

namespace vct {

class GpuScene {
public:
    explicit GpuScene(const Scene& scene);

    // Which materials' triangles draw() draws: all, only the opaque ones, or only those with an
    // alpha mask (a depth-only pass draws the opaque ones with no fragment shader at all, which
    // rasterizers run much faster than a fragment shader that may discard).
    enum class Materials { All, Opaque, Masked };

    // How the base-colour textures are filtered: mipmapped and anisotropic (the textures' own
    // settings: voxelization and the light-view maps), or mipmapped only (the G-buffer, whose
    // shader filters over each pixel's footprint itself: shaders/material.glsl).
    enum class Filtering { Anisotropic, Isotropic };

    // Draws the triangles of `which` materials with `program` bound; sets its material uniforms
    // (shaders/material.glsl) and binds the base-colour texture at gl::TEXTURE_BASE_COLOR.
    void draw(GLuint program, Materials which = Materials::All, Filtering filtering = Filtering::Anisotropic) const;

    std::size_t bytes() const { return bytes_; }

    // Replaces material `index`'s colour, alpha and emission (textures stay).
    void setMaterial(std::size_t index, const Material& material);
    GLuint materialBuffer() const { return materialBuffer_.id(); }
    bool hasEmission() const;
    float maxEmission() const;  // largest emitted radiance component of any material

private:
    struct GpuMaterial {
        glm::vec3 baseColor{0.0f};
        float baseAlpha = 1.0f;
        glm::vec3 emissive{0.0f};
        float alphaCutoff = -1.0f;  // negative: opaque
        int texture = -1;           // index into textures_, −1 none
        // The base-colour texture's TextureMapping: UV set, transform, and the sampler objects of
        // its wrap modes (anisotropic: 0 for the texture's own settings, repeat; and isotropic).
        int texCoordSet = 0;
        glm::mat3 uvTransform{1.0f};
        GLuint sampler = 0;
        GLuint isotropicSampler = 0;
    };
    // The sampler object of a wrap pair, made on first use; 0 for an anisotropic repeat/repeat.
    GLuint samplerFor(TextureWrap wrapS, TextureWrap wrapT, Filtering filtering);

    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    std::vector<gl::Texture> textures_;
    gl::Sampler samplers_[2][9];  // by filtering, 3·wrapS + wrapT, made on first use (none for anisotropic repeat/repeat)
    float anisotropy_ = 1.0f;
    std::vector<GpuMaterial> materials_;
    gl::Buffer materialBuffer_;
    void uploadMaterial(std::size_t index);
    std::vector<DrawRange> ranges_;
    std::vector<bool> rangeHasVertexColors_;  // per range: some vertex colour is not white
    std::size_t bytes_ = 0;
};

}  // namespace vct
