// Image error metrics (`vct compare`, engine/metrics) against values known in closed form, and the
// CPU display transform against the engine's GLSL one.
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "core/image.hpp"
#include "core/tonemap.hpp"
#include "metrics/error_image.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/pixel_mask.hpp"
#include "metrics/ssim.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

std::string path(const std::filesystem::path& p) { return p.string(); }

// A smooth, non-constant test image (values 0.05 .. 1.05).
ImageF gradientImage(int width, int height) {
    ImageF image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[0] = 0.05f + float(x) / width;
            p[1] = 0.05f + float(y) / height;
            p[2] = 0.05f + 0.5f * float((x * 7 + y * 3) % 11) / 11.0f;
            p[3] = 1.0f;
        }
    return image;
}

ImageF offsetImage(ImageF image, float offset, int fromX = 0) {
    for (int y = 0; y < image.height; ++y)
        for (int x = fromX; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y)[c] += offset;
    return image;
}

nlohmann::json compareJson(const std::string& arguments, const std::filesystem::path& json, std::string* output = nullptr) {
    const auto result = test::runVct("compare " + arguments + " --json " + path(json));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    if (output) *output = result.output;
    std::ifstream file(json);
    return nlohmann::json::parse(file);
}

}  // namespace

TEST(Metrics, IdenticalImagesHaveZeroErrorInfinitePsnrAndSsimOne) {
    const auto dir = test::testDir();
    writeHdrImage(dir / "a.pfm", gradientImage(40, 30));
    std::string output;
    const auto j = compareJson(path(dir / "a.pfm") + " " + path(dir / "a.pfm"), dir / "m.json", &output);
    EXPECT_EQ(j["rmse"].get<double>(), 0.0);
    EXPECT_EQ(j["relmse"].get<double>(), 0.0);
    EXPECT_EQ(j["psnr"], "inf");
    EXPECT_EQ(j["ssim"].get<double>(), 1.0);
    EXPECT_EQ(j["pixels"].get<int>(), 1200);
    EXPECT_NE(output.find("psnr    inf"), std::string::npos) << output;
}

// A constant offset d on every channel: RMSE = d exactly, relMSE = mean d²/(b² + ε), and on the
// displayed luma PSNR/SSIM follow from their definitions.
TEST(Metrics, ConstantOffsetGivesKnownErrors) {
    const auto dir = test::testDir();
    const ImageF b = gradientImage(48, 32);
    const ImageF a = offsetImage(b, 0.1f);
    writeHdrImage(dir / "a.exr", a);
    writeHdrImage(dir / "b.pfm", b);
    const auto j = compareJson(path(dir / "a.exr") + " " + path(dir / "b.pfm"), dir / "m.json");
    double relMse = 0.0;
    for (int y = 0; y < b.height; ++y)
        for (int x = 0; x < b.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = double(a.at(x, y)[c]) - b.at(x, y)[c], vb = b.at(x, y)[c];
                relMse += d * d / (vb * vb + 1e-2);
            }
    relMse /= 3.0 * b.width * b.height;
    EXPECT_NEAR(j["rmse"].get<double>(), 0.1, 1e-6);
    EXPECT_NEAR(j["relmse"].get<double>(), relMse, 1e-9);
    EXPECT_GT(j["relmse"].get<double>(), 0.01);
    EXPECT_LT(j["ssim"].get<double>(), 1.0);
    EXPECT_GT(j["ssim"].get<double>(), 0.5);
    EXPECT_GT(j["psnr"].get<double>(), 10.0);
    EXPECT_LT(j["psnr"].get<double>(), 40.0);
    // Every pixel is brighter in A: the median relative error is positive, none within 1 %.
    EXPECT_GT(j["rel_error_median"].get<double>(), 0.05);
    EXPECT_EQ(j["within_1_percent"].get<double>(), 0.0);
}

