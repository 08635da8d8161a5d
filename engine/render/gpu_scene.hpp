#pragma once
// The scene's geometry and materials on the GPU: one interleaved vertex buffer, one index
// buffer sorted by material, and one mipmapped sRGB texture per base-colour image. Every pass
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

    // Draws every triangle with `program` bound; sets its material uniforms (shaders/
    // material.glsl) and binds the base-colour texture at gl::TEXTURE_BASE_COLOR.
    void draw(GLuint program) const;

    std::size_t bytes() const { return bytes_; }

    // Replaces material `index`'s colour, alpha and emission (textures stay).
    void setMaterial(std::size_t index, const Material& material);
    GLuint materialBuffer() const { return materialBuffer_.id(); }
    bool hasEmission() const;
    float maxEmission() const;  // largest emitted radiance component of any material

private:
    struct GpuMaterial {
        glm::vec3 baseColor;
        float baseAlpha;
        glm::vec3 emissive;
        float alphaCutoff;  // negative: opaque
        int texture;        // index into textures_, −1 none
    };

    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    gl::Buffer indices_;
    std::vector<gl::Texture> textures_;
    std::vector<GpuMaterial> materials_;
    gl::Buffer materialBuffer_;
    void uploadMaterial(std::size_t index);
    std::vector<DrawRange> ranges_;
    std::size_t bytes_ = 0;
};

}  // namespace vct
