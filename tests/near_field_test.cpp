// The near field of the camera's narrow cones (shaders/near_field.glsl), run on the GPU against a
// G-buffer made here: the camera's rays cast at a floor with a low box on it (a step a voxel tall),
// each surface with its own direct light. A cone's axis followed from a floor point beside the box
// must meet the box's side and bring back that side's light and emission; the same axis from the
// far side of the box meets a face the camera does not see, whose light the G-buffer does not hold:
// it brings back what hiddenSideLight (in the engine: the voxels there) says that face sends; an axis
// straight up, one along the floor's own plane and one from behind the camera meet nothing, and
// their cones are traced as before.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/compute.hpp"
#include "gl/context.hpp"
#include "gl/shader.hpp"
#include "shader_probe.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

constexpr int kSize = 128;
constexpr float kVoxel = 0.1f;   // scene units per voxel
constexpr float kOffset = 1.5f;  // the cones' start offset, voxels
// The box on the floor y = 0: x in [1, 2], y in [0, 0.1] (one voxel), z in [-1, 1].
const glm::vec3 kBoxLo(1.0f, 0.0f, -1.0f), kBoxHi(2.0f, 0.1f, 1.0f);
const glm::vec3 kEye(-1.5f, 1.5f, 0.0f), kTarget(1.0f, 0.0f, 0.0f);

struct Surface {
    glm::vec3 position{0.0f}, normal{0.0f}, direct{0.0f}, emission{0.0f};
    bool hit = false;
};

// The first surface along the ray: the floor or a face of the box, each with its own light.
Surface castRay(glm::vec3 origin, glm::vec3 direction) {
    Surface nearest;
    float best = std::numeric_limits<float>::infinity();
    auto consider = [&](float t, glm::vec3 normal, glm::vec3 direct, glm::vec3 emission) {
        if (!(t > 1e-5f) || t >= best) return;
        best = t;
        nearest = {origin + direction * t, normal, direct, emission, true};
    };
    if (direction.y < 0.0f) consider(-origin.y / direction.y, {0, 1, 0}, {1.0f, 0.0f, 0.0f}, {});
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            const float plane = side ? kBoxHi[a] : kBoxLo[a];
            if (direction[a] == 0.0f) continue;
            const float t = (plane - origin[a]) / direction[a];
            const glm::vec3 p = origin + direction * t;
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            if (p[b] < kBoxLo[b] || p[b] > kBoxHi[b] || p[c] < kBoxLo[c] || p[c] > kBoxHi[c]) continue;
            glm::vec3 normal(0.0f);
            normal[a] = side ? 1.0f : -1.0f;
            // The top is green, the side facing the camera (−x) blue and emissive, the others grey.
            glm::vec3 direct(0.5f), emission(0.0f);
            if (a == 1 && side == 1) direct = {0.0f, 1.0f, 0.0f};
            if (a == 0 && side == 0) direct = {0.0f, 0.0f, 0.25f}, emission = {0.0f, 0.0f, 0.5f};
            consider(t, normal, direct, emission);
        }
    return nearest;
}

struct NearFieldCase {
    glm::vec4 point;      // the pixel's surface point, the step jitter in w
    glm::vec4 normal;     // its unit normal
    glm::vec4 direction;  // the cone's unit axis
    glm::vec4 seen;       // written: what took the cone's place, w = −1 where nothing did
};

}  // namespace

