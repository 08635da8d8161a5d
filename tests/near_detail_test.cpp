// The near field's detail at every pixel (render/near_detail.hpp, shaders/near_detail.comp) on a
// real G-buffer: a floor seen at an angle with a box standing on it, every pixel given the same
// irradiance. What it must do: darken the floor in the crease at the box's foot, where the rays
// towards the box meet its side within the cones' start offset; leave a floor that nothing
// overhangs exactly as it was; keep the light of a patch around the crease about where it was (it
// moves light within a patch, it does not add or remove it); never touch the cones' visibility.
#include <cmath>
#include <vector>

#include "gl/context.hpp"
#include "render/gbuffer.hpp"
#include "render/gpu_scene.hpp"
#include "render/near_detail.hpp"
#include "render/view.hpp"
#include "scene/scene_loader.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

constexpr float kBoxHeight = 1.0f;
constexpr float kBoxLoX = 0.0f;                // the box's side that faces the camera
constexpr double kVoxelSize = 8.0 / 128.0;     // a 128³ grid over the 8 m floor
constexpr float kConeOffset = 1.5f;            // voxels: the near field's reach along the normal

std::vector<float> readRgba(GLuint texture, int width, int height) {
    std::vector<float> values(std::size_t(width) * height * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(values.size() * 4), values.data());
    return values;
}

// Below 360 lines the visibility is followed at every pixel, from there up at one of each 2×2 block.
void expectCreaseDarkAndOpenFloorUntouched(int width, int height) {
    auto context = gl::createContext(gl::defaultBackend());
    test::ObjWriter obj;
    obj.material("grey", glm::vec3(0.5f));
    obj.floor(0.0f, 4.0f);
    obj.box({kBoxLoX, 0.0f, -1.5f}, {kBoxLoX + 1.0f, kBoxHeight, 1.5f});
    const Scene scene = loadModelFile(obj.write(test::testDir()));
    Camera camera;
    camera.eye = {-2.5, 2.0, 0.3};  // looking down at the floor before the box's −x side
    camera.target = {0.0, 0.2, 0.0};
    GpuScene gpuScene(scene);
    GBuffer gbuffer(width, height);
    const ViewTransform view = cameraView(camera, scene, width, height);
    gbuffer.render(gpuScene, view);

    // Irradiance 1 and the cones' visibility 0.5 at every pixel.
    std::vector<float> input(std::size_t(width) * height * 4);
    for (std::size_t i = 0; i < input.size(); i += 4) input[i] = input[i + 1] = input[i + 2] = 1.0f, input[i + 3] = 0.5f;
    gl::Texture indirect = gl::createTexture2D(GL_RGBA32F, width, height, 1, "test irradiance");
    glTextureSubImage2D(indirect.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, input.data());
    gl::Texture direct = gl::createTexture2D(GL_RGBA32F, width, height, 1, "test direct light");
    NearDetail detail(width, height);
    const std::vector<float> output =
        readRgba(detail.render(gbuffer, indirect.id(), direct.id(), view, kVoxelSize, kConeOffset), width, height);
    const std::vector<float> position = readRgba(gbuffer.position(), width, height);

    // The G-buffer holds scene-local points, centred on the scene's bounds: the floor lies at
    // y = −kBoxHeight / 2, and x is shifted by the bounds' centre (the floor's, x = 0).
    const float floorY = -0.5f * kBoxHeight;
    const float crease = float(kConeOffset * kVoxelSize);  // floor within this of the side: rays meet it
    int creasePixels = 0, openPixels = 0, patchPixels = 0;
    double creaseSum = 0.0, patchSum = 0.0;
    float openLowest = 1.0f, openHighest = 1.0f;
    for (int i = 0; i < width * height; ++i) {
        const float* p = &position[std::size_t(i) * 4];
        const float* out = &output[std::size_t(i) * 4];
        ASSERT_EQ(out[3], 0.5f) << "the cones' visibility is left as it was";
        ASSERT_TRUE(out[0] == out[1] && out[1] == out[2]);
        if (!(p[3] > 0.0f) || std::abs(p[1] - floorY) > 1e-3f || std::abs(p[2]) > 1.2f) continue;  // the floor before the side
        const float fromSide = kBoxLoX - p[0];  // > 0 in front of the box
        if (fromSide < 0.0f) continue;
        if (fromSide < 0.5f * crease) {
            ++creasePixels;
            creaseSum += out[0];
        }
        if (fromSide > 1.0f) {  // nothing within the near field's reach, nor within the mean's taps
            ++openPixels;
            openLowest = std::min(openLowest, out[0]);
            openHighest = std::max(openHighest, out[0]);
        }
        if (fromSide < 0.5f) {
            ++patchPixels;
            patchSum += out[0];
        }
    }
    EXPECT_GT(creasePixels, 10);
    if (creasePixels == 0) return;
    EXPECT_GT(openPixels, 100);
    const double creaseMean = creaseSum / creasePixels, patchMean = patchSum / patchPixels;
    std::printf("[ near detail ] %dx%d: crease %.3f over %d pixels, the half metre before the side %.3f over %d, open floor "
                "%.3f..%.3f over %d\n",
                width, height, creaseMean, creasePixels, patchMean, patchPixels, openLowest, openHighest, openPixels);
    EXPECT_LT(creaseMean, 0.9) << "the crease at the box's foot (1 without the detail)";
    EXPECT_EQ(openLowest, 1.0f) << "open floor untouched";
    EXPECT_EQ(openHighest, 1.0f) << "open floor untouched";
    EXPECT_NEAR(patchMean, 1.0, 0.05) << "the light of the floor before the side stays about where it was";
}

}  // namespace

TEST(NearDetail, TheCreaseAtAWallsFootIsDarkAndOpenFloorUntouched) { expectCreaseDarkAndOpenFloorUntouched(128, 96); }

TEST(NearDetail, FromBlocksOfPixelsAtLargerImagesToo) { expectCreaseDarkAndOpenFloorUntouched(480, 360); }
