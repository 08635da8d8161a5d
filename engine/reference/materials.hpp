#pragma once
// What the path tracer needs to know about a surface's material, evaluated the way the
// rasterizer's shaders/material.glsl does it:
//   albedo ρ = baseColor · vertex colour · texture.rgb   (linear; texture sampled by
//              TextureSampler at the material's TextureMapping of the vertex UV sets)
//   alpha    = baseAlpha · texture.a     (Mask materials: alpha < cutoff is a hole)
//   emission = Material::emissive        (W/(m²·sr), not textured, from both sides)
#include <vector>

#include <glm/glm.hpp>

#include "reference/texture_sampler.hpp"
#include "scene/scene.hpp"

namespace vct::reference {

class MaterialTable {
public:
    explicit MaterialTable(const Scene& scene);  // keeps references: `scene` must outlive this

    // At a point with vertex UV sets `uv0`, `uv1` and vertex colour `vertexColor`.
    glm::vec3 albedo(std::uint32_t material, glm::vec2 uv0, glm::vec2 uv1, glm::vec3 vertexColor) const;
    glm::vec3 emission(std::uint32_t material) const { return materials_[material].emission; }
    bool isMasked(std::uint32_t material) const { return materials_[material].masked; }
    bool isEmissive(std::uint32_t material) const { return materials_[material].emissive; }
    // True where an alpha-masked material has a hole (the ray passes through).
    bool cutsAway(std::uint32_t material, glm::vec2 uv0, glm::vec2 uv1) const;

private:
    struct Entry {
        glm::vec3 baseColor;
        float baseAlpha;
        float cutoff;
        glm::vec3 emission;
        int texture;  // index into samplers_, −1 = none
        TextureMapping mapping;
        bool masked;
        bool emissive;
    };
    std::vector<Entry> materials_;
    std::vector<TextureSampler> samplers_;  // one per material with a texture (its wrap modes)
};

}  // namespace vct::reference
