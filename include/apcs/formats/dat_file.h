#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/graphic.h"
#include "apcs/base/diagnostic.h"
#include "apcs/formats/text_lines.h"
#include "apcs/geometry/vec3.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// One point line of a .dat file: 2 or 3 numbers, or 7 with the staff values of a path file.
struct DatPoint {
    Vec3 position;
    std::optional<StaffValues> staff;
    int line = 0; // source line, for messages about this point
};

struct DatPart {
    std::string name;
    // Closed when marked CLOSED or when the first point equals the last.
    Closure closure = Closure::open;
    std::vector<DatPoint> points;
};

// The text format of SPEC §2.1, shared by key, path (ani) and in-between files.
struct DatFile {
    std::vector<DatPart> parts;
    // A path file's `SLOPES S0 S1` line (SPEC §2.1): the end slopes it was adjusted with.
    std::optional<EndSlopes> slopes;

    std::size_t point_count() const;
};

// Limits of SPEC §2.1, checked while reading, before memory for the points is reserved.
inline constexpr std::size_t max_dat_points = 1'000'000;
inline constexpr std::size_t max_dat_line_bytes = max_text_line_bytes;
inline constexpr double max_dat_magnitude = 1e9;

// Parses `text` (the whole file) read from `file_name`. Accepts CRLF, a trailing Ctrl-Z, a UTF-8
// byte-order mark, tabs and exponents; rejects everything else SPEC §2.1 lists with
// "FILE:LINE: what was expected". `minimum_points` is checked over the whole file.
// A text of a megabyte or more is read in halves (DatReading::in_halves).
Expected<DatFile> parse_dat(std::string_view text, const std::string& file_name, std::size_t minimum_points = 2);

// How parse_dat reads: line after line, or the text's two halves (split after the first line end
// past its middle) scanned on both cores, each half's point lines read there and every other line
// (a count, PART or SLOPES line, a line at fault) read after, in order, so that the file, its
// points' lines and the first problem are those read in order gives. A text with a Ctrl-Z, or
// without a line end past its middle, is read in order.
enum class DatReading { in_order, in_halves };
Expected<DatFile> parse_dat(std::string_view text, const std::string& file_name, std::size_t minimum_points,
                            DatReading reading);

// Formats a .dat file: one PART line per part when there is more than one part or a part is named
// or closed, each point with the shortest decimal form that reads back exactly. Points with staff
// values get all seven columns.
std::string format_dat(const DatFile& file);

// "PART name OPEN|CLOSED" as format_dat and format_graphic write part `index` (0 for the first),
// without its line end: an unnamed part is called P1, P2, ...; blanks and comment characters in a
// name become '_' so that it reads back as one field. A writer checks its size against
// max_dat_line_bytes, since a longer line would not read back.
std::string part_line(const std::string& part_name, Closure closure, std::size_t index);

// "SLOPES S0 S1" with the shortest exact numbers, without its line end (SPEC §2.1).
std::string slopes_line(const EndSlopes& slopes);

// One point line as format_dat writes it (three columns, or seven with staff values), without
// its line end.
void append_point_line(std::string& text, const Vec3& position, const std::optional<StaffValues>& staff);

// A graphic with the parts of `structure` and the point sequence `points` (as many as the parts
// hold), formatted like format_dat, or with `decimals` fixed decimals (append_fixed); no copy of
// the points is made.
std::string format_graphic(const Graphic& structure, std::span<const Vec3> points, int decimals = -1);

// Fills `out` with points first … first + out.size() − 1 of a graphic's point sequence.
using GraphicPoints = std::function<void(std::size_t first, std::span<Vec3> out)>;

// format_graphic for points made on demand: the text goes to `sink` in chunks of some thousand
// points, the points asked of `points_at` a chunk at a time, so neither the points nor the text
// is ever whole in memory. False when the sink said false (and nothing more was made).
bool format_graphic_in_chunks(const Graphic& structure, std::size_t point_count, const GraphicPoints& points_at,
                              int decimals, const std::function<bool(std::string_view)>& sink);

// The key-frame model of a file (staff columns are dropped).
Graphic graphic_from(const DatFile& file);

// parse_dat's checks and messages, straight into the key-frame model: only the positions are
// kept (staff columns are checked, then dropped), so a large key frame costs 24 bytes a point
// while it is read, not a DatPoint's 72 and then a copy.
Expected<Graphic> parse_key_frame(std::string_view text, const std::string& file_name, std::size_t minimum_points = 2);

// A piece of text for a reader that takes text as it comes, and what hands the pieces over: it
// calls the sink with each piece in order and returns the first problem, its own or the sink's.
using TextPieceSink = std::function<Expected<void>(std::string_view piece)>;
using TextPieces = std::function<Expected<void>(const TextPieceSink& sink)>;

// parse_key_frame for text that comes in pieces (a file read a block at a time), never whole;
// `line_count` (the text's LFs + 1) sizes the points once.
Expected<Graphic> parse_key_frame_pieces(const std::string& file_name, std::size_t line_count, const TextPieces& read,
                                         std::size_t minimum_points = 2);

} // namespace apcs
