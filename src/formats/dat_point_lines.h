#pragma once

// What parse_dat's parser and its halves read alike (dat_file.cpp): a line's fields, a point line's
// numbers checked without the parser's state, and one half of a long text scanned on its own
// thread: its point lines read, every other line kept for the parser to read in order.
#include "apcs/base/diagnostic.h"
#include "apcs/formats/dat_file.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs::dat_lines {

// The blank-separated fields of a line: the first eight, and how many there are in all (a
// point has at most seven, so no line needs more to be judged; nothing is allocated per line).
struct Fields {
    std::array<std::string_view, 8> items;
    std::size_t count = 0;

    std::size_t size() const { return count; }
    bool empty() const { return count == 0; }
    std::string_view operator[](std::size_t i) const { return items[i]; }
};

Fields split_fields(std::string_view line);

// What is wrong with a point line, in the order the parser checks: the count of fields, then each
// field in turn (a number, finite, within max_dat_magnitude), then the staff values in turn.
enum class PointFault { none, field_count, not_a_number, not_finite, too_large, staff_outside };

struct ReadPoint {
    DatPoint point;                    // its line is not set
    PointFault fault = PointFault::none;
    std::size_t field = 0;             // the field at fault (for staff_outside: 3 to 6)
};

// A point line's numbers, read and checked as the parser checks them, whatever the lines before
// it were (the limit on the number of points is the parser's to check).
ReadPoint read_point(const Fields& fields);

// A line the parser must read itself (a count, PART or SLOPES line, a line at fault), after the
// half's first `points_before` points.
struct OtherLine {
    int line = 0; // in the half, from 1
    std::string_view content;
    std::size_t points_before = 0;
};

// One half of a text, starting at a line's start and ending after a line end, scanned alone.
struct ScannedHalf {
    std::vector<DatPoint> points; // lines numbered in the half, from 1
    std::vector<OtherLine> others;
    int line_count = 0;
    // The reader's own problem (a line too long, a NUL byte), which ends the half; its line is in the half.
    std::optional<Diagnostic> problem;
    // The half cannot be read alone: it holds a Ctrl-Z (what follows one is judged over the whole
    // text), or it is a second half that starts with a byte-order mark's bytes (which only the
    // text's start may skip). The parser then reads the whole text in order.
    bool needs_whole_text = false;
};

// Scans `half`, its points' room reserved for `expected_points`.
ScannedHalf scan_half(std::string_view half, const std::string& file_name, bool first_half, std::size_t expected_points);

} // namespace apcs::dat_lines
