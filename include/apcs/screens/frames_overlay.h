#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/view_transform.h"
#include "apcs/geometry/vec3.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/stroke.h"

#include <cstddef>
#include <string>
#include <vector>

namespace apcs {

// The line style of item `index` of `count` overlaid in one colour: the first solid, the last
// dashed, the ones between dotted, so that where a motion starts and where it ends can be told
// apart (apcs draw, the pictures of apcs fit and apcs play, the session's last screen).
LineStyle overlay_style(std::size_t index, std::size_t count);
// Its colour role, for a terminal whose glyphs cannot draw a dash or a dot apart from a line
// (braille, blocks): the first in the monitor's colour, the last in the key frames' (cyan), the
// ones between in the in-betweens' (red); the legend's parts are in the same colours.
ColourRole overlay_role(std::size_t index, std::size_t count);

// What the strokes of an overlay stand for.
struct OverlayNames {
    std::string first;   // e.g. "KEY1 key1.dat", "frame 0"
    std::string last;    // e.g. "KEY2 key2.dat", "frame 72"
    std::string between; // e.g. "12 in-betweens", "frames 1-71"
};

// "solid: FIRST  dashed: LAST  dotted: BETWEEN" for an overlay of `count` items: only the solid
// part for one item, no dotted part for two, empty for none.
std::string overlay_legend(const OverlayNames& names, std::size_t count);

// The names of a fit's frames: KEY1 and KEY2 by their files, the in-betweens by their number.
OverlayNames key_frames_names(const std::string& key1, const std::string& key2, std::size_t frame_count);
// The names of a scene's frames 0 … frame_count − 1.
OverlayNames scene_frames_names(std::size_t frame_count);

// A point an overlay marks and letters (e.g. a car's waypoint A): an x at it, `label` in the text
// cell under it.
struct LetteredPoint {
    std::string label;
    Vec3 position; // world units
};

// What an overlay of all frames shows besides the frames: the legend's names, the lettered points
// and lines saying what the letters are (under the legend).
struct FramesOverlay {
    OverlayNames names;
    std::vector<LetteredPoint> points;
    std::vector<std::string> notes;
    // On a terminal of 80x24 cells every frame overlaid is one blob (SPEC §3.1): only the first,
    // the middle (frame (N-1)/2, named `middle_name`) and the last are drawn, and a note says so.
    // Pictures draw every frame.
    bool first_middle_last = false;
    std::string middle_name; // e.g. "in-between 6 (inb006.dat)", "frame 36"
};

// The frames an overlay of `count` frames draws: all, or the first, the middle and the last.
std::vector<std::size_t> overlaid_frames(std::size_t count, bool first_middle_last);

// The text row of an overlay's legend, under the message line; its notes follow on the rows below,
// down to the last row.
inline constexpr int overlay_legend_row = 19;

// All `frames` overlaid inside the session's drawing area through `view`, each drawn by the parts
// of `structure` in the style overlay_style gives it, the lines recorded as strokes (for SVG);
// `caption` on the message line, the legend and `overlay`'s points and notes. The last screen of
// the session and of apcs play, and the picture of apcs fit --png and apcs play --png.
GraphicsScreen frames_overlay_screen(const FrameSequence& frames, const Graphic& structure,
                                     const ViewTransform& view, const std::string& caption,
                                     const FramesOverlay& overlay);
// The same, through a view fitted to all frames from `angles`, as the player fits its own.
GraphicsScreen frames_overlay_screen(const FrameSequence& frames, const Graphic& structure, ViewAngles angles,
                                     const std::string& caption, const FramesOverlay& overlay);

// The view the player and the overlay picture fit to all frames from `angles`.
ViewTransform frames_view(const FrameSequence& frames, ViewAngles angles);

} // namespace apcs
