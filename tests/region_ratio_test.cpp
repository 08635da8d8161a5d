// Per-region brightness ratios (metrics/region_ratio.hpp) and the log-ratio picture
// (metrics/error_image.hpp): in process on synthetic images whose per-cell ratios are known, then
// `vct compare --regions / --ratio-image` end to end through the real binary, and the benchmark
// report's per-region table.
#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/bench_report.hpp"
#include "core/error.hpp"
#include "core/image.hpp"
#include "metrics/error_image.hpp"
#include "metrics/pixel_mask.hpp"
#include "metrics/region_ratio.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

std::string path(const std::filesystem::path& p) { return p.string(); }

ImageF greyImage(int width, int height, const std::function<float(int x, int y)>& value) {
    ImageF image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[0] = p[1] = p[2] = value(x, y);
            p[3] = 1.0f;
        }
    return image;
}

// A reference that varies inside every cell, so a cell's ratio is a ratio of sums, not of two
// constants.
float referenceValue(int x, int y) { return 0.1f + 0.01f * float((x * 3 + y * 5) % 7); }

// 10×7 pixels in 3×3 cells: columns [0,3) [3,6) [6,10), rows [0,2) [2,4) [4,7). A is B times a
// power of two per cell, so every ratio is exact in floating point. Cell (2, 0) has a black
// reference; cell (2, 2) a reference 1000× darker than the rest (not significant).
constexpr int kWidth = 10, kHeight = 7;
constexpr double kFactor[3][3] = {{0.5, 1.0, 0.0}, {2.0, 0.25, 4.0}, {1.0, 0.5, 16.0}};  // [row][column]

int cellColumn(int x) { return x < 3 ? 0 : x < 6 ? 1 : 2; }
int cellRow(int y) { return y < 2 ? 0 : y < 4 ? 1 : 2; }

float knownB(int x, int y) {
    const int column = cellColumn(x), row = cellRow(y);
    if (column == 2 && row == 0) return 0.0f;
    if (column == 2 && row == 2) return referenceValue(x, y) / 1024.0f;
    return referenceValue(x, y);
}

float knownA(int x, int y) {
    const int column = cellColumn(x), row = cellRow(y);
    if (column == 2 && row == 0) return 0.3f;  // light where the reference has none
    return float(kFactor[row][column]) * knownB(x, y);
}

ImageF knownImageA() { return greyImage(kWidth, kHeight, knownA); }
ImageF knownImageB() { return greyImage(kWidth, kHeight, knownB); }

// Mean luminance of a grey image over a pixel range, the long way.
double meanOver(const ImageF& image, int x0, int x1, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += metrics::luminance(image.at(x, y));
    return sum / double((x1 - x0) * (y1 - y0));
}

void writeKnownPair(const std::filesystem::path& dir) {
    writeHdrImage(dir / "a.pfm", knownImageA());
    writeHdrImage(dir / "b.pfm", knownImageB());
}

}  // namespace

