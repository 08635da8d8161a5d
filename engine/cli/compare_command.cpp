// `vct compare A B`: error metrics of image A against the reference B (both linear radiance,
// .pfm or .exr, same size): RMSE and relative MSE in linear radiance, PSNR and SSIM on the
// displayed luma, per-pixel relative error statistics; optionally a mask, a JSON report, a
// false-colour error image, a grid of per-region brightness ratios (--regions) and a picture of
// the per-pixel ratio (--ratio-image). Definitions: engine/metrics/image_metrics.hpp, ssim.hpp,
// region_ratio.hpp and error_image.hpp.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "core/tonemap.hpp"
#include "metrics/error_image.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"

namespace vct::cli {
namespace {

struct CompareOptions {
    std::string a, b, mask, json, errorImage, ratioImage, regions;
    double exposureEV = 0.0;
    std::string toneCurve = "aces";
    double errorScale = metrics::kDefaultErrorScale;
    double ratioStops = metrics::kDefaultRatioStops;
    bool regionsGiven = false;  // an empty --regions value is refused, not ignored
};

struct RegionGrid {
    int columns = 0, rows = 0;
};

// "CxR" (e.g. "3x3"), each a whole number in 1..kMaxRegionCells.
RegionGrid parseRegionGrid(const std::string& text) {
    const auto refuse = [&] {
        fail("--regions must be COLUMNSxROWS, each a whole number from 1 to ", metrics::kMaxRegionCells,
             " (e.g. 3x3), got '", text, "'");
    };
    const auto wholeNumber = [&](std::string_view digits) {
        int value = 0;
        const bool onlyDigits = !digits.empty() && digits.size() <= 3 &&
                                digits.find_first_not_of("0123456789") == std::string_view::npos;
        if (!onlyDigits) refuse();
        std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (value < 1 || value > metrics::kMaxRegionCells) refuse();
        return value;
    };
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string::npos) refuse();
    const std::string_view whole(text);
    return {wholeNumber(whole.substr(0, x)), wholeNumber(whole.substr(x + 1))};
}

std::string formatRatio(const metrics::RegionCell& cell) {
    if (!cell.ratio) return "-";
    char text[32];
    std::snprintf(text, sizeof text, cell.significant ? "%.3f" : "(%.3f)", *cell.ratio);
    return text;
}

// One value per cell, rows top to bottom as the image is seen.
void printGrid(const metrics::RegionRatios& r, const char* title,
               const std::function<std::string(const metrics::RegionCell&)>& value) {
    std::printf("    %s\n      %-8s", title, "");
    for (int column = 0; column < r.columns; ++column) std::printf(" %10s", concat("column ", column).c_str());
    std::printf("\n");
    for (int row = 0; row < r.rows; ++row) {
        std::printf("      %-8s", concat("row ", row).c_str());
        for (int column = 0; column < r.columns; ++column) std::printf(" %10s", value(r.cell(column, row)).c_str());
        std::printf("\n");
    }
}

std::string describeExtreme(const metrics::RegionRatios& r, const std::optional<double>& ratio) {
    for (const auto& cell : r.cells)
        if (cell.significant && cell.ratio == ratio)
            return concat(formatRatio(cell), " (column ", cell.column, ", row ", cell.row, ")");
    return "-";
}

void printRegions(const metrics::RegionRatios& r) {
    std::printf("  regions %dx%d: mean luminance per cell, column 0 at the left, row 0 at the top\n", r.columns,
                r.rows);
    printGrid(r, "A/B", formatRatio);
    printGrid(r, "B mean", [](const metrics::RegionCell& cell) {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", cell.meanB);
        return cell.pixels ? std::string(text) : std::string("-");
    });
    printGrid(r, "share of B's light", [](const metrics::RegionCell& cell) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f %%", 100.0 * cell.share);
        return cell.pixels ? std::string(text) : std::string("-");
    });
    const double threshold = metrics::kSignificantCellFraction * r.meanB;
    std::printf("    (…) = B mean ≤ %g %% of the image's %.4g, left out of min/max; "
                "- = no counted pixel or B mean ≤ 0\n",
                100.0 * metrics::kSignificantCellFraction, r.meanB);
    if (r.minRatioSignificant)
        std::printf("  regions A/B over cells with B mean > %.4g: min %s, max %s\n", threshold,
                    describeExtreme(r, r.minRatioSignificant).c_str(),
                    describeExtreme(r, r.maxRatioSignificant).c_str());
    else
        std::printf("  regions A/B: no cell has a B mean above %.4g, so no min/max\n", threshold);
}

