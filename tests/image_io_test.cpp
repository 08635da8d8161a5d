// Image files: PFM/EXR round trips keep float values exactly, orientation is preserved, bad files
// give clear errors.
#include <fstream>

#include "core/error.hpp"
#include "core/image.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {
ImageF gradient(int w, int h) {
    ImageF image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = image.at(x, y);
            p[0] = float(x) + 0.25f;
            p[1] = float(y) * 1e-3f;
            p[2] = x == 0 && y == 0 ? 1e6f : -2.0f;
            p[3] = 1.0f;
        }
    return image;
}
}  // namespace

TEST(ImageIo, PfmRoundTripIsExactAndKeepsRowOrder) {
    const auto dir = test::testDir();
    const ImageF image = gradient(7, 5);
    writeHdrImage(dir / "a.pfm", image);
    const ImageF back = readHdrImage(dir / "a.pfm");
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(back.at(x, y)[c], image.at(x, y)[c]) << x << "," << y;
}

TEST(ImageIo, ExrRoundTripIsExact) {
    const auto dir = test::testDir();
    const ImageF image = gradient(6, 3);
    writeHdrImage(dir / "a.exr", image);
    const ImageF back = readHdrImage(dir / "a.exr");
    ASSERT_EQ(back.width, 6);
    ASSERT_EQ(back.height, 3);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) EXPECT_EQ(back.rgba[i], image.rgba[i]) << i;
}

TEST(ImageIo, PngRoundTrip) {
    const auto dir = test::testDir();
    Image8 image(3, 2);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * 10);
    writePng(dir / "a.png", image);
    const Image8 back = readPng(dir / "a.png");
    EXPECT_EQ(back.rgba, image.rgba);
}

TEST(ImageIo, BadFilesGiveClearErrors) {
    const auto dir = test::testDir();
    std::ofstream(dir / "truncated.pfm") << "PF\n4 4\n-1.0\n0123";
    EXPECT_THROW(readHdrImage(dir / "truncated.pfm"), Error);
    std::ofstream(dir / "junk.pfm") << "P6 not a pfm";
    EXPECT_THROW(readHdrImage(dir / "junk.pfm"), Error);
    EXPECT_THROW(readHdrImage(dir / "missing.pfm"), Error);
    EXPECT_THROW(writeHdrImage(dir / "image.bmp", ImageF(1, 1)), Error);
    try {
        writePng(dir / "no_such_folder" / "x.png", Image8(1, 1));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_folder"), std::string::npos) << e.what();
    }
}
