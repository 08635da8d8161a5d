#include "reference/materials.hpp"

#include "core/error.hpp"

namespace vct::reference {

MaterialTable::MaterialTable(const Scene& scene) {
    samplers_.reserve(scene.textures.size());
    for (const Texture& texture : scene.textures) samplers_.emplace_back(texture);
    for (const Material& m : scene.materials) {
        if (m.baseColorTexture >= int(scene.textures.size()))
            fail("material '", m.name, "' refers to texture ", m.baseColorTexture, " of ", scene.textures.size(),
                 " (a loader bug: please report it)");
        Entry e;
        e.baseColor = m.baseColor;
        e.baseAlpha = m.baseAlpha;
        e.cutoff = m.alphaCutoff;
        e.emission = m.emissive;
        e.texture = m.baseColorTexture;
        e.masked = m.alphaMode == AlphaMode::Mask;
        e.emissive = m.emissive.x > 0.0f || m.emissive.y > 0.0f || m.emissive.z > 0.0f;
        materials_.push_back(e);
    }
}

glm::vec3 MaterialTable::albedo(std::uint32_t material, glm::vec2 uv) const {
    const Entry& e = materials_[material];
    if (e.texture < 0) return e.baseColor;
    return e.baseColor * glm::vec3(samplers_[e.texture].sample(uv));
}

bool MaterialTable::cutsAway(std::uint32_t material, glm::vec2 uv) const {
    const Entry& e = materials_[material];
    if (!e.masked) return false;
    const float alpha = e.baseAlpha * (e.texture < 0 ? 1.0f : samplers_[e.texture].sampleAlpha(uv));
    return alpha < e.cutoff;
}

}  // namespace vct::reference
