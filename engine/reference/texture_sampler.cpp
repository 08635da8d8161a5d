#include "reference/texture_sampler.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/tonemap.hpp"

namespace vct::reference {

const std::array<float, 256>& srgbToLinearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

TextureSampler::TextureSampler(const Texture& texture)
    : texture_(&texture), width_(texture.width), height_(texture.height) {
    if (width_ < 1 || height_ < 1 || texture.rgba.size() != std::size_t(width_) * height_ * 4)
        fail("texture '", texture.name, "' has inconsistent size ", width_, "x", height_, " for ",
             texture.rgba.size(), " bytes (a loader bug: please report it)");
}

TextureSampler::Footprint TextureSampler::footprint(glm::vec2 uv) const {
    // Wrap first (in double, so UVs far outside [0,1] keep their sub-texel position), then find
    // the texel centres around the point: centre of texel i is at (i + ½)/W.
    auto axis = [](double coordinate, int size, int& i0, int& i1, float& weight) {
        const double s = (coordinate - std::floor(coordinate)) * size - 0.5;  // in [−½, size − ½)
        const double base = std::floor(s);
        weight = float(s - base);
        i0 = int(base);
        i1 = i0 + 1;
        if (i0 < 0) i0 += size;      // repeat: −1 → size − 1
        if (i1 >= size) i1 -= size;  // repeat: size → 0
    };
    Footprint f{};
    int j0 = 0, j1 = 0;
    axis(uv.x, width_, f.x0, f.x1, f.fx);
    axis(uv.y, height_, j0, j1, f.fy);
    // GL row j (bottom-up) is file row H − 1 − j (Texture::rgba is top-down).
    f.r0 = height_ - 1 - j0;
    f.r1 = height_ - 1 - j1;
    return f;
}

glm::vec4 TextureSampler::sample(glm::vec2 uv) const {
    const Footprint f = footprint(uv);
    const auto& lut = srgbToLinearTable();
    auto decode = [&](int x, int row) {
        const std::uint8_t* t = texel(x, row);
        return glm::vec4(lut[t[0]], lut[t[1]], lut[t[2]], float(t[3]) / 255.0f);
    };
    const glm::vec4 bottom = glm::mix(decode(f.x0, f.r0), decode(f.x1, f.r0), f.fx);
    const glm::vec4 top = glm::mix(decode(f.x0, f.r1), decode(f.x1, f.r1), f.fx);
    return glm::mix(bottom, top, f.fy);
}

float TextureSampler::sampleAlpha(glm::vec2 uv) const {
    const Footprint f = footprint(uv);
    auto alpha = [&](int x, int row) { return float(texel(x, row)[3]) / 255.0f; };
    // Same arithmetic as glm::mix in sample(), so both give the same alpha.
    const float bottom = alpha(f.x0, f.r0) * (1.0f - f.fx) + alpha(f.x1, f.r0) * f.fx;
    const float top = alpha(f.x0, f.r1) * (1.0f - f.fx) + alpha(f.x1, f.r1) * f.fx;
    return bottom * (1.0f - f.fy) + top * f.fy;
}

}  // namespace vct::reference