TEST(RegionRatio, KnownFactorsPerCellOnANonDivisibleImage) {
    const ImageF a = knownImageA(), b = knownImageB();
    const metrics::RegionRatios r = metrics::regionRatios(a, b, 3, 3);
    ASSERT_EQ(r.columns, 3);
    ASSERT_EQ(r.rows, 3);
    ASSERT_EQ(r.cells.size(), 9u);
    const int xs[4] = {0, 3, 6, 10}, ys[4] = {0, 2, 4, 7};
    double shares = 0.0;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            const metrics::RegionCell& cell = r.cell(column, row);
            SCOPED_TRACE(concat("column ", column, ", row ", row));
            EXPECT_EQ(cell.column, column);
            EXPECT_EQ(cell.row, row);
            EXPECT_EQ(cell.x0, xs[column]);
            EXPECT_EQ(cell.x1, xs[column + 1]);
            EXPECT_EQ(cell.y0, ys[row]);
            EXPECT_EQ(cell.y1, ys[row + 1]);
            EXPECT_EQ(cell.pixels, std::size_t((xs[column + 1] - xs[column]) * (ys[row + 1] - ys[row])));
            EXPECT_NEAR(cell.meanA, meanOver(a, cell.x0, cell.x1, cell.y0, cell.y1), 1e-12);
            EXPECT_NEAR(cell.meanB, meanOver(b, cell.x0, cell.x1, cell.y0, cell.y1), 1e-12);
            shares += cell.share;
            if (column == 2 && row == 0) {
                EXPECT_FALSE(cell.ratio) << "a black reference has no ratio";
                EXPECT_EQ(cell.meanB, 0.0);
                EXPECT_EQ(cell.share, 0.0);
                EXPECT_FALSE(cell.significant);
                continue;
            }
            ASSERT_TRUE(cell.ratio);
            EXPECT_EQ(*cell.ratio, kFactor[row][column]);
            EXPECT_EQ(cell.significant, !(column == 2 && row == 2));
        }
    std::size_t pixels = 0;
    for (const auto& cell : r.cells) pixels += cell.pixels;
    EXPECT_EQ(pixels, std::size_t(kWidth * kHeight)) << "the cells cover every pixel exactly once";
    EXPECT_NEAR(shares, 1.0, 1e-12);
    EXPECT_NEAR(r.meanB, meanOver(b, 0, kWidth, 0, kHeight), 1e-12);
    EXPECT_NEAR(r.meanA, meanOver(a, 0, kWidth, 0, kHeight), 1e-12);
    // The dark cell's 16× is left out: it holds almost none of the reference's light.
    ASSERT_TRUE(r.minRatioSignificant && r.maxRatioSignificant);
    EXPECT_EQ(*r.minRatioSignificant, 0.25);
    EXPECT_EQ(*r.maxRatioSignificant, 4.0);
}

TEST(RegionRatio, OneCellIsTheWholeImageAndEveryPixelCanBeACell) {
    const ImageF a = knownImageA(), b = knownImageB();
    const metrics::RegionRatios whole = metrics::regionRatios(a, b, 1, 1);
    ASSERT_EQ(whole.cells.size(), 1u);
    EXPECT_EQ(whole.cells[0].pixels, std::size_t(kWidth * kHeight));
    EXPECT_NEAR(*whole.cells[0].ratio, whole.meanA / whole.meanB, 1e-15);
    EXPECT_NEAR(whole.cells[0].share, 1.0, 1e-15);

    const metrics::RegionRatios pixels = metrics::regionRatios(a, b, kWidth, kHeight);
    for (const auto& cell : pixels.cells) {
        EXPECT_EQ(cell.pixels, 1u);
        EXPECT_EQ(cell.x0, cell.column);
        EXPECT_EQ(cell.y0, cell.row);
    }
}

TEST(RegionRatio, MaskKeepsOnlyCountedPixels) {
    ImageF a = knownImageA();
    const ImageF b = knownImageB();
    // Column 0 of cell (0, 0) is far too bright, but masked out; cell (1, 1) is masked out entirely.
    for (int y = 0; y < 2; ++y)
        for (int c = 0; c < 3; ++c) a.at(0, y)[c] = 100.0f;
    metrics::PixelMask mask = metrics::allPixels(kWidth, kHeight);
    const auto drop = [&](int x, int y) {
        mask.counts[std::size_t(y) * kWidth + x] = 0;
        --mask.countedPixels;
    };
    for (int y = 0; y < 2; ++y) drop(0, y);
    for (int y = 2; y < 4; ++y)
        for (int x = 3; x < 6; ++x) drop(x, y);

    const metrics::RegionRatios r = metrics::regionRatios(a, b, 3, 3, &mask);
    const metrics::RegionCell& partial = r.cell(0, 0);
    EXPECT_EQ(partial.pixels, 4u);
    EXPECT_EQ(*partial.ratio, 0.5);
    EXPECT_NEAR(partial.meanB, meanOver(b, 1, 3, 0, 2), 1e-12);
    const metrics::RegionCell& empty = r.cell(1, 1);
    EXPECT_EQ(empty.pixels, 0u);
    EXPECT_FALSE(empty.ratio);
    EXPECT_FALSE(empty.significant);
    EXPECT_EQ(empty.meanA, 0.0);
    EXPECT_EQ(empty.meanB, 0.0);
    EXPECT_EQ(*r.minRatioSignificant, 0.5) << "the masked-out 0.25 cell no longer counts";
    EXPECT_EQ(*r.maxRatioSignificant, 4.0);

    const metrics::RegionRatios unmasked = metrics::regionRatios(a, b, 3, 3);
    EXPECT_GT(*unmasked.cell(0, 0).ratio, 10.0) << "without the mask the bright column counts";
}

