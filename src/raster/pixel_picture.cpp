#include "apcs/raster/pixel_picture.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace apcs {

namespace {

// The source pixels [first, end) under target pixel `target` when `sources` pixels are scaled to
// `targets`: a partition when the picture is reduced (each source pixel pooled into one target
// pixel, so a line does not grow thicker), one pixel each when it is enlarged (nearest neighbour).
struct SourceSpan {
    int first = 0;
    int end = 0;
};

SourceSpan source_span(int target, int targets, int sources)
{
    const long long first = static_cast<long long>(target) * sources / targets;
    const long long end = static_cast<long long>(target + 1) * sources / targets;
    return {static_cast<int>(first), static_cast<int>(std::max(end, first + 1))};
}

} // namespace

int cell_rows_above(int raster_rows, int raster_height, CellArea area)
{
    int rows = 0;
    // Cell row r begins at raster row floor(r · raster_height / area.rows) (cell_of_pixel).
    while (rows < area.rows && static_cast<long long>(rows) * raster_height / area.rows < raster_rows)
        ++rows;
    return rows;
}

std::optional<PicturePlacement> place_picture(CellArea area, int cell_rows, int raster_width, int raster_rows,
                                              CellPixels cell, std::optional<PictureLimit> limit)
{
    if (area.columns <= 0 || cell_rows <= 0 || raster_width <= 0 || raster_rows <= 0 || cell.width <= 0 ||
        cell.height <= 0)
        return std::nullopt;
    long long box_width = static_cast<long long>(area.columns) * cell.width;
    long long box_height = static_cast<long long>(cell_rows) * cell.height;
    if (limit) {
        // Whole cells within the limit, and room for a sixel band's last rows (up to 5 more).
        constexpr int sixel_slack = 5;
        box_width = std::min(box_width, static_cast<long long>(limit->width / cell.width) * cell.width);
        box_height = std::min(box_height, static_cast<long long>((limit->height - sixel_slack) / cell.height) * cell.height);
        if (box_width <= 0 || box_height <= 0)
            return std::nullopt;
    }
    // The raster is raster_width wide and raster_rows · 3/2 tall (hercules::aspect_correction):
    // the width limits the scale when box_width / raster_width <= box_height / (1.5 · raster_rows).
    const bool width_limits = box_width * raster_rows * 3 <= box_height * raster_width * 2;
    const long long content_width = width_limits ? box_width : box_height * raster_width * 2 / (3LL * raster_rows);
    const long long content_height = width_limits ? box_width * raster_rows * 3 / (2LL * raster_width) : box_height;
    PicturePlacement placement;
    placement.cell = cell;
    placement.raster_rows = raster_rows;
    placement.content_width = static_cast<int>(std::max(1LL, content_width));
    placement.content_height = static_cast<int>(std::max(1LL, content_height));
    placement.columns = cells_holding(placement.content_width, cell.width);
    placement.rows = cells_holding(placement.content_height, cell.height);
    placement.column = (area.columns - placement.columns) / 2;
    return placement;
}

Bitmap scale_to_picture(const Bitmap& raster, const PicturePlacement& placement)
{
    Bitmap picture(placement.pixel_width(), placement.pixel_height());
    const int source_rows = std::min(placement.raster_rows, raster.height());
    if (source_rows <= 0 || raster.width() <= 0)
        return picture;
    std::vector<SourceSpan> columns;
    columns.reserve(static_cast<std::size_t>(placement.content_width));
    for (int x = 0; x < placement.content_width; ++x)
        columns.push_back(source_span(x, placement.content_width, raster.width()));
    // lit_before[x]: how many of the pooled rows' columns 0 … x − 1 are lit, so that each picture
    // pixel asks its span in one subtraction.
    std::vector<int> lit_before(static_cast<std::size_t>(raster.width()) + 1);
    for (int y = 0; y < placement.content_height; ++y) {
        const SourceSpan rows = source_span(y, placement.content_height, source_rows);
        for (int x = 0; x < raster.width(); ++x) {
            bool lit = false;
            for (int row = rows.first; row < std::min(rows.end, source_rows) && !lit; ++row)
                lit = raster.get(x, row);
            lit_before[static_cast<std::size_t>(x) + 1] = lit_before[static_cast<std::size_t>(x)] + (lit ? 1 : 0);
        }
        for (int x = 0; x < placement.content_width; ++x) {
            const SourceSpan span = columns[static_cast<std::size_t>(x)];
            const int end = std::min(span.end, raster.width());
            if (lit_before[static_cast<std::size_t>(end)] > lit_before[static_cast<std::size_t>(span.first)])
                picture.set(x, y, true);
        }
    }
    return picture;
}

std::optional<CellRowBand> changed_band(const Bitmap& sent, const Bitmap& now, int cell_height)
{
    if (cell_height <= 0)
        return std::nullopt;
    if (sent.width() != now.width() || sent.height() != now.height())
        return CellRowBand{0, cells_holding(now.height(), cell_height)};
    const std::size_t row_bytes = (static_cast<std::size_t>(now.width()) + 7) / 8;
    const auto differs = [&](int y) { return std::memcmp(sent.row(y), now.row(y), row_bytes) != 0; };
    int first = 0;
    while (first < now.height() && !differs(first))
        ++first;
    if (first == now.height())
        return std::nullopt;
    int last = now.height() - 1;
    while (last > first && !differs(last))
        --last;
    return CellRowBand{first / cell_height, last / cell_height + 1};
}

} // namespace apcs
