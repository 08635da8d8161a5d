#include "scene/texture_mapping.hpp"

#include <cmath>

namespace vct {

const char* textureWrapName(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Repeat: return "repeat";
        case TextureWrap::ClampToEdge: return "clamp to edge";
        case TextureWrap::MirroredRepeat: return "mirrored repeat";
    }
    return "?";
}

glm::mat3 fromGltfTransform(glm::vec2 offset, float rotation, glm::vec2 scale) {
    // glm is column-major: m[column][row]. The matrices of the KHR_texture_transform spec:
    //   T = [1 0 ox; 0 1 oy; 0 0 1], R = [cos sin 0; −sin cos 0; 0 0 1], S = diag(sx, sy, 1).
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    const glm::mat3 flip(1, 0, 0, 0, -1, 0, 0, 1, 1);  // (u, v) → (u, 1 − v), its own inverse
    return flip * t * r * sc * flip;
}

}  // namespace vct
