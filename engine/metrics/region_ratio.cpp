#include "metrics/region_ratio.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "metrics/image_metrics.hpp"

namespace vct::metrics {
namespace {

void checkGrid(int columns, int rows, const ImageF& image) {
    if (columns < 1 || columns > kMaxRegionCells || rows < 1 || rows > kMaxRegionCells)
        fail("a region grid of ", columns, "x", rows, " cells is outside 1..", kMaxRegionCells,
             " per side; ask for e.g. 3x3");
    if (columns > image.width || rows > image.height)
        fail("a region grid of ", columns, "x", rows, " cells needs at least one pixel per cell, but the image is ",
             image.width, "x", image.height, "; ask for fewer cells");
}

}  // namespace

RegionRatios regionRatios(const ImageF& a, const ImageF& b, int columns, int rows, const PixelMask* mask) {
    checkSameSize(a, b, "A", "B");
    checkGrid(columns, rows, a);
    if (mask && (mask->width != a.width || mask->height != a.height))
        fail("the mask is ", mask->width, "x", mask->height, " but the images are ", a.width, "x", a.height,
             "; use a mask of the same size");
    checkFinite(a, "image A");
    checkFinite(b, "image B");

    RegionRatios result;
    result.columns = columns;
    result.rows = rows;
    std::vector<double> sumsB;
    double totalA = 0.0, totalB = 0.0;
    std::size_t totalPixels = 0;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            RegionCell cell;
            cell.column = column;
            cell.row = row;
            cell.x0 = column * a.width / columns;
            cell.x1 = (column + 1) * a.width / columns;
            cell.y0 = row * a.height / rows;
            cell.y1 = (row + 1) * a.height / rows;
            double sumA = 0.0, sumB = 0.0;
            for (int y = cell.y0; y < cell.y1; ++y)
                for (int x = cell.x0; x < cell.x1; ++x) {
                    if (mask && !(*mask)(x, y)) continue;
                    sumA += luminance(a.at(x, y));
                    sumB += luminance(b.at(x, y));
                    ++cell.pixels;
                }
            if (cell.pixels > 0) {
                cell.meanA = sumA / double(cell.pixels);
                cell.meanB = sumB / double(cell.pixels);
                if (cell.meanB > 0.0) cell.ratio = cell.meanA / cell.meanB;
            }
            totalA += sumA;
            totalB += sumB;
            totalPixels += cell.pixels;
            sumsB.push_back(sumB);
            result.cells.push_back(cell);
        }
    if (totalPixels > 0) {
        result.meanA = totalA / double(totalPixels);
        result.meanB = totalB / double(totalPixels);
    }
    for (std::size_t i = 0; i < result.cells.size(); ++i) {
        RegionCell& cell = result.cells[i];
        if (totalB > 0.0) cell.share = sumsB[i] / totalB;
        cell.significant =
            result.meanB > 0.0 && cell.pixels > 0 && cell.meanB > kSignificantCellFraction * result.meanB;
        if (!cell.significant || !cell.ratio) continue;
        const double ratio = *cell.ratio;
        result.minRatioSignificant = std::min(result.minRatioSignificant.value_or(ratio), ratio);
        result.maxRatioSignificant = std::max(result.maxRatioSignificant.value_or(ratio), ratio);
    }
    return result;
}

}  // namespace vct::metrics
