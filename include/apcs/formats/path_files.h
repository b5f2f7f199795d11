#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/base/diagnostic.h"
#include "apcs/formats/dat_file.h"

#include <filesystem>
#include <span>
#include <string_view>
#include <string>
#include <utility>
#include <vector>

namespace apcs {

// The name of graphic point K's path file (K from 1): "ani1.dat", "ani2.dat", …
std::string path_file_name(std::size_t point_number);

// A file to be written: its name in the session's folder and its whole content.
struct NamedText {
    std::string name;
    std::string content;
};

// The thesis' split.c (SPEC §5.2) writes one path file per graphic point, aniK.dat holding KEY1
// point K and KEY2 point K (the keys equalised, so their counts are equal): path file
// `point_number` (from 1) from its point in KEY1 and in KEY2, made one at a time, so that a split
// of 10^6 points never holds all its files' text in memory.
NamedText split_path_file(std::size_t point_number, const Vec3& key1_point, const Vec3& key2_point);

// "inb001.dat" … (three digits at least, more when there are over 999 in-betweens).
std::string inbetween_file_name(std::size_t number);

// How many in-between files a frame sequence gives: every frame but the first and the last.
std::size_t inbetween_count(const FrameSequence& frames);

// The decimals of in-between files: decimals_for_size of the largest absolute coordinate of the
// key frames (the first and the last frame), so that every number reads back within 0.5e-9 of
// the keys' size.
int inbetween_decimals(std::span<const Vec3> key1, std::span<const Vec3> key2);
int inbetween_decimals(const FrameSequence& frames);

// The first line of in-between file `number` of `count`: "; APCS in-between 3 of 12".
std::string inbetween_heading(std::size_t number, std::size_t count);

// In-between file `number` (1 … inbetween_count): frame `number`, the whole graphic with the
// parts of `structure`, headed by "; APCS in-between k of M", its numbers with
// inbetween_decimals. Made one at a time, so that only one file's text is ever in memory.
NamedText inbetween_file(const FrameSequence& frames, const Graphic& structure, std::size_t number);

// A path file for graphic point `which` ("first" or "last") must start at its KEY1 position and
// end at its KEY2 position (to 1e-6 of the scene's size). Else the problem, as "FILE:LINE: …"
// naming the expected point.
Expected<void> check_path_ends(const DatFile& path, const std::string& file_name, const std::string& which,
                               const Vec3& key1_position, const Vec3& key2_position);

// A path file's points as KB control points, all parts in file order: 7-column points keep their
// own t c b a, shorter ones take `defaults`.
ControlPoints control_points_from(const DatFile& file, const StaffValues& defaults);

// The two graphic points that carry a path file: the very first and the very last of each key.
enum class PathEnd { first, last };

// The path-file step of key → path → fit: checks that `file` (named `file_name` in messages) runs
// from the KEY1 to the KEY2 position of graphic point `end` (check_path_ends, "first" or "last"),
// then gives its control points (control_points_from with `defaults`).
[[nodiscard]] Expected<ControlPoints> point_path_from(const DatFile& file, const std::string& file_name, PathEnd end,
                                                      const EqualisedKeys& keys, const StaffValues& defaults);

// A path file's control points with their staff values, as written back after adjusting (all
// seven columns).
DatFile dat_from(const ControlPoints& points);

// A path file rewritten after adjusting: `original_text` (parsed as `original`) with its point
// lines replaced by `points` in seven columns; every other line (comments, blank lines, PART
// lines) stays where it was among the points. `origins` runs parallel to `points`: each point's
// index among the original's points, or new_point (waypoint_change.h) for an inserted one, which
// gets a line of its own after the point before it. The comments before a deleted point stay,
// before the next point kept. CRLF line ends stay CRLF. With `slopes`, a `SLOPES S0 S1` line goes
// just before the first point and any SLOPES line of the original goes (SPEC §2.1).
std::string format_path_file(std::string_view original_text, const DatFile& original, const ControlPoints& points,
                             std::span<const std::size_t> origins, std::optional<EndSlopes> slopes = std::nullopt);

// "(x, y, z)" for messages, each number with `digits` significant digits (significant_number):
// "(0, 0.3, 0)", not (0, 0.30000000000000004, 0).
std::string describe_point(const Vec3& point, int digits = 6);

// Two points a message compares (a path's end and the key point it should be at): describe_point's
// six digits, more when six would show two different points alike.
std::pair<std::string, std::string> describe_points(const Vec3& a, const Vec3& b);

} // namespace apcs
