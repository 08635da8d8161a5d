// `vct compare A B`: error metrics of image A against the reference B (both linear radiance,
// .pfm or .exr, same size): RMSE and relative MSE in linear radiance, PSNR and SSIM on the
// displayed luma, per-pixel relative error statistics; optionally a mask, a JSON report and a
// false-colour error image. Definitions: engine/metrics/image_metrics.hpp and ssim.hpp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "core/tonemap.hpp"
#include "metrics/error_image.hpp"
#include "metrics/image_metrics.hpp"

namespace vct::cli {
namespace {

struct CompareOptions {
    std::string a, b, mask, json, errorImage;
    double exposureEV = 0.0;
    std::string toneCurve = "aces";
    double errorScale = metrics::kDefaultErrorScale;
};

std::string formatPsnr(double psnr) {
    if (std::isinf(psnr)) return "inf";
    return concat(std::round(psnr * 1000.0) / 1000.0, " dB");
}

void run(const CompareOptions& o) {
    if (!o.json.empty()) ensureWritable(o.json);
    if (!o.errorImage.empty()) ensureWritable(o.errorImage);
    if (!std::isfinite(o.exposureEV)) fail("--exposure must be a finite number of stops");
    if (!(o.errorScale > 0.0) || !std::isfinite(o.errorScale))
        fail("--error-scale must be a positive number (e.g. 0.2 for ±20 %)");
    metrics::DisplaySettings display{o.exposureEV, parseTonemapCurve(o.toneCurve)};
    const ImageF a = readHdrImage(o.a);
    const ImageF b = readHdrImage(o.b);
    if (a.width != b.width || a.height != b.height)
        fail("the images differ in size: '", o.a, "' is ", a.width, "x", a.height, ", '", o.b, "' is ", b.width, "x",
             b.height, "; compare images rendered at the same --width and --height");
    metrics::PixelMask mask = metrics::allPixels(a.width, a.height);
    if (!o.mask.empty()) {
        const ImageF maskImage = metrics::readMaskImage(o.mask);
        if (maskImage.width != a.width || maskImage.height != a.height)
            fail("the mask '", o.mask, "' is ", maskImage.width, "x", maskImage.height, " but the images are ",
                 a.width, "x", a.height, "; use a mask of the same size");
        mask = metrics::maskFromImage(maskImage);
    }
    const metrics::ImageMetrics m = metrics::compareImages(a, b, mask, display);

    std::printf("compare %s against %s: %dx%d, %zu pixels%s\n", o.a.c_str(), o.b.c_str(), m.width, m.height, m.pixels,
                o.mask.empty() ? "" : concat(" (mask ", o.mask, ")").c_str());
    std::printf("  rmse    %.6g  (linear radiance W/(m^2 sr))\n", m.rmse);
    std::printf("  relmse  %.6g  (epsilon %.g)\n", m.relMse, metrics::kRelMseEpsilon);
    std::printf("  psnr    %s  (display luma, EV %g, %s)\n", formatPsnr(m.psnr).c_str(), o.exposureEV, o.toneCurve.c_str());
    std::printf("  ssim    %.6f\n", m.ssim);
    std::printf("  relative error per pixel: median %.3f %%, p95 %.3f %%, within 1 %%: %.2f %%, within 5 %%: %.2f %%\n",
                100.0 * m.relErrorMedian, 100.0 * m.relErrorP95, 100.0 * m.fractionWithin1Percent,
                100.0 * m.fractionWithin5Percent);
    std::printf("  mean luminance  A %.6g  B %.6g\n", m.meanLuminanceA, m.meanLuminanceB);

    if (!o.errorImage.empty()) {
        writePng(o.errorImage, metrics::relativeErrorImage(a, b, mask, o.errorScale));
        std::printf("  error image %s: %s\n", o.errorImage.c_str(), metrics::errorImageLegend(o.errorScale).c_str());
    }
    if (!o.json.empty()) {
        nlohmann::ordered_json j;
        j["a"] = o.a;
        j["b"] = o.b;
        j["mask"] = o.mask.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(o.mask);
        j["width"] = m.width;
        j["height"] = m.height;
        j["pixels"] = m.pixels;
        j["exposure_ev"] = o.exposureEV;
        j["tonemap"] = o.toneCurve;
        j["rmse"] = m.rmse;
        j["relmse"] = m.relMse;
        j["relmse_epsilon"] = metrics::kRelMseEpsilon;
        j["psnr"] = std::isinf(m.psnr) ? nlohmann::ordered_json("inf") : nlohmann::ordered_json(m.psnr);
        j["ssim"] = m.ssim;
        j["rel_error_median"] = m.relErrorMedian;
        j["rel_error_p95"] = m.relErrorP95;
        j["within_1_percent"] = m.fractionWithin1Percent;
        j["within_5_percent"] = m.fractionWithin5Percent;
        j["mean_luminance_a"] = m.meanLuminanceA;
        j["mean_luminance_b"] = m.meanLuminanceB;
        std::ofstream file(o.json);
        file << j.dump(2) << "\n";
        if (!file) fail("cannot write '", o.json, "' (disk full?)");
    }
    std::fflush(stdout);
}

}  // namespace

Run addCompareCommand(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    CompareOptions& o = *options;
    CLI::App* command = app.add_subcommand(
        "compare", "error metrics of image A against reference B (RMSE, relMSE, PSNR, SSIM, relative error)");
    command->add_option("A", o.a, "image to judge (.pfm or .exr, linear radiance)")->required();
    command->add_option("B", o.b, "reference image (.pfm or .exr), same size")->required();
    command->add_option("--mask", o.mask, "only pixels where this image's luminance is > 0.5 count (.pfm/.exr/.png)");
    command->add_option("--json", o.json, "write the metrics as JSON (psnr is the string \"inf\" for identical images)");
    command->add_option("--error-image", o.errorImage, "false-colour PNG of the signed relative error per pixel");
    command->add_option("--error-scale", o.errorScale, "relative error shown in full colour by --error-image")
        ->capture_default_str();
    command->add_option("--exposure", o.exposureEV, "exposure (EV) of the display transform for PSNR/SSIM")
        ->capture_default_str();
    command->add_option("--tonemap", o.toneCurve, "tone curve for PSNR/SSIM: aces, reinhard, clamp")
        ->capture_default_str();
    return [options] { run(*options); };
}

}  // namespace vct::cli
