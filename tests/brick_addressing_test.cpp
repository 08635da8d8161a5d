// Brick addressing (shaders/bricks_common.glsl), run on the GPU: brickOriginIn turns a brick
// index into its texel origin in a pool without integer division (llvmpipe divides lane by lane),
// so it must agree exactly with the integer arithmetic for every index of every pool shape
// brickPoolLayout can produce, up to the largest pool a 3D texture holds.
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "gl/context.hpp"
#include "shader_probe.hpp"
#include "voxel/brick_pool.hpp"

using namespace vct;

namespace {

struct AddressCase {
    glm::ivec4 indexAndBricks;  // brick index, pool bricks per axis
    glm::ivec4 origin;          // written by the shader
};

const char* kProbe =
    "#version 450\nlayout(local_size_x = 64) in;\n#include \"bricks_common.glsl\"\n"
    "struct AddressCase { ivec4 indexAndBricks; ivec4 origin; };\n"
    "layout(std430, binding = SSBO_CONE_COUNTERS) buffer Cases { AddressCase cases[]; };\n"
    "uniform uint uCount;\n"
    "void main() {\n"
    "    uint i = gl_GlobalInvocationID.x;\n"
    "    if (i >= uCount) return;\n"
    "    ivec4 c = cases[i].indexAndBricks;\n"
    "    cases[i].origin = ivec4(brickOriginIn(uint(c.x), c.yzw), 0);\n"
    "}\n";

}  // namespace

TEST(BrickAddressing, OriginsAreExactForEveryPoolShape) {
    auto context = gl::createContext(gl::defaultBackend());
    // From one brick to the most a 3D texture holds, for pools of one and of six directions.
    const std::uint32_t counts[] = {1, 2, 27, 1000, 628'582, 2'700'000, 16'777'217, 52'000'000, 300'000'000};
    GLint max3D = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
    std::mt19937 random(7);
    std::vector<AddressCase> cases;
    for (int depthShare : {1, 6})
        for (std::uint32_t count : counts) {
            const std::int64_t capacity = std::int64_t(max3D / 3) * (max3D / 3) * std::max(max3D / 3 / depthShare, 1);
            if (count > capacity) continue;
            const glm::ivec3 bricks = brickPoolLayout(count, "bricks", depthShare);
            const std::int64_t plane = std::int64_t(bricks.x) * bricks.y;
            auto add = [&](std::int64_t index) {
                if (index >= 0 && index < count) cases.push_back({glm::ivec4(int(index), bricks), glm::ivec4(-1)});
            };
            // The indices where a row or a plane begins or ends are where an estimate off by one shows.
            for (std::int64_t z = 0; z * plane < count; ++z)
                for (std::int64_t d : {-1, 0, 1}) add(z * plane + d), add(z * plane + bricks.x + d), add((z + 1) * plane - bricks.x + d);
            for (int i = 0; i < 2000; ++i) add(std::uniform_int_distribution<std::int64_t>(0, count - 1)(random));
            add(count - 1);
        }
    ASSERT_GT(cases.size(), 1000u);
    const std::vector<AddressCase> out =
        test::runShaderProbe("brick_addressing_probe.comp", {"bricks_common.glsl"}, kProbe, cases);
    int wrong = 0;
    for (const AddressCase& c : out) {
        const int b = c.indexAndBricks.x;
        const glm::ivec3 bricks(c.indexAndBricks.y, c.indexAndBricks.z, c.indexAndBricks.w);
        const glm::ivec3 expected = 3 * glm::ivec3(b % bricks.x, (b / bricks.x) % bricks.y, b / (bricks.x * bricks.y));
        if (glm::ivec3(c.origin) != expected && ++wrong <= 5)
            ADD_FAILURE() << "brick " << b << " of a pool of " << bricks.x << "×" << bricks.y << "×" << bricks.z
                          << " bricks: origin " << c.origin.x << "," << c.origin.y << "," << c.origin.z << ", expected "
                          << expected.x << "," << expected.y << "," << expected.z;
    }
    std::printf("[ bricks   ] %zu brick indices up to %d, %d wrong origins\n", out.size(),
                out.empty() ? 0 : out.back().indexAndBricks.x, wrong);
    EXPECT_EQ(wrong, 0);
}