nlohmann::ordered_json optionalNumber(const std::optional<double>& value) {
    return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json regionsJson(const metrics::RegionRatios& r) {
    nlohmann::ordered_json j;
    j["columns"] = r.columns;
    j["rows"] = r.rows;
    j["mean_a"] = r.meanA;
    j["mean_b"] = r.meanB;
    j["significant_fraction"] = metrics::kSignificantCellFraction;
    j["min_ratio_significant"] = optionalNumber(r.minRatioSignificant);
    j["max_ratio_significant"] = optionalNumber(r.maxRatioSignificant);
    j["cells"] = nlohmann::ordered_json::array();
    for (const auto& cell : r.cells) {
        nlohmann::ordered_json c;
        c["column"] = cell.column;
        c["row"] = cell.row;
        c["ratio"] = optionalNumber(cell.ratio);
        c["mean_a"] = cell.meanA;
        c["mean_b"] = cell.meanB;
        c["pixels"] = cell.pixels;
        c["share"] = cell.share;
        c["significant"] = cell.significant;
        c["x0"] = cell.x0;
        c["x1"] = cell.x1;
        c["y0"] = cell.y0;
        c["y1"] = cell.y1;
        j["cells"].push_back(c);
    }
    return j;
}

std::string formatPsnr(double psnr) {
    if (std::isinf(psnr)) return "inf";
    return concat(std::round(psnr * 1000.0) / 1000.0, " dB");
}

void run(const CompareOptions& o) {
    if (!o.json.empty()) ensureWritable(o.json);
    if (!o.errorImage.empty()) ensureWritablePng(o.errorImage, "--error-image");
    if (!o.ratioImage.empty()) ensureWritablePng(o.ratioImage, "--ratio-image");
    std::optional<RegionGrid> grid;
    if (o.regionsGiven) grid = parseRegionGrid(o.regions);
    if (!(o.ratioStops > 0.0) || !std::isfinite(o.ratioStops))
        fail("--ratio-stops must be a positive number of stops (e.g. 2: full colour at 4x)");
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
    // Before anything is printed: a grid the image cannot hold fails alone, not after the metrics.
    std::optional<metrics::RegionRatios> regions;
    if (grid) regions = metrics::regionRatios(a, b, grid->columns, grid->rows, &mask);

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
    if (regions) printRegions(*regions);

    if (!o.errorImage.empty()) {
        writePng(o.errorImage, metrics::relativeErrorImage(a, b, mask, o.errorScale));
        std::printf("  error image %s: %s\n", o.errorImage.c_str(), metrics::errorImageLegend(o.errorScale).c_str());
    }
    if (!o.ratioImage.empty()) {
        writePng(o.ratioImage, metrics::ratioImage(a, b, mask, o.ratioStops));
        std::printf("  ratio image %s: %s\n", o.ratioImage.c_str(), metrics::ratioImageLegend(o.ratioStops).c_str());
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
        if (regions) j["regions"] = regionsJson(*regions);
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
    CLI::Option* regions = command->add_option(
        "--regions", o.regions, "per-cell A/B of mean luminance on a COLUMNSxROWS grid (e.g. 3x3, 1..64 per side)");
    command->add_option("--ratio-image", o.ratioImage,
                        "false-colour PNG of log2(A/B) of luminance per pixel: blue darker, red brighter");
    command->add_option("--ratio-stops", o.ratioStops, "stops of A/B shown in full colour by --ratio-image")
        ->capture_default_str();
    command->add_option("--exposure", o.exposureEV, "exposure (EV) of the display transform for PSNR/SSIM")
        ->capture_default_str();
    command->add_option("--tonemap", o.toneCurve, "tone curve for PSNR/SSIM: aces, reinhard, clamp")
        ->capture_default_str();
    return [options, regions] {
        options->regionsGiven = regions->count() > 0;
        run(*options);
    };
}

}  // namespace vct::cli
