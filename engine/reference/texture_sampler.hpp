#pragma once
// Base-colour texture lookups exactly as the rasterizer's GL_SRGB8_ALPHA8 textures deliver them,
// at mip level 0 (the reference integrates over the pixel footprint by supersampling instead of
// by pre-filtered mip levels):
//   * UV origin bottom-left (Vertex::uv): GL row j = floor(v·H − ½) counts from the LAST row of
//     Texture::rgba, i.e. file row = H − 1 − j (texel row ≈ (1 − v)·H);
//   * the material's wrap mode per axis (GL_REPEAT, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT),
//     applied to the texel indices exactly as the GL specification does (section 8.14.2);
//   * GL_LINEAR: bilinear between the four nearest texel centres;
//   * sRGB → linear per texel *before* filtering, as GL does for sRGB textures (filtering the
//     encoded values and decoding afterwards gives a darker, wrong result at edges).
// Alpha is stored linearly and filtered as is.
#include <array>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace vct::reference {

class TextureSampler {
public:
    // Keeps a reference: `texture` must outlive this.
    explicit TextureSampler(const Texture& texture, TextureWrap wrapS = TextureWrap::Repeat,
                            TextureWrap wrapT = TextureWrap::Repeat);

    glm::vec4 sample(glm::vec2 uv) const;  // linear RGB and alpha, bilinear at level 0
    float sampleAlpha(glm::vec2 uv) const; // alpha only (the alpha-mask test in the ray filter)

private:
    struct Footprint {
        int x0, x1, r0, r1;  // texel columns and file rows of the 2×2 neighbourhood
        float fx, fy;        // bilinear weights of x1 and of the GL row above (r1)
    };
    Footprint footprint(glm::vec2 uv) const;
    const std::uint8_t* texel(int x, int fileRow) const {
        return &texture_->rgba[(std::size_t(fileRow) * width_ + x) * 4];
    }

    const Texture* texture_;
    int width_, height_;
    TextureWrap wrapS_, wrapT_;
};

// sRGB-encoded byte → linear value, the IEC 61966-2-1 EOTF, tabulated.
const std::array<float, 256>& srgbToLinearTable();

}  // namespace vct::reference
