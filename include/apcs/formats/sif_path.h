#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/dat_file.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// Which plane the document's 2-D vector (u, v) is read into (SPEC §7.5), the plane the view looks
// at: top (u, v, 0), front (0, u, v), side (u, 0, v).
enum class SifPlane { top, front, side };

// What parse_sif_path reads of a document.
struct SifReading {
    std::string param = "origin"; // --sif-param NAME: the animated vector parameter to read
    SifPlane plane = SifPlane::top;
};

// A Synfig document's animated vector as a path.
struct SifPath {
    // One open unnamed part, one DatPoint per waypoint in time order: its position, its staff
    // {tension, continuity, bias, acceleration 0}, and line = the waypoint's line in the document.
    DatFile file;
    // What was read but differs from Synfig (unequal time spacing, a temporal tension APCS
    // ignores): "FILE:LINE: message" each, for the caller to show.
    std::vector<std::string> warnings;
};

// Reads `text` (a whole Synfig document, canvas version 1.2, read from `file_name`) and returns
// the path of the first top-level layer of the root canvas whose parameter `reading.param` is an
// animated vector (SPEC §7.5). Refused with "FILE:LINE: message" (or "FILE: message" when no line
// applies): text that is not well-formed XML or whose root is not a canvas; any entity
// declaration (nothing is expanded or loaded); no such layer; the parameter animated with another
// type, or found only in a nested canvas; a waypoint whose value is not a literal vector; an
// interpolation other than TCB ("auto") between the first and last waypoints; two waypoints at one
// time; fewer than 2 or more than max_dat_points waypoints; a number not finite or over
// max_dat_magnitude; tension, continuity or bias outside [-1, 1]; a time Synfig writes in a form
// APCS does not read (SOT, EOT, hh:mm:ss). The text is streamed through expat in chunks: time and
// memory grow linearly with it, and only the chosen parameter's waypoints are kept.
// Elements nested deeper are refused: expat would hold them all (a Synfig document nests a few dozen).
inline constexpr std::size_t most_nested_elements = 1000;

// Whether `name` is a Synfig document by its extension (.sif, in any case).
bool is_sif_name(std::string_view name);

// The plane a view looks at (SPEC §7.5): front or side for those named views' angles, else top
// (the plane of 2-D data, and of any other view: its depth is not in a Synfig document).
SifPlane sif_plane_of(double theta_degrees, double phi_degrees);

Expected<SifPath> parse_sif_path(std::string_view text, const std::string& file_name, const SifReading& reading);

} // namespace apcs
