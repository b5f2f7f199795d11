#include "draw_command.h"

#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/raster/painter.h"
#include "apcs/screens/frames_overlay.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/world_drawing.h"

namespace apcs {

std::string overlay_legend(std::span<const NamedGraphic> graphics)
{
    if (graphics.empty())
        return {};
    const std::string between = graphics.size() > 3    ? std::to_string(graphics.size() - 2) + " between"
                                : graphics.size() == 3 ? graphics[1].name
                                                       : std::string();
    return overlay_legend({graphics.front().name, graphics.back().name, between}, graphics.size());
}

GraphicsScreen draw_graphics_overlay(std::span<const NamedGraphic> graphics, ViewAngles angles)
{
    ViewScene scene;
    for (const NamedGraphic& named : graphics)
        scene.add(named.graphic.polylines(named.graphic.all_points()));
    const ViewTransform view = scene.fit(angles, layout::view_area);
    GraphicsScreen screen;
    Painter painter(screen.bitmap);
    painter.record_into(screen.strokes).rectangle(layout::drawing_area);
    Painter inside(screen.bitmap, layout::inside_boundary);
    inside.record_into(screen.strokes);
    for (std::size_t k = 0; k < graphics.size(); ++k) {
        const Graphic& graphic = graphics[k].graphic;
        draw_world_graphic(inside, graphic, graphic.all_points(), view, overlay_style(k, graphics.size()));
    }
    screen.text.push_back({1, layout::message_row, overlay_legend(graphics)});
    return screen;
}

ExitStatus run_draw_command(std::span<const std::filesystem::path> files, const CommonOptions& options,
                            std::ostream& out, std::ostream& err)
{
    std::vector<NamedGraphic> graphics;
    for (const std::filesystem::path& file : files) {
        Expected<Graphic> graphic = read_key_frame(file);
        if (!graphic)
            return report_bad_input(graphic.error(), err);
        const std::string name = file == standard_stream_name ? "standard input" : file.filename().string();
        graphics.push_back({name, std::move(*graphic)});
    }
    if (Expected<void> done = write_pictures(draw_graphics_overlay(graphics, options.view), options, out); !done)
        return report_bad_input(done.error(), err);
    return ExitStatus::success;
}

} // namespace apcs
