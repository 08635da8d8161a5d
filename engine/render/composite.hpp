#pragma once
// Composite pass (DESIGN §4 pass 13): direct + emissive (+ indirect later) into a linear HDR
// image and a tone-mapped 8-bit sRGB image; or one AOV buffer instead, for tests and figures.
#include <string>

#include "core/image.hpp"
#include "core/tonemap.hpp"
#include "gl/objects.hpp"
#include "render/gbuffer.hpp"

namespace vct {

enum class Aov { Final, Direct, Albedo, Normal, Depth, Indirect, Ao, Gi };
// The tone curves are core/tonemap.hpp's (its order matches shaders/tonemap.glsl's constants).
using ToneCurve = TonemapCurve;

Aov parseAov(const std::string& name);            // throws listing the valid names
inline ToneCurve parseToneCurve(const std::string& name) { return parseTonemapCurve(name); }
const char* aovName(Aov aov);

constexpr double kMaxExposureEV = 64.0;  // |exposure| in stops; 2^±64 keeps float's range for any radiance

struct DisplaySettings {
    Aov aov = Aov::Final;
    float giScale = 1.0f;  // artistic only; 1 in every accuracy measurement
    ToneCurve toneCurve = ToneCurve::Aces;
    double exposureEV = 0.0;

    bool operator==(const DisplaySettings&) const = default;
};

class Composite {
public:
    Composite(int width, int height);
    // `indirect` (0 = GI off): irradiance and visibility from cone tracing.
    // `debugImage` (0 = none): a debug view's colour, shown instead of the lit image.
    // `samplesInAverage`: 1 starts a new average with this frame; n > 1 adds it as the n-th sample
    // (a frame jittered inside the pixel) to the average the output holds, its indirect light
    // with weight `indirectWeight` (render/cone_trace.hpp, indirectWeightOfSample).
    void render(const GBuffer& gbuffer, GLuint directRadiance, GLuint indirect, const ViewTransform& camera,
                float depthScale, const DisplaySettings& display, int samplesInAverage, float indirectWeight = 1.0f,
                GLuint debugImage = 0, bool toneMapDebugImage = false);

    ImageF readHdr() const;  // rows top to bottom
    Image8 readLdr() const;
    GLuint ldr() const { return ldr_.id(); }
    std::size_t bytes() const { return std::size_t(width_) * height_ * (16 + 16 + 16 + 4); }

private:
    int width_, height_;
    gl::Texture hdr_, hdrSum_, indirectSum_, ldr_;
    gl::Program program_;
};

}  // namespace vct
