#include "core/tonemap.hpp"

#include <cmath>

#include "core/error.hpp"

namespace vct {

TonemapCurve parseTonemapCurve(const std::string& name) {
    if (name == "aces") return TonemapCurve::Aces;
    if (name == "reinhard") return TonemapCurve::Reinhard;
    if (name == "clamp") return TonemapCurve::Clamp;
    fail("unknown tone curve '", name, "'; use aces, reinhard or clamp");
}

const char* tonemapCurveName(TonemapCurve curve) {
    switch (curve) {
        case TonemapCurve::Aces: return "aces";
        case TonemapCurve::Reinhard: return "reinhard";
        case TonemapCurve::Clamp: return "clamp";
    }
    return "?";
}

glm::vec3 toneCurve(glm::vec3 x, TonemapCurve curve) {
    switch (curve) {
        case TonemapCurve::Aces:
            return glm::clamp(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
        case TonemapCurve::Reinhard: return x / (1.0f + x);
        case TonemapCurve::Clamp: break;
    }
    return glm::clamp(x, 0.0f, 1.0f);
}

glm::vec3 linearToSrgb(glm::vec3 c) {
    c = glm::clamp(c, 0.0f, 1.0f);
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = c[i] < 0.0031308f ? 12.92f * c[i] : 1.055f * std::pow(c[i], 1.0f / 2.4f) - 0.055f;
    return out;
}

float srgbToLinear(float e) {
    return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 displayTransform(glm::vec3 radiance, double exposureEV, TonemapCurve curve) {
    const float exposure = float(std::exp2(exposureEV));  // the composite pass's uExposure
    return linearToSrgb(toneCurve(radiance * exposure, curve));
}

std::uint8_t toUnorm8(float value) {
    if (!(value > 0.0f)) return 0;  // also NaN
    if (value >= 1.0f) return 255;
    return std::uint8_t(std::lround(value * 255.0f));
}

Image8 tonemapImage(const ImageF& hdr, double exposureEV, TonemapCurve curve) {
    Image8 out(hdr.width, hdr.height);
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) {
            const float* p = hdr.at(x, y);
            const glm::vec3 d = displayTransform({p[0], p[1], p[2]}, exposureEV, curve);
            std::uint8_t* q = out.at(x, y);
            for (int c = 0; c < 3; ++c) q[c] = toUnorm8(d[c]);
            q[3] = 255;
        }
    return out;
}

}  // namespace vct
