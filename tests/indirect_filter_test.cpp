// The cones' edge-aware filter (render/indirect_filter.hpp, shaders/indirect_filter.comp) on a
// synthetic irradiance over a real G-buffer: a floor seen from straight above with a box standing
// on it. What it must do: keep a linear change of irradiance where it is, up to the edges of the
// image and of the surface (a mean there would shift it), keep a surface a step away out of the
// average, and smooth what varies from pixel to pixel.
#include <cmath>
#include <vector>

#include "gl/context.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/indirect_filter.hpp"
#include "render/view.hpp"
#include "scene/scene_loader.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

constexpr int kWidth = 96, kHeight = 72;
constexpr float kBoxTop = 0.3f;  // 4.8 voxels: near enough that only the tangent plane tells the surfaces apart
constexpr glm::vec3 kBoxLo{0.3f, 0.0f, -1.0f}, kBoxHi{1.6f, 0.0f, 1.0f};  // its footprint (x, z)
constexpr double kVoxelSize = 8.0 / 128.0;  // a 128³ grid over the 8 m floor

std::vector<float> readRgba(GLuint texture) {
    std::vector<float> values(std::size_t(kWidth) * kHeight * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(values.size() * 4), values.data());
    return values;
}

// What the filter is given at each pixel, as a function of the pixel's surface point.
using Irradiance = float (*)(int x, int y, const float* position);

struct Filtered {
    std::vector<float> input, output, position;  // RGBA per pixel, rows as GL stores them
};

Filtered filterOverFloorAndBox(Irradiance irradiance, float sigmaVoxels = kDefaultGiFilterVoxels) {
    auto context = gl::createContext(gl::defaultBackend());
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.5f));
    obj.floor(0.0f, 4.0f);
    obj.box({kBoxLo.x, 0.0f, kBoxLo.z}, {kBoxHi.x, kBoxTop, kBoxHi.z});
    const Scene scene = loadModelFile(obj.write(test::testDir()));
    Camera camera;
    camera.eye = {0.0, 6.0, 0.0};  // straight down: the floor and the box top are parallel to the image
    camera.target = {0.0, 0.0, 0.0};
    camera.up = {0.0, 0.0, -1.0};
    GpuScene gpuScene(scene);
    GBuffer gbuffer(kWidth, kHeight);
    gbuffer.render(gpuScene, cameraView(camera, scene, kWidth, kHeight));

    Filtered f;
    f.position = readRgba(gbuffer.position());
    f.input.resize(f.position.size());
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = (std::size_t(y) * kWidth + x) * 4;
            const float e = irradiance(x, y, &f.position[i]);
            f.input[i] = f.input[i + 1] = f.input[i + 2] = e;
            f.input[i + 3] = 1.0f;
        }
    gl::Texture traced = gl::createTexture2D(GL_RGBA32F, kWidth, kHeight, 1, "test irradiance");
    glTextureSubImage2D(traced.id(), 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, f.input.data());
    IndirectFilter filter(kWidth, kHeight);
    f.output = readRgba(filter.render(gbuffer, traced.id(), 0, kVoxelSize, sigmaVoxels));
    return f;
}

// The G-buffer holds scene-local points, centred on the scene's bounds: the floor lies at
// y = −kBoxTop / 2, the box top at +kBoxTop / 2.
bool onBoxTop(const float* p) { return p[3] > 0.0f && p[1] > 0.25f * kBoxTop; }
bool onFloor(const float* p) { return p[3] > 0.0f && p[1] < -0.499f * kBoxTop; }

// Floor points more than half a metre from the box's footprint: the ramp's own test.
bool awayFromBox(const float* p) {
    return p[0] < kBoxLo.x - 0.5f || p[0] > kBoxHi.x + 0.5f || p[2] < kBoxLo.z - 0.5f || p[2] > kBoxHi.z + 0.5f;
}

// The floor brightens along x; the box top is far brighter and flat.
float rampAndBox(int, int, const float* p) { return onBoxTop(p) ? 5.0f : 1.0f + 0.25f * p[0]; }
// The same floor with a ±0.2 checkerboard on it, pixel by pixel.
float noisyFloor(int x, int y, const float* p) { return rampAndBox(x, y, p) + (((x + y) & 1) ? 0.2f : -0.2f); }

}  // namespace

TEST(IndirectFilter, KeepsALinearChangeUpToTheEdgesAndOtherSurfacesOut) {
    // The plane fit at σ 4 voxels, and at the default's 8, whose wider kernel reaches further past
    // the floor's edges (measured 0.0139 and 0.0290; a mean instead of a plane left the edge
    // pixels 0.03 off at σ 4).
    for (const float sigma : {4.0f, kDefaultGiFilterVoxels}) {
        const Filtered f = filterOverFloorAndBox(rampAndBox, sigma);
        double floorWorst = 0.0, boxWorst = 0.0;
        int floorPixels = 0, boxPixels = 0;
        for (std::size_t i = 0; i < f.output.size(); i += 4) {
            const double error = std::abs(f.output[i] - f.input[i]);
            if (onFloor(&f.position[i]) && awayFromBox(&f.position[i])) {
                floorWorst = std::max(floorWorst, error);
                ++floorPixels;
            } else if (onBoxTop(&f.position[i])) {
                boxWorst = std::max(boxWorst, error);
                ++boxPixels;
            }
        }
        std::printf("[ filter ] σ %.0f voxels: ramp 0.375..1.625 on %d floor pixels away from the box: worst error "
                    "%.4f; flat box top (5) on %d: %.4f\n",
                    sigma, floorPixels, floorWorst, boxPixels, boxWorst);
        ASSERT_GT(floorPixels, kWidth * kHeight / 2);
        ASSERT_GT(boxPixels, 200);
        // Without the tangent plane's weight the box top, 4.8 voxels above the floor, fell from 5 to 3.0.
        EXPECT_LT(floorWorst, sigma <= 4.0f ? 0.02 : 0.035) << sigma;
        EXPECT_LT(boxWorst, 0.003) << sigma;
    }
}

TEST(IndirectFilter, SmoothsWhatVariesFromPixelToPixel) {
    const Filtered f = filterOverFloorAndBox(noisyFloor);
    double before = 0.0, after = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < f.output.size(); i += 4) {
        if (!onFloor(&f.position[i])) continue;
        const double truth = 1.0 + 0.25 * f.position[i];
        before += (f.input[i] - truth) * (f.input[i] - truth);
        after += (f.output[i] - truth) * (f.output[i] - truth);
        ++n;
    }
    before = std::sqrt(before / n);
    after = std::sqrt(after / n);
    std::printf("[ filter ] checkerboard ±0.2 on the floor: RMS error %.4f before, %.4f after\n", before, after);
    EXPECT_LT(after, 0.1 * before);
}