TEST(RegionRatio, BadGridsSizesAndValuesAreRefused) {
    const ImageF a = knownImageA(), b = knownImageB();
    EXPECT_THROW(metrics::regionRatios(a, b, 0, 3), Error);
    EXPECT_THROW(metrics::regionRatios(a, b, 3, 0), Error);
    EXPECT_THROW(metrics::regionRatios(a, b, 65, 1), Error);
    EXPECT_THROW(metrics::regionRatios(a, b, kWidth + 1, 1), Error);
    EXPECT_THROW(metrics::regionRatios(a, b, 1, kHeight + 1), Error);
    EXPECT_THROW(metrics::regionRatios(a, greyImage(kWidth + 1, kHeight, referenceValue), 3, 3), Error);
    const metrics::PixelMask wrongMask = metrics::allPixels(4, 4);
    EXPECT_THROW(metrics::regionRatios(a, b, 3, 3, &wrongMask), Error);
    ImageF nan = a;
    nan.at(1, 1)[0] = std::nanf("");
    EXPECT_THROW(metrics::regionRatios(nan, b, 3, 3), Error);
    try {
        metrics::regionRatios(a, b, kWidth + 1, 1);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("10x7"), std::string::npos) << e.what();
    }
}

// Left third 4× the reference (saturated red at 2 stops), middle equal (white), right third a
// quarter (saturated blue); the bottom row black in both (grey); 2× is half-way to red.
TEST(RegionRatio, RatioImageColoursFollowTheLogScale) {
    const int w = 12, h = 4;
    const ImageF b = greyImage(w, h, [](int, int y) { return y == 3 ? 0.0f : 0.5f; });
    const ImageF a = greyImage(w, h, [](int x, int y) {
        if (y == 3) return 0.0f;
        if (y == 2 && x < 4) return 1.0f;  // 2×
        return x < 4 ? 2.0f : x < 8 ? 0.5f : 0.125f;
    });
    const auto all = metrics::allPixels(w, h);
    const Image8 image = metrics::ratioImage(a, b, all, 2.0);
    const auto expectColour = [&](int x, int y, int r, int g, int bl) {
        const std::uint8_t* p = image.at(x, y);
        EXPECT_EQ(int(p[0]), r) << x << "," << y;
        EXPECT_EQ(int(p[1]), g) << x << "," << y;
        EXPECT_EQ(int(p[2]), bl) << x << "," << y;
        EXPECT_EQ(int(p[3]), 255) << x << "," << y;
    };
    expectColour(1, 0, 180, 4, 38);
    expectColour(5, 1, 255, 255, 255);
    expectColour(10, 0, 59, 76, 192);
    expectColour(6, 3, 128, 128, 128);
    expectColour(1, 2, 218, 130, 147);  // half-way from white to (180, 4, 38)
    // A one-stop scale saturates the 2× pixel; the mask blacks out what it leaves out.
    EXPECT_EQ(int(metrics::ratioImage(a, b, all, 1.0).at(1, 2)[0]), 180);
    auto mask = all;
    mask.counts[0] = 0;
    --mask.countedPixels;
    EXPECT_EQ(int(metrics::ratioImage(a, b, mask, 2.0).at(0, 0)[0]), 0);
    EXPECT_THROW(metrics::ratioImage(a, b, all, 0.0), Error);
    EXPECT_EQ(metrics::ratioImageLegend(2.0),
              "blue = A darker, red = A brighter, white = equal, full colour at 4x (2 stops), grey = both dark, "
              "black = outside the mask");
}

