#include "reference/texture_sampler.hpp"

#include <algorithm>
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

TextureSampler::TextureSampler(const Texture& texture, TextureWrap wrapS, TextureWrap wrapT)
    : texture_(&texture), width_(texture.width), height_(texture.height), wrapS_(wrapS), wrapT_(wrapT) {
    if (width_ < 1 || height_ < 1 || texture.rgba.size() != std::size_t(width_) * height_ * 4)
        fail("texture '", texture.name, "' has inconsistent size ", width_, "x", height_, " for ",
             texture.rgba.size(), " bytes (a loader bug: please report it)");
}

namespace {

// The texel indices i0, i1 = i0 + 1 around `coordinate` along an axis of `size` texels (centre of
// texel i at (i + ½)/size), wrapped, and the weight of i1.
void repeatAxis(double coordinate, int size, int& i0, int& i1, float& weight) {
    // Wrap first (in double, so UVs far outside [0,1] keep their sub-texel position).
    const double s = (coordinate - std::floor(coordinate)) * size - 0.5;  // in [−½, size − ½)
    const double base = std::floor(s);
    weight = float(s - base);
    i0 = int(base);
    i1 = i0 + 1;
    if (i0 < 0) i0 += size;      // repeat: −1 → size − 1
    if (i1 >= size) i1 -= size;  // repeat: size → 0
}

void clampAxis(double coordinate, int size, int& i0, int& i1, float& weight) {
    // Beyond the edge every index clamps to the edge texel: cut far coordinates short first.
    const double s = std::clamp(coordinate, -1.0, 2.0) * size - 0.5;
    const double base = std::floor(s);
    weight = float(s - base);
    i0 = std::clamp(int(base), 0, size - 1);
    i1 = std::clamp(int(base) + 1, 0, size - 1);
}

void mirrorAxis(double coordinate, int size, int& i0, int& i1, float& weight) {
    // The pattern repeats every 2 in UV: reduce first (in double, as for repeat).
    const double s = (coordinate - 2.0 * std::floor(0.5 * coordinate)) * size - 0.5;  // [−½, 2·size − ½)
    const double base = std::floor(s);
    weight = float(s - base);
    // GL: (size − 1) − mirror((i mod 2·size) − size), mirror(a) = a ≥ 0 ? a : −(1 + a).
    auto mirrored = [size](int i) {
        const int m = ((i % (2 * size)) + 2 * size) % (2 * size);
        return m < size ? m : 2 * size - 1 - m;
    };
    i0 = mirrored(int(base));
    i1 = mirrored(int(base) + 1);
}

void wrapAxis(TextureWrap wrap, double coordinate, int size, int& i0, int& i1, float& weight) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return clampAxis(coordinate, size, i0, i1, weight);
        case TextureWrap::MirroredRepeat: return mirrorAxis(coordinate, size, i0, i1, weight);
        case TextureWrap::Repeat: break;
    }
    repeatAxis(coordinate, size, i0, i1, weight);
}

}  // namespace

TextureSampler::Footprint TextureSampler::footprint(glm::vec2 uv) const {
    Footprint f{};
    int j0 = 0, j1 = 0;
    wrapAxis(wrapS_, uv.x, width_, f.x0, f.x1, f.fx);
    wrapAxis(wrapT_, uv.y, height_, j0, j1, f.fy);
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
