#include "apcs/screens/frames_overlay.h"

#include "apcs/base/utf8.h"
#include "apcs/geometry/hercules.h"
#include "apcs/raster/painter.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/world_drawing.h"

#include <algorithm>

namespace apcs {

namespace {

// The text cell of a lettered point's label: the first row whose top is below the point's x (2
// pixels under it and more), where a thing moved along its path (drawn above it: a car on its
// road) is least often; in the point's column; kept inside the boundary's rows 1 … 17 (a fitted
// view's lowest points are a cell above the boundary) and columns 1 … 78.
TextLine label_cell(PixelPoint at, const std::string& label)
{
    int row = 1;
    while (row < layout::message_row - 1 && hercules::text_row_top(row) <= at.y + 2)
        ++row;
    const int column = std::clamp(at.x / hercules::cell_width, 1, hercules::text_columns - 2);
    return {column, row, label};
}

// The legend's parts for `count` items: "solid: FIRST", "  dashed: LAST", "  dotted: BETWEEN",
// as many as there are kinds of items.
std::vector<std::string> legend_parts(const OverlayNames& names, std::size_t count)
{
    std::vector<std::string> parts;
    if (count > 0)
        parts.push_back("solid: " + names.first);
    if (count > 1)
        parts.push_back("  dashed: " + names.last);
    if (count > 2)
        parts.push_back("  dotted: " + names.between);
    return parts;
}

// The legend on `row` from column 1, each part in the colour of the frames it names.
void put_legend(GraphicsScreen& screen, const OverlayNames& names, std::size_t count, int row)
{
    const ColourRole roles[] = {ColourRole::monitor, ColourRole::key_frame, ColourRole::inbetween};
    int column = 1;
    const std::vector<std::string> parts = legend_parts(names, count);
    for (std::size_t part = 0; part < parts.size(); ++part) {
        screen.text.push_back({column, row, parts[part], CellStyle::plain, roles[part]});
        column += text_columns(parts[part]);
    }
}

} // namespace

std::vector<std::size_t> overlaid_frames(std::size_t count, bool first_middle_last)
{
    if (first_middle_last && count > 3)
        return {0, (count - 1) / 2, count - 1};
    std::vector<std::size_t> all(count);
    for (std::size_t k = 0; k < count; ++k)
        all[k] = k;
    return all;
}

LineStyle overlay_style(std::size_t index, std::size_t count)
{
    if (index == 0)
        return LineStyle::solid;
    return index + 1 == count ? LineStyle::dashed : LineStyle::dotted;
}

ColourRole overlay_role(std::size_t index, std::size_t count)
{
    if (index == 0)
        return ColourRole::monitor;
    return index + 1 == count ? ColourRole::key_frame : ColourRole::inbetween;
}

std::string overlay_legend(const OverlayNames& names, std::size_t count)
{
    std::string legend;
    for (const std::string& part : legend_parts(names, count))
        legend += part;
    return legend;
}

OverlayNames key_frames_names(const std::string& key1, const std::string& key2, std::size_t frame_count)
{
    const std::size_t inbetweens = frame_count > 2 ? frame_count - 2 : 0;
    return {"KEY1 " + key1, "KEY2 " + key2,
            std::to_string(inbetweens) + (inbetweens == 1 ? " in-between" : " in-betweens")};
}

OverlayNames scene_frames_names(std::size_t frame_count)
{
    const std::size_t last = frame_count > 0 ? frame_count - 1 : 0;
    const std::string between = last == 2 ? "frame 1" : "frames 1-" + std::to_string(last > 0 ? last - 1 : 0);
    return {"frame 0", "frame " + std::to_string(last), between};
}

ViewTransform frames_view(const FrameSequence& frames, ViewAngles angles)
{
    return ViewScene{}.add(frames).fit(angles, layout::view_area);
}

GraphicsScreen frames_overlay_screen(const FrameSequence& frames, const Graphic& structure,
                                     const ViewTransform& view, const std::string& caption,
                                     const FramesOverlay& overlay)
{
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    painter.record_into(screen.strokes).rectangle(layout::drawing_area);
    const std::size_t count = frames.frame_count();
    const std::vector<std::size_t> drawn = overlaid_frames(count, overlay.first_middle_last);
    for (const std::size_t k : drawn) {
        Bitmap layer;
        Painter frame_painter(layer, layout::inside_boundary);
        frame_painter.record_into(screen.strokes);
        draw_world_graphic(frame_painter, structure, frames.frame(k), view, overlay_style(k, count));
        paint_layer(screen, layer, overlay_role(k, count));
    }
    for (const LetteredPoint& point : overlay.points) {
        const PixelPoint at = view.to_device(point.position).rounded();
        if (!layout::inside_boundary.contains(at))
            continue;
        screen.marks.push_back({at, MarkKind::control_point});
        screen.text.push_back(label_cell(at, point.label));
    }
    screen.text.push_back({1, layout::message_row, caption});
    const bool sampled = drawn.size() < count;
    OverlayNames names = overlay.names;
    if (sampled)
        names.between = overlay.middle_name;
    put_legend(screen, names, count, overlay_legend_row);
    int row = overlay_legend_row + 1;
    if (sampled)
        screen.text.push_back({1, row++, "the first, middle and last of " + std::to_string(count) +
                                             " frames (pictures, --png, draw every frame)"});
    for (const std::string& note : overlay.notes)
        if (row < hercules::text_rows)
            screen.text.push_back({1, row++, note});
    return screen;
}

GraphicsScreen frames_overlay_screen(const FrameSequence& frames, const Graphic& structure, ViewAngles angles,
                                     const std::string& caption, const FramesOverlay& overlay)
{
    return frames_overlay_screen(frames, structure, frames_view(frames, angles), caption, overlay);
}

} // namespace apcs