TEST(NearField, AConesAxisMeetsTheSurfacesTheCameraSeesWithinItsStartOffset) {
    auto context = gl::createContext(gl::defaultBackend());
    const glm::mat4 viewProjection = glm::perspective(glm::radians(60.0f), 1.0f, 0.05f, 100.0f) *
                                     glm::lookAt(kEye, kTarget, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 toScene = glm::inverse(viewProjection);

    // The G-buffer: row 0 at the bottom, as clip space's y = −1.
    std::vector<glm::vec4> position(kSize * kSize), normal(kSize * kSize), direct(kSize * kSize), emission(kSize * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / float(kSize) * 2.0f - 1.0f;
            const glm::vec4 far = toScene * glm::vec4(ndc, 1.0f, 1.0f);
            const Surface s = castRay(kEye, glm::normalize(glm::vec3(far) / far.w - kEye));
            const int i = y * kSize + x;
            position[i] = glm::vec4(s.position, s.hit ? 1.0f : 0.0f);
            normal[i] = glm::vec4(s.normal, 0.0f);
            direct[i] = glm::vec4(s.direct, 1.0f);
            emission[i] = glm::vec4(s.emission, 0.0f);
        }
    auto upload = [](const std::vector<glm::vec4>& texels, const char* label) {
        gl::Texture texture = gl::createTexture2D(GL_RGBA32F, kSize, kSize, 1, label);
        glTextureSubImage2D(texture.id(), 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, texels.data());
        return texture;
    };
    const gl::Texture positionTexture = upload(position, "probe position"), normalTexture = upload(normal, "probe normal"),
                      directTexture = upload(direct, "probe direct"), emissionTexture = upload(emission, "probe emission");

    const glm::vec4 up(0.0f, 1.0f, 0.0f, 0.0f);
    auto axis = [](float x, float y, float z) { return glm::vec4(glm::normalize(glm::vec3(x, y, z)), 0.0f); };
    std::vector<NearFieldCase> cases = {
        // 0: beside the box, towards its side (met 0.06 along, 0.035 up): the side's light and emission.
        {{0.95f, 0.0f, 0.0f, 0.5f}, up, axis(1.0f, 0.6f, 0.0f), {}},
        // 1: the same point straight up: nothing below the cone's start.
        {{0.95f, 0.0f, 0.0f, 0.5f}, up, axis(0.0f, 1.0f, 0.0f), {}},
        // 2: beyond the box, towards its far side, which the camera does not see: blocked, with
        // the light hiddenSideLight gives.
        {{2.05f, 0.0f, 0.0f, 0.5f}, up, axis(-1.0f, 0.3f, 0.0f), {}},
        // 3: along the floor, away from the box: its own plane meets nothing.
        {{0.5f, 0.0f, 0.5f, 0.5f}, up, axis(-1.0f, 0.05f, 0.0f), {}},
        // 4: a point behind the camera: off the G-buffer, nothing.
        {{-1.6f, 0.0f, 0.0f, 0.5f}, up, axis(-1.0f, 1.0f, 0.0f), {}},
    };
    const std::string probe =
        "#version 450\nlayout(local_size_x = 64) in;\n"
        "uniform float uVoxelScale;\nuniform float uConeOffset;\n"
        "layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;\n"
        "layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;\n"
        "layout(binding = TEXTURE_GBUFFER_GEOMETRIC_NORMAL) uniform sampler2D uGeometricNormal;\n"
        // Stands for the voxels: a fixed light, and the length along the axis to the point met.
        "bool hiddenSideLight(vec3 point, vec3 normal, vec3 direction, float length, out vec3 radiance) {\n"
        "    radiance = vec3(0.3, 0.2, length);\n"
        "    return true;\n"
        "}\n"
        "#include \"near_field.glsl\"\n"
        "struct NearFieldCase { vec4 point; vec4 normal; vec4 direction; vec4 seen; };\n"
        "layout(std430, binding = SSBO_CONE_COUNTERS) buffer Cases { NearFieldCase cases[]; };\n"
        "uniform uint uCount;\n"
        "void main() {\n"
        "    uint i = gl_GlobalInvocationID.x;\n"
        "    if (i >= uCount) return;\n"
        "    nearFieldPoint = cases[i].point.xyz;\n"
        "    nearFieldNormal = cases[i].normal.xyz;\n"
        "    nearFieldJitter = cases[i].point.w;\n"
        "    vec4 seen;\n"
        "    cases[i].seen = nearFieldHit(cases[i].direction.xyz, seen) ? seen : vec4(-1.0);\n"
        "}\n";
    const auto dir = test::testDir();
    std::filesystem::copy_file(gl::shaderDirectory() / "near_field.glsl", dir / "near_field.glsl",
                               std::filesystem::copy_options::overwrite_existing);
    std::ofstream(dir / "near_field_probe.comp") << probe;
    setenv("VCT_SHADER_DIR", dir.c_str(), 1);
    const gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, "near_field_probe.comp"}});
    unsetenv("VCT_SHADER_DIR");
    const gl::Buffer buffer = gl::createBuffer(GLsizeiptr(cases.size() * sizeof(NearFieldCase)), cases.data(),
                                               GL_DYNAMIC_STORAGE_BIT, "near field cases");
    gl::ComputeCall(program)
        .storage(gl::SSBO_CONE_COUNTERS, buffer)
        .texture(gl::TEXTURE_GBUFFER_POSITION, positionTexture.id())
        .texture(gl::TEXTURE_GBUFFER_NORMAL, normalTexture.id())
        .texture(gl::TEXTURE_GBUFFER_GEOMETRIC_NORMAL, normalTexture.id())
        .texture(gl::TEXTURE_NEAR_FIELD_DIRECT, directTexture.id())
        .texture(gl::TEXTURE_NEAR_FIELD_EMISSIVE, emissionTexture.id())
        .uniform("uVoxelScale", 1.0f / kVoxel)
        .uniform("uConeOffset", kOffset)
        .uniform("uViewProjection", viewProjection)
        .uniform("uEye", kEye)
        .uniform("uCount", unsigned(cases.size()))
        .dispatch1D(cases.size(), 64, GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<NearFieldCase> out = test::readBuffer<NearFieldCase>(buffer, cases.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        std::printf("[ near field ] case %zu: seen (%.3f, %.3f, %.3f), opacity %.0f\n", i, out[i].seen.x, out[i].seen.y,
                    out[i].seen.z, out[i].seen.w);

    EXPECT_EQ(out[0].seen, glm::vec4(0.0f, 0.0f, 0.75f, 1.0f)) << "the box's side, its direct light and emission";
    EXPECT_EQ(out[1].seen.w, -1.0f) << "nothing below the cone's start straight up";
    // The far side (x = 2) lies 0.05 × 1.044 = 0.052 along the axis. At this grazing angle the march
    // reaches three times the offset (0.45) in six steps of 0.075, at jitter 0.5 at 0.0375, 0.1125,
    // ...: it stops at the first step past the face and asks hiddenSideLight for a step further.
    EXPECT_FLOAT_EQ(out[2].seen.x, 0.3f) << "a face the camera does not see: the light hiddenSideLight gives";
    EXPECT_FLOAT_EQ(out[2].seen.y, 0.2f);
    EXPECT_GT(out[2].seen.z, 0.052f + 0.075f) << "the length asked: a step past the face";
    EXPECT_LT(out[2].seen.z, 0.052f + 2.0f * 0.075f);
    EXPECT_EQ(out[2].seen.w, 1.0f) << "blocked";
    EXPECT_EQ(out[3].seen.w, -1.0f) << "the floor's own plane";
    EXPECT_EQ(out[4].seen.w, -1.0f) << "behind the camera";
}