TEST(RegionRatio, CompareRegionsJsonAndTable) {
    const auto dir = test::testDir();
    writeKnownPair(dir);
    const auto result = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm") +
                                     " --regions 3x3 --json " + path(dir / "m.json"));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream file(dir / "m.json");
    const nlohmann::json j = nlohmann::json::parse(file);
    const auto& regions = j.at("regions");
    EXPECT_EQ(regions.at("columns"), 3);
    EXPECT_EQ(regions.at("rows"), 3);
    EXPECT_EQ(regions.at("min_ratio_significant").get<double>(), 0.25);
    EXPECT_EQ(regions.at("max_ratio_significant").get<double>(), 4.0);
    ASSERT_EQ(regions.at("cells").size(), 9u);
    const metrics::RegionRatios expected = metrics::regionRatios(knownImageA(), knownImageB(), 3, 3);
    for (const auto& cell : regions.at("cells")) {
        const int column = cell.at("column"), row = cell.at("row");
        const metrics::RegionCell& want = expected.cell(column, row);
        SCOPED_TRACE(concat("column ", column, ", row ", row));
        EXPECT_EQ(cell.at("pixels").get<std::size_t>(), want.pixels);
        EXPECT_DOUBLE_EQ(cell.at("mean_a").get<double>(), want.meanA);
        EXPECT_DOUBLE_EQ(cell.at("mean_b").get<double>(), want.meanB);
        if (column == 2 && row == 0) EXPECT_TRUE(cell.at("ratio").is_null());
        else EXPECT_EQ(cell.at("ratio").get<double>(), kFactor[row][column]);
    }
    // The table: rows top to bottom, '-' for the black-reference cell, brackets for the dark one.
    EXPECT_NE(result.output.find("regions 3x3"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("0.500      1.000          -"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("(16.000)"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("min 0.250 (column 1, row 1), max 4.000 (column 2, row 1)"), std::string::npos)
        << result.output;
}

TEST(RegionRatio, CompareRegionsHonoursTheMask) {
    const auto dir = test::testDir();
    writeKnownPair(dir);
    // Everything but the middle cell.
    writeHdrImage(dir / "mask.pfm", greyImage(kWidth, kHeight, [](int x, int y) {
                      return cellColumn(x) == 1 && cellRow(y) == 1 ? 0.0f : 1.0f;
                  }));
    const auto result = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm") + " --regions 3x3" +
                                     " --mask " + path(dir / "mask.pfm") + " --json " + path(dir / "m.json"));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream file(dir / "m.json");
    const nlohmann::json j = nlohmann::json::parse(file);
    const auto& middle = j.at("regions").at("cells").at(4);
    EXPECT_EQ(middle.at("column"), 1);
    EXPECT_EQ(middle.at("row"), 1);
    EXPECT_EQ(middle.at("pixels"), 0);
    EXPECT_TRUE(middle.at("ratio").is_null());
    EXPECT_EQ(j.at("regions").at("min_ratio_significant").get<double>(), 0.5);
}

TEST(RegionRatio, CompareRefusesMalformedGridsWithAClearMessage) {
    const auto dir = test::testDir();
    writeKnownPair(dir);
    const std::string ab = path(dir / "a.pfm") + " " + path(dir / "b.pfm");
    for (const char* grid : {"0x3", "3x", "abc", "x3", "3x3x3", "65x1", "3x0", "3 x3", "1.5x2", "''"}) {
        const auto result = test::runVct("compare " + ab + " --regions '" + grid + "'");
        EXPECT_NE(result.exitCode, 0) << grid << "\n" << result.output;
        EXPECT_NE(result.output.find("--regions must be COLUMNSxROWS"), std::string::npos)
            << grid << ": " << result.output;
    }
    const auto tooMany = test::runVct("compare " + ab + " --regions 11x3");
    EXPECT_NE(tooMany.exitCode, 0);
    EXPECT_NE(tooMany.output.find("at least one pixel per cell"), std::string::npos) << tooMany.output;
    EXPECT_EQ(tooMany.output.find("rmse"), std::string::npos) << "metrics printed before the error:\n" << tooMany.output;
    const auto badStops = test::runVct("compare " + ab + " --ratio-image " + path(dir / "r.png") + " --ratio-stops 0");
    EXPECT_NE(badStops.exitCode, 0);
    EXPECT_NE(badStops.output.find("--ratio-stops"), std::string::npos) << badStops.output;
}

TEST(RegionRatio, CompareWritesTheRatioImage) {
    const auto dir = test::testDir();
    writeKnownPair(dir);
    const auto result = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm") + " --ratio-image " +
                                     path(dir / "r.png"));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("full colour at 4x (2 stops)"), std::string::npos) << result.output;
    const Image8 image = readPng(dir / "r.png");
    ASSERT_EQ(image.width, kWidth);
    ASSERT_EQ(image.height, kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double factor = kFactor[cellRow(y)][cellColumn(x)];
            const std::uint8_t* p = image.at(x, y);
            SCOPED_TRACE(concat("pixel ", x, ",", y, ": ", int(p[0]), " ", int(p[1]), " ", int(p[2])));
            if (cellColumn(x) == 2 && cellRow(y) == 0) {  // black reference, lit A: as bright as it gets
                EXPECT_EQ(int(p[0]), 180);
                EXPECT_EQ(int(p[2]), 38);
            } else if (factor > 1.0) {
                EXPECT_GT(p[0], p[2]) << "red where A is brighter";
            } else if (factor < 1.0) {
                EXPECT_LT(p[0], p[2]) << "blue where A is darker";
            } else {
                EXPECT_EQ(int(p[0]) + int(p[1]) + int(p[2]), 3 * 255) << "white where equal";
            }
        }
    const auto oneStop = test::runVct("compare " + path(dir / "a.pfm") + " " + path(dir / "b.pfm") +
                                      " --ratio-image " + path(dir / "r1.png") + " --ratio-stops 1");
    ASSERT_EQ(oneStop.exitCode, 0) << oneStop.output;
    EXPECT_NE(oneStop.output.find("full colour at 2x (1 stop)"), std::string::npos) << oneStop.output;
}

