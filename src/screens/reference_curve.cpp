#include "apcs/screens/reference_curve.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/geometry/hercules.h"
#include "apcs/raster/screen_layout.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

namespace apcs {

namespace {

// The label must leave the boundary's top edge room for a replay's badge on its right.
constexpr std::size_t longest_label = 40;
constexpr int label_column = 2;

std::string values_named(const StaffValues& staff, bool short_names)
{
    std::string text;
    for (const StaffLine line : staff_lines) {
        const double value = staff[line];
        if (format_staff_value(value) == format_staff_value(0.0))
            continue;
        const std::string name = ascii_lower_case(staff_line_name(line));
        text += (text.empty() ? "" : "  ") + (short_names ? name.substr(0, 1) : name) + " " + format_staff_value(value);
    }
    return text;
}

// The 80x24 text cells a bitmap lights inside the boundary.
using CellsLit = std::array<std::array<bool, hercules::text_columns>, hercules::text_rows>;

CellsLit cells_lit(const Bitmap& bitmap)
{
    CellsLit lit{};
    const PixelRect& inside = layout::inside_boundary;
    for (int y = inside.top; y < inside.bottom; ++y)
        for (int x = inside.left; x < inside.right; ++x)
            if (bitmap.get(x, y))
                lit[static_cast<std::size_t>(y * hercules::text_rows / hercules::screen_height)]
                   [static_cast<std::size_t>(x / hercules::cell_width)] = true;
    return lit;
}

bool lit_near(const CellsLit& lit, int row, int column)
{
    for (int r = std::max(row - 1, 0); r <= std::min(row + 1, hercules::text_rows - 1); ++r)
        for (int c = std::max(column - 1, 0); c <= std::min(column + 1, hercules::text_columns - 1); ++c)
            if (lit[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)])
                return true;
    return false;
}

// The cell for the letter: among the reference's cells a cell or more from the live curve (inside
// the boundary's frame), the one nearest their middle; none where the two curves run together.
std::optional<std::array<int, 2>> letter_cell(const Bitmap& reference, const Bitmap& curve)
{
    const CellsLit reference_cells = cells_lit(reference);
    const CellsLit curve_cells = cells_lit(curve);
    std::vector<std::array<int, 2>> apart;
    for (int row = 1; row < layout::message_row - 1; ++row)
        for (int column = 1; column < hercules::text_columns - 1; ++column)
            if (reference_cells[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] &&
                !lit_near(curve_cells, row, column))
                apart.push_back({row, column});
    if (apart.empty())
        return std::nullopt;
    double row_sum = 0.0;
    double column_sum = 0.0;
    for (const auto& [row, column] : apart) {
        row_sum += row;
        column_sum += column;
    }
    const double mid_row = row_sum / static_cast<double>(apart.size());
    const double mid_column = column_sum / static_cast<double>(apart.size());
    // A text cell is about 1.6 times as tall as it is wide.
    const auto far = [&](const std::array<int, 2>& cell) {
        const double down = (cell[0] - mid_row) * 1.6;
        const double across = cell[1] - mid_column;
        return down * down + across * across;
    };
    return *std::min_element(apart.begin(), apart.end(),
                             [&](const auto& a, const auto& b) { return far(a) < far(b); });
}

} // namespace

std::string reference_label(const StaffValues& staff)
{
    std::string values = values_named(staff, false);
    if ((values.size() + 3) > longest_label)
        values = values_named(staff, true);
    return "A: " + (values.empty() ? std::string("tension, continuity, bias 0") : values);
}

void draw_reference(GraphicsScreen& screen, const Bitmap& reference, const Bitmap& curve, std::string_view label)
{
    Bitmap dashed;
    const PixelRect& inside = layout::inside_boundary;
    for (int y = inside.top; y < inside.bottom; ++y)
        for (int x = inside.left; x < inside.right; ++x)
            if ((x + 2 * y) % 36 < 27 && reference.get(x, y))
                dashed.set(x, y, true);
    paint_layer(screen, dashed, ColourRole::reference);
    if (const auto cell = letter_cell(reference, curve))
        screen.text.push_back({(*cell)[1], (*cell)[0], "A", CellStyle::bold, ColourRole::reference});
    screen.text.push_back({label_column, 0, " " + std::string(label) + " ", CellStyle::plain, ColourRole::reference});
}

} // namespace apcs