// PSNR and SSIM of constant luma images in closed form: PSNR = −20·log10|a − b|, and with zero
// variance SSIM = (2ab + C1)/(a² + b² + C1).
TEST(Metrics, PsnrAndSsimOfConstantImagesMatchTheFormulas) {
    const int w = 20, h = 16;
    const auto mask = metrics::allPixels(w, h);
    const std::vector<double> a(w * h, 0.6), b(w * h, 0.4);
    EXPECT_NEAR(metrics::psnr(a, b, mask), -20.0 * std::log10(0.2), 1e-9);
    const double c1 = 1e-4;
    EXPECT_NEAR(metrics::ssim(a, b, mask), (2 * 0.6 * 0.4 + c1) / (0.36 + 0.16 + c1), 1e-9);
    // Structure: an image against its negative is far from similar, against itself identical.
    std::vector<double> stripes(w * h), inverse(w * h);
    for (int i = 0; i < w * h; ++i) {
        stripes[i] = (i % w) % 2 ? 0.9 : 0.1;
        inverse[i] = 1.0 - stripes[i];
    }
    EXPECT_LT(metrics::ssim(stripes, inverse, mask), 0.0);
    EXPECT_DOUBLE_EQ(metrics::ssim(stripes, stripes, mask), 1.0);
    // The window: 11×11 Gaussian, σ = 1.5. A single differing pixel in a large constant image
    // changes SSIM only near it.
    std::vector<double> spot(w * h, 0.5), flat(w * h, 0.5);
    spot[8 * w + 10] = 0.9;
    const double s = metrics::ssim(spot, flat, mask);
    EXPECT_LT(s, 1.0);
    EXPECT_GT(s, 0.8);
}

// Only the mask's pixels count: A differs from B by 0.2 in the right half only.
TEST(Metrics, MaskRestrictsTheComparison) {
    const auto dir = test::testDir();
    const int w = 32, h = 20;
    const ImageF b = gradientImage(w, h);
    const ImageF a = offsetImage(b, 0.2f, w / 2);
    ImageF left(w, h), right(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) (x < w / 2 ? left : right).at(x, y)[c] = 1.0f;
    writeHdrImage(dir / "a.pfm", a);
    writeHdrImage(dir / "b.pfm", b);
    writeHdrImage(dir / "left.pfm", left);
    Image8 rightPng(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) rightPng.at(x, y)[c] = x >= w / 2 || c == 3 ? 255 : 0;
    writePng(dir / "right.png", rightPng);
    const std::string ab = path(dir / "a.pfm") + " " + path(dir / "b.pfm");

    const auto all = compareJson(ab, dir / "all.json");
    const auto onlyLeft = compareJson(ab + " --mask " + path(dir / "left.pfm"), dir / "l.json");
    const auto onlyRight = compareJson(ab + " --mask " + path(dir / "right.png"), dir / "r.json");
    EXPECT_NEAR(all["rmse"].get<double>(), 0.2 / std::sqrt(2.0), 1e-6);
    EXPECT_EQ(onlyLeft["pixels"].get<int>(), w * h / 2);
    EXPECT_EQ(onlyLeft["rmse"].get<double>(), 0.0);
    EXPECT_EQ(onlyLeft["psnr"], "inf");
    EXPECT_EQ(onlyLeft["ssim"].get<double>(), 1.0) << "SSIM windows must not see pixels outside the mask";
    EXPECT_LT(all["ssim"].get<double>(), 1.0);
    EXPECT_EQ(onlyRight["pixels"].get<int>(), w * h / 2);
    EXPECT_NEAR(onlyRight["rmse"].get<double>(), 0.2, 1e-6);
}

