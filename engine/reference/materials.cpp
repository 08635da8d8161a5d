#include "reference/materials.hpp"

#include "core/error.hpp"

namespace vct::reference {

MaterialTable::MaterialTable(const Scene& scene) {
    for (const Material& m : scene.materials) {
        if (m.baseColorTexture >= int(scene.textures.size()))
            fail("material '", m.name, "' refers to texture ", m.baseColorTexture, " of ", scene.textures.size(),
                 " (a loader bug: please report it)");
        Entry e;
        e.baseColor = m.baseColor;
        e.baseAlpha = m.baseAlpha;
        e.cutoff = m.alphaCutoff;
        e.emission = m.emissive;
        e.texture = -1;
        if (m.baseColorTexture >= 0) {
            e.texture = int(samplers_.size());
            samplers_.emplace_back(scene.textures[std::size_t(m.baseColorTexture)], m.baseColorMapping.wrapS,
                                   m.baseColorMapping.wrapT);
        }
        e.mapping = m.baseColorMapping;
        e.masked = m.alphaMode == AlphaMode::Mask;
        e.emissive = m.emissive.x > 0.0f || m.emissive.y > 0.0f || m.emissive.z > 0.0f;
        materials_.push_back(e);
    }
}

glm::vec3 MaterialTable::albedo(std::uint32_t material, glm::vec2 uv0, glm::vec2 uv1, glm::vec3 vertexColor) const {
    const Entry& e = materials_[material];
    const glm::vec3 base = e.baseColor * vertexColor;
    if (e.texture < 0) return base;
    return base * glm::vec3(samplers_[e.texture].sample(e.mapping.apply(uv0, uv1)));
}

bool MaterialTable::cutsAway(std::uint32_t material, glm::vec2 uv0, glm::vec2 uv1) const {
    const Entry& e = materials_[material];
    if (!e.masked) return false;
    const float alpha =
        e.baseAlpha * (e.texture < 0 ? 1.0f : samplers_[e.texture].sampleAlpha(e.mapping.apply(uv0, uv1)));
    return alpha < e.cutoff;
}

}  // namespace vct::reference
