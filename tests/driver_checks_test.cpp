// The driver checks (engine/gl/driver_checks.hpp) on a frame that runs every pass: the octree
// build, photons, two bounces and the cone trace, then a second frame after the light moved,
// which reuses the first frame's buffers. No switch may change a bit of the image. Poisoned
// buffers and textures that changed it would mean a pass reads storage nobody wrote, which
// llvmpipe's zeroed allocations hide and a GPU's leftovers do not; all barriers that changed it
// would mean a pass asks for too few barrier bits (on llvmpipe, which finishes each dispatch
// before the next, only a GPU can show that).
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace {

std::string renderBytes(const std::filesystem::path& dir, const std::string& name, const std::string& environment,
                        const std::string& frames = "--frames 2 --light-path orbit") {
    const auto out = dir / name;
    const vct::test::CommandResult r = vct::test::runVct(
        "render -q --scene cornell --width 48 --height 36 --voxel-levels 6 --bounces 2 " + frames + " --out " +
            out.string() + ".png --hdr-out " + out.string() + ".pfm",
        environment);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(out.string() + ".pfm", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(DriverChecks, PoisonedBuffersAndFullBarriersChangeNoBit) {
    const auto dir = vct::test::testDir();
    const std::string plain = renderBytes(dir, "plain", "");
    ASSERT_GT(plain.size(), 48u * 36u * 12u);
    EXPECT_EQ(renderBytes(dir, "poisoned", "VCT_GL_POISON=1"), plain) << "a pass reads a buffer nobody wrote";
    EXPECT_EQ(renderBytes(dir, "barriers", "VCT_GL_ALL_BARRIERS=1"), plain) << "a pass asks for too few barrier bits";
    EXPECT_EQ(renderBytes(dir, "finished", "VCT_GL_FINISH=1"), plain) << "two dispatches must not overlap";
}

TEST(DriverChecks, RebuildsThatKeepTheirStorageWriteAllOfIt) {
    // Full frames rebuild the octree and the radiance volume in the storage of the previous build
    // (gl::fitBuffer, fitBrickPool); poisoned again, it must still give the image of one frame.
    const auto dir = vct::test::testDir();
    const std::string once = renderBytes(dir, "once", "", "--frames 1");
    ASSERT_GT(once.size(), 48u * 36u * 12u);
    EXPECT_EQ(renderBytes(dir, "rebuilt", "VCT_GL_POISON=1", "--frames 3 --full-frames"), once)
        << "a rebuild reads storage the previous build left";
}

TEST(DriverChecks, EveryNodeGroupSizeGivesTheSameBits) {
    // The radiance filter gives each node a work group whose size vct picks for the device (8 on
    // llvmpipe, 64 on a GPU): a GPU's size, and one invocation per node, must give this machine's
    // image, bit for bit (two bounces run the filter over every voxel).
    const auto dir = vct::test::testDir();
    const std::string chosen = renderBytes(dir, "chosen", "");
    ASSERT_GT(chosen.size(), 48u * 36u * 12u);
    EXPECT_EQ(renderBytes(dir, "size64", "VCT_NODE_GROUP_SIZE=64"), chosen);
    EXPECT_EQ(renderBytes(dir, "size1", "VCT_NODE_GROUP_SIZE=1"), chosen);
}

TEST(DriverChecks, EveryConeLaneCountGivesTheSameBits) {
    // An apex's cones are traced by one invocation, or with VCT_CONE_LANES=cones by one invocation
    // per cone (cone_trace.cpp, coneLanes), whose parts the work group adds: lanes must give one
    // invocation's image, bit for bit, for the frame's four narrow cones, for six (two
    // dispatches, the second with idle lanes), for the one cone of each later sample and for the
    // cone set, each frame with a second bounce, whose voxels gather with the cone set.
    const auto dir = vct::test::testDir();
    for (const std::string cones : {"", "--cone-rays 6 ", "--samples 3 ", "--cone-rays 0 "}) {
        const std::string frames = cones + "--frames 2 --light-path orbit";
        const std::string one = renderBytes(dir, "lanes1", "VCT_CONE_LANES=1", frames);
        ASSERT_GT(one.size(), 48u * 36u * 12u);
        EXPECT_TRUE(renderBytes(dir, "lanes", "VCT_CONE_LANES=cones", frames) == one) << "cones: " << cones;
    }
}

TEST(DriverChecks, DeviceChoicesRefuseValuesTheyDoNotKnow) {
    // The variables that force a device's choice name themselves and what they take, and stop
    // the render, rather than falling back to a default that hides the mistake.
    struct Case {
        std::string environment, message;
    };
    for (const Case& c : {Case{"VCT_CONE_LANES=2", "VCT_CONE_LANES must be 1"},
                          Case{"VCT_NODE_GROUP_SIZE=0", "VCT_NODE_GROUP_SIZE must be a whole number"}}) {
        const vct::test::CommandResult r = vct::test::runVct(
            "render -q --scene cornell --width 16 --height 12 --voxel-levels 5 --out " +
                (vct::test::testDir() / "refused.png").string(),
            c.environment);
        EXPECT_NE(r.exitCode, 0) << c.environment;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.environment << ": " << r.output;
    }
}
