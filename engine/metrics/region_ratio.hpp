#pragma once
// Where an image A is too dark or too bright against the reference B: the image is cut into a
// grid of C columns × R rows and each cell gets the ratio of A's to B's mean luminance (Rec. 709
// luminance of the linear radiance, as in image_metrics.hpp). A single image-wide ratio hides a
// region that is half as bright behind another that is twice as bright; the grid shows both.
//
// Cell (column i, row j) covers the pixels x in [i·W/C, (i+1)·W/C), y in [j·H/R, (j+1)·H/R)
// (integer division), so the cells tile the image exactly once whatever its size; row 0 is the
// top row as the image is seen. Only the mask's counted pixels enter a cell's means.
//
//   ratio        mean Y(a) / mean Y(b) over the cell's counted pixels; undefined when the cell
//                counts no pixel or B's mean there is ≤ 0 (an indirect part made as full − direct
//                can be slightly negative where there is no indirect light)
//   share        the cell's part of B's total luminance over the counted pixels (the shares of
//                all cells add up to 1): how much of the reference's light the cell holds
//   significant  B's mean in the cell exceeds kSignificantCellFraction × B's mean over the whole
//                image: cells that dark hold too little light for their ratio to matter, and
//                their ratio is mostly the reference's noise
#include <cstddef>
#include <optional>
#include <vector>

#include "core/image.hpp"
#include "metrics/pixel_mask.hpp"

namespace vct::metrics {

inline constexpr int kMaxRegionCells = 64;  // per side
inline constexpr double kSignificantCellFraction = 0.05;

struct RegionCell {
    int column = 0, row = 0;  // 0-based; row 0 at the top
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // pixel range [x0, x1) × [y0, y1)
    std::size_t pixels = 0;              // counted pixels
    double meanA = 0.0, meanB = 0.0;     // mean luminance over the counted pixels (0 without any)
    std::optional<double> ratio;         // meanA / meanB, absent where undefined (see above)
    double share = 0.0;                  // of B's total luminance
    bool significant = false;
};

struct RegionRatios {
    int columns = 0, rows = 0;
    std::vector<RegionCell> cells;  // row-major: cells[row * columns + column]
    double meanA = 0.0, meanB = 0.0;  // over every counted pixel of the image
    std::optional<double> minRatioSignificant, maxRatioSignificant;  // absent without a significant cell

    const RegionCell& cell(int column, int row) const { return cells[std::size_t(row) * columns + column]; }
};

// Throws vct::Error when the sizes differ, the grid is outside 1..kMaxRegionCells per side or has
// more columns (rows) than the image has pixels across (down), the mask has another size, or an
// image holds NaN/Inf values. Without a mask every pixel counts.
RegionRatios regionRatios(const ImageF& a, const ImageF& b, int columns, int rows, const PixelMask* mask = nullptr);

}  // namespace vct::metrics
