// Storage kept from one octree build to the next: buffers while the new size fits with at most a
// quarter to spare, else replaced with an eighth to spare (gl::fitBuffer); brick pools while their
// layout stays the same (fitBrickPool).
#include "gl/context.hpp"
#include "gl/objects.hpp"
#include "test_util.hpp"
#include "voxel/brick_pool.hpp"

using namespace vct;

namespace {
GLsizeiptr withAnEighthToSpare(GLsizeiptr bytes) { return (bytes + bytes / 8 + 15) / 16 * 16; }
}  // namespace

TEST(GlStorage, BuffersAreKeptWhileTheyFitAndReplacedWithRoomToGrow) {
    auto context = gl::createContext(gl::defaultBackend());
    gl::Buffer buffer;
    EXPECT_TRUE(gl::fitBuffer(buffer, 1000, 0, "test"));
    EXPECT_EQ(gl::bufferBytes(buffer), 1000) << "a first allocation is exact";
    const GLuint first = buffer.id();

    EXPECT_FALSE(gl::fitBuffer(buffer, 1000, 0, "test"));
    EXPECT_FALSE(gl::fitBuffer(buffer, 800, 0, "test")) << "a quarter to spare is kept";
    EXPECT_EQ(buffer.id(), first);
    EXPECT_TRUE(gl::fitBuffer(buffer, 799, 0, "test")) << "more than a quarter to spare is freed";
    EXPECT_EQ(gl::bufferBytes(buffer), withAnEighthToSpare(799));
    EXPECT_EQ(gl::bufferBytes(buffer) % 16, 0) << "clearable as RGBA32F";

    EXPECT_TRUE(gl::fitBuffer(buffer, 1200, 0, "test")) << "larger than held";
    EXPECT_EQ(gl::bufferBytes(buffer), withAnEighthToSpare(1200));
    EXPECT_FALSE(gl::fitBuffer(buffer, 1300, 0, "test")) << "within the eighth to spare";
    EXPECT_TRUE(gl::fitBuffer(buffer, 1300, GL_DYNAMIC_STORAGE_BIT, "test")) << "other storage flags";
    EXPECT_EQ(gl::bufferBytes(gl::Buffer()), 0);
}

TEST(GlStorage, BrickPoolsAreKeptWhileTheirLayoutStaysTheSame) {
    auto context = gl::createContext(gl::defaultBackend());
    gl::Texture pool;
    glm::ivec3 layout{0};
    fitBrickPool(pool, layout, 1000, "nodes", 1, GL_RGBA16F, "test pool");
    EXPECT_EQ(layout, brickPoolLayout(1000, "nodes"));
    const GLuint first = pool.id();

    fitBrickPool(pool, layout, 999, "nodes", 1, GL_RGBA16F, "test pool");
    ASSERT_EQ(brickPoolLayout(999, "nodes"), brickPoolLayout(1000, "nodes"));
    EXPECT_EQ(pool.id(), first) << "the same layout";
    fitBrickPool(pool, layout, 900, "nodes", 1, GL_RGBA16F, "test pool");
    EXPECT_EQ(layout, brickPoolLayout(900, "nodes")) << "another layout, exactly the new one";
    GLint depth = 0;
    glGetTextureLevelParameteriv(pool.id(), 0, GL_TEXTURE_DEPTH, &depth);
    EXPECT_EQ(depth, 3 * layout.z);

    gl::Texture stacked;
    glm::ivec3 stackedLayout{0};
    fitBrickPool(stacked, stackedLayout, 500, "nodes", 6, GL_RGBA32F, "test pool");
    glGetTextureLevelParameteriv(stacked.id(), 0, GL_TEXTURE_DEPTH, &depth);
    EXPECT_EQ(depth, 3 * 6 * stackedLayout.z) << "six pools stacked along z";
}