TEST(Metrics, SizeMismatchAndBadInputEndInOneClearError) {
    const auto dir = test::testDir();
    writeHdrImage(dir / "a.pfm", gradientImage(32, 20));
    writeHdrImage(dir / "b.pfm", gradientImage(30, 20));
    writeHdrImage(dir / "mask.pfm", gradientImage(8, 8));
    ImageF nan = gradientImage(32, 20);
    nan.at(3, 4)[1] = std::numeric_limits<float>::quiet_NaN();
    writeHdrImage(dir / "nan.pfm", nan);
    const std::pair<std::string, std::string> cases[] = {
        {path(dir / "a.pfm") + " " + path(dir / "b.pfm"), "differ in size"},
        {path(dir / "a.pfm") + " " + path(dir / "a.pfm") + " --mask " + path(dir / "mask.pfm"), "mask"},
        {path(dir / "a.pfm") + " " + path(dir / "missing.pfm"), "not found"},
        {path(dir / "nan.pfm") + " " + path(dir / "a.pfm"), "non-finite"},
        {path(dir / "a.pfm") + " " + path(dir / "a.pfm") + " --tonemap filmic", "tone curve"},
        {path(dir / "a.pfm") + " " + path(dir / "a.pfm") + " --json " + path(dir / "no" / "m.json"), "does not exist"},
    };
    for (const auto& [arguments, mentions] : cases) {
        const auto result = test::runVct("compare " + arguments);
        EXPECT_EQ(result.exitCode, 1) << arguments << "\n" << result.output;
        EXPECT_NE(result.output.find("vct: error: "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find(mentions), std::string::npos) << arguments << ": " << result.output;
    }
    const auto sizes = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm"));
    EXPECT_NE(sizes.output.find("32x20"), std::string::npos) << sizes.output;
    EXPECT_NE(sizes.output.find("30x20"), std::string::npos) << sizes.output;
}

// The false-colour image: white where equal, blue where A is darker by ≥ the scale, red where
// brighter, black outside the mask; the legend names the scale.
TEST(Metrics, ErrorImageColoursFollowTheDocumentedScale) {
    const auto dir = test::testDir();
    const int w = 12, h = 4;
    ImageF b(w, h), a(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                b.at(x, y)[c] = 1.0f;
                a.at(x, y)[c] = x < 4 ? 1.0f : x < 8 ? 0.5f : 1.05f;  // equal, −50 %, +5 %
            }
    const Image8 image = metrics::relativeErrorImage(a, b, metrics::allPixels(w, h), 0.2);
    const std::uint8_t* equal = image.at(0, 0);
    const std::uint8_t* darker = image.at(5, 1);
    const std::uint8_t* brighter = image.at(9, 2);
    EXPECT_EQ(int(equal[0]), 255);
    EXPECT_EQ(int(equal[1]), 255);
    EXPECT_EQ(int(equal[2]), 255);
    EXPECT_EQ(int(darker[0]), 59);  // saturated blue
    EXPECT_EQ(int(darker[2]), 192);
    EXPECT_EQ(int(brighter[0]), 236);  // a quarter of the way from white to red (180, 4, 38)
    EXPECT_EQ(int(brighter[1]), 192);
    EXPECT_EQ(int(brighter[2]), 201);
    auto mask = metrics::allPixels(w, h);
    mask.counts[0] = 0;
    --mask.countedPixels;
    EXPECT_EQ(int(metrics::relativeErrorImage(a, b, mask, 0.2).at(0, 0)[0]), 0);

    writeHdrImage(dir / "a.pfm", a);
    writeHdrImage(dir / "b.pfm", b);
    const auto result = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm") + " --error-image " +
                                     path(dir / "e.png") + " --error-scale 0.1");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("±10 %"), std::string::npos) << result.output;
    EXPECT_EQ(readPng(dir / "e.png").width, w);
}

// core/tonemap.hpp is the C++ twin of shaders/tonemap.glsl: the engine's own PNG and the CPU
// display transform of the engine's HDR output agree to the last bit, ±1 for float rounding. How
// many values land on the other side of a rounding step depends on the driver's pow and exp: none
// on llvmpipe, a few percent on a GPU whose transcendentals are approximations; a wrong curve or
// a wrong sRGB step moves most values by more than one step.
TEST(Metrics, CpuDisplayTransformMatchesTheEnginePng) {
    const auto dir = test::testDir();
    for (const char* curve : {"aces", "reinhard", "clamp"}) {
        const auto result = test::runVct(std::string("render -q --scene cornell --width 64 --height 48 --exposure 1.5 "
                                                     "--tonemap ") + curve + " --out " + path(dir / "e.png") +
                                         " --hdr-out " + path(dir / "e.pfm"));
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const Image8 engine = readPng(dir / "e.png");
        const Image8 cpu = tonemapImage(readHdrImage(dir / "e.pfm"), 1.5, parseTonemapCurve(curve));
        ASSERT_EQ(engine.width, cpu.width);
        int worst = 0, exact = 0, total = 0;
        for (std::size_t i = 0; i < engine.rgba.size(); ++i) {
            if (i % 4 == 3) continue;
            const int d = std::abs(int(engine.rgba[i]) - int(cpu.rgba[i]));
            worst = std::max(worst, d);
            exact += d == 0;
            ++total;
        }
        std::printf("[ tonemap ] %s: %.2f %% of channel values identical, worst difference %d/255\n", curve,
                    100.0 * exact / total, worst);
        EXPECT_LE(worst, 1) << curve;
        EXPECT_GT(double(exact) / total, 0.95) << curve;
    }
    // Known values: sRGB OETF of 0.5 is 0.7354, ACES(1) = 0.8038.
    EXPECT_NEAR(linearToSrgb(glm::vec3(0.5f)).x, 0.735357f, 1e-5);
    EXPECT_NEAR(toneCurve(glm::vec3(1.0f), TonemapCurve::Aces).x, 2.54f / 3.16f, 1e-6);
    EXPECT_NEAR(toneCurve(glm::vec3(1.0f), TonemapCurve::Reinhard).x, 0.5f, 1e-7);
}
