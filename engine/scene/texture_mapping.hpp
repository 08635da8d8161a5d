#pragma once
// How a material's texture is laid on the surface: which texture-coordinate set it reads, the
// affine transform applied to that set (glTF KHR_texture_transform) and what happens outside
// [0, 1] on each axis (glTF sampler wrapS / wrapT). The rasterizer (shaders/material_vertex.glsl,
// GpuScene's sampler objects) and the reference path tracer (reference/texture_sampler.hpp) both
// evaluate this one description, so that they see the same texture.
//
// Everything is in vct's UV convention (Vertex::uv: v = 0 at the bottom of the image). glTF's
// transform is defined with v = 0 at the top; fromGltfTransform converts.
#include <cmath>

#include <glm/glm.hpp>

namespace vct {

enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// Beyond ±2²⁴ consecutive floats lie 2 apart: a texture coordinate there can no longer say even
// which repeat of the texture it falls in, and multiplied by a texture's size in a sampler it
// overflows (llvmpipe then returns NaN texels). The loaders treat such coordinates, and transforms
// with such offsets or scales, like non-finite ones.
constexpr double kLargestUsableUv = 16777216.0;
inline bool isUsableTextureCoordinate(double v) { return std::abs(v) <= kLargestUsableUv; }  // false for NaN

const char* textureWrapName(TextureWrap wrap);

struct TextureMapping {
    int texCoord = 0;                 // 0: Vertex::uv, 1: Vertex::uv1
    glm::mat3 transform{1.0f};        // uv' = (transform · (uv, 1)).xy; the last row is (0, 0, 1)
    TextureWrap wrapS = TextureWrap::Repeat;  // along u
    TextureWrap wrapT = TextureWrap::Repeat;  // along v

    bool isDefault() const {
        return texCoord == 0 && transform == glm::mat3(1.0f) && wrapS == TextureWrap::Repeat &&
               wrapT == TextureWrap::Repeat;
    }
    // The texture coordinates this mapping gives a point with vertex sets `uv0` and `uv1`.
    glm::vec2 apply(glm::vec2 uv0, glm::vec2 uv1) const {
        const glm::vec2 uv = texCoord == 1 ? uv1 : uv0;
        return glm::vec2(transform * glm::vec3(uv, 1.0f));
    }
};

// KHR_texture_transform's offset, rotation (radians, counter-clockwise in glTF's image space) and
// scale, as glTF defines them (T · R · S on glTF UVs, v down), turned into the same map on vct's
// UVs (v up): F · T · R · S · F with F: (u, v) → (u, 1 − v).
glm::mat3 fromGltfTransform(glm::vec2 offset, float rotation, glm::vec2 scale);

}  // namespace vct