// The benchmark report: the default point's table in the markdown, its numbers in the CSV.
TEST(RegionRatio, BenchReportShowsTheDefaultPointsRegions) {
    const auto dir = test::testDir();
    bench::BenchRow def;
    def.kind = "engine";
    def.label = "default";
    def.isDefault = true;
    def.frameMs = 10.0;
    def.frameStaticMs = 5.0;
    def.error.rmse = 0.1;
    def.indirectRegions = metrics::regionRatios(knownImageA(), knownImageB(), 3, 3);
    bench::BenchRow other = def;
    other.label = "cones=1";
    other.isDefault = false;
    other.indirectRegions.reset();
    const std::vector<bench::BenchRow> rows = {def, other};
    bench::BenchSummary summary;
    summary.scene = "synthetic";
    bench::writeMarkdown(dir / "r.md", rows, summary, "");
    bench::writeCsv(dir / "r.csv", rows);

    std::ifstream md(dir / "r.md");
    const std::string report((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    EXPECT_NE(report.find("## Indirect light per region (default point)"), std::string::npos) << report;
    EXPECT_NE(report.find("| row 0 | 0.500× ("), std::string::npos) << report;
    EXPECT_NE(report.find("| - |"), std::string::npos) << report;
    EXPECT_NE(report.find("*16.000×*"), std::string::npos) << report;
    EXPECT_NE(report.find("runs from 0.250 to 4.000"), std::string::npos) << report;

    std::ifstream csv(dir / "r.csv");
    std::string header, defaultLine, otherLine;
    std::getline(csv, header);
    std::getline(csv, defaultLine);
    std::getline(csv, otherLine);
    EXPECT_NE(header.find(",indirect_region_ratio_min,indirect_region_ratio_max,indirect_region_ratios"),
              std::string::npos)
        << header;
    EXPECT_NE(defaultLine.find(",0.25,4,0.5;1;;2;0.25;4;1;0.5;16"), std::string::npos) << defaultLine;
    EXPECT_NE(otherLine.find(",,,"), std::string::npos) << otherLine;
}
