#include "apcs/formats/dat_file.h"

#include "apcs/base/parallel_work.h"
#include "dat_point_lines.h"

#include "apcs/animation/input_limits.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"

#include <algorithm>
#include <array>
#include <span>
#include <cctype>
#include <charconv>
#include <cmath>

namespace apcs {

std::size_t DatFile::point_count() const { return total_point_count(parts); }

namespace {

void append_xyz(std::string& text, const Vec3& point)
{
    append_shortest(text, point.x);
    text += ' ';
    append_shortest(text, point.y);
    text += ' ';
    append_shortest(text, point.z);
}

using dat_lines::Fields;
using dat_lines::split_fields;

// Reads a file line by line and collects parts and points; the first problem ends the reading.
class DatParser {
public:
    // `positions_only`: the points keep only their positions (a key frame's need, 24 bytes a point
    // instead of a DatPoint's 72), for parse_graphic.
    DatParser(const std::string& file_name, std::size_t minimum_points, bool positions_only = false)
        : m_file_name(file_name)
        , m_minimum_points(minimum_points)
        , m_positions_only(positions_only)
    {
    }

    Expected<DatFile> parse(std::string_view text);
    // The same, the text's two halves scanned on both cores (when it has a line end past its
    // middle and holds no Ctrl-Z), then their other lines read and their points taken in order.
    Expected<DatFile> parse_in_halves(std::string_view text);
    // Only for a parser made with positions_only.
    Expected<Graphic> parse_graphic_pieces(std::size_t line_count, const TextPieces& read);

private:
    Expected<void> parse_line(std::string_view line);
    Expected<void> parse_count(std::string_view field);
    Expected<void> parse_slopes(const Fields& fields);
    Expected<void> parse_part(const Fields& fields);
    Expected<void> parse_point(const Fields& fields);
    void start_unnamed_part();
    void add_point(const DatPoint& point);
    Expected<void> take_half(dat_lines::ScannedHalf& half, int line_offset);
    Expected<void> take_points(std::vector<DatPoint>& points, std::size_t first, std::size_t end, int line_offset);
    Expected<void> finish();
    [[nodiscard]] Diagnostic error(std::string message, int line) const
    {
        return {m_file_name, line, std::move(message)};
    }
    [[nodiscard]] Diagnostic error(std::string message) const { return error(std::move(message), m_line); }
    void end_part();
    Expected<void> parse_all(std::string_view text);
    Expected<void> parse_pieces(std::size_t line_count, const TextPieces& read);
    std::size_t part_size(std::size_t part) const
    {
        return m_positions_only ? m_positions[part].size() : m_file.parts[part].points.size();
    }
    const Vec3& part_end(std::size_t part, bool last) const
    {
        if (m_positions_only)
            return last ? m_positions[part].back() : m_positions[part].front();
        return last ? m_file.parts[part].points.back().position : m_file.parts[part].points.front().position;
    }
    template <typename Points>
    void reserve_for_lines_left(Points& points) const;

    const std::string& m_file_name;
    std::size_t m_minimum_points;
    bool m_positions_only;
    std::vector<std::vector<Vec3>> m_positions; // per part, when positions only
    DatFile m_file;
    int m_line = 0;
    bool m_seen_data = false;
    std::optional<std::size_t> m_declared_count;
    int m_count_line = 0;
    std::vector<int> m_part_lines;
    std::vector<bool> m_marked_closed;
    std::size_t m_points = 0;
    std::size_t m_text_lines = 0;
};

// A whole text as one piece, and the line count that sizes its points.
std::size_t line_count_of(std::string_view text)
{
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
}

TextPieces whole(std::string_view text)
{
    return [text](const TextPieceSink& sink) { return sink(text); };
}

Expected<void> DatParser::parse_all(std::string_view text)
{
    return parse_pieces(line_count_of(text), whole(text));
}

Expected<void> DatParser::parse_pieces(std::size_t line_count, const TextPieces& read)
{
    // A part's points are reserved for the lines left, so that a large file's points are not
    // copied again and again as they grow (end_part gives back what a part did not use).
    m_text_lines = line_count;
    DataLineReader lines(m_file_name, [this](int line, std::string_view content) {
        m_line = line;
        return parse_line(content);
    });
    if (auto outcome = read([&lines](std::string_view piece) { return lines.feed(piece); }); !outcome)
        return outcome;
    if (auto outcome = lines.finish(); !outcome)
        return outcome.error();
    return finish();
}

Expected<DatFile> DatParser::parse(std::string_view text)
{
    if (auto outcome = parse_all(text); !outcome)
        return outcome.error();
    return std::move(m_file);
}

Expected<Graphic> DatParser::parse_graphic_pieces(std::size_t line_count, const TextPieces& read)
{
    if (auto outcome = parse_pieces(line_count, read); !outcome)
        return outcome.error();
    Graphic graphic;
    graphic.parts.reserve(m_file.parts.size());
    for (std::size_t i = 0; i < m_file.parts.size(); ++i)
        graphic.parts.push_back({std::move(m_file.parts[i].name), m_file.parts[i].closure, std::move(m_positions[i])});
    return graphic;
}

template <typename Points>
void DatParser::reserve_for_lines_left(Points& points) const
{
    const std::size_t lines_left = m_text_lines - std::min(m_text_lines, static_cast<std::size_t>(m_line - 1));
    points.reserve(std::min(lines_left, max_dat_points - m_points));
}

Expected<void> DatParser::parse_line(std::string_view content)
{
    const Fields fields = split_fields(content);
    if (fields.empty())
        return ok;
    if (equals_ignoring_case(fields[0], "PART"))
        return parse_part(fields);
    if (equals_ignoring_case(fields[0], "SLOPES"))
        return parse_slopes(fields);
    if (!m_seen_data && fields.size() == 1)
        return parse_count(fields[0]);
    return parse_point(fields);
}

Expected<void> DatParser::parse_count(std::string_view field)
{
    m_seen_data = true;
    m_count_line = m_line;
    const std::optional<std::size_t> count = parse_count_value(field);
    if (!count)
        return error("expected a point count (a whole number from 0 to " + std::to_string(max_dat_points) +
                     ") or a point of 2, 3 or 7 numbers, found " + quote_field(field));
    if (*count > max_dat_points)
        return error("point count " + std::to_string(*count) + " is over the limit of " +
                     std::to_string(max_dat_points));
    m_declared_count = *count;
    return ok;
}

// SLOPES S0 S1 (SPEC §2.1): once, before the first point, each slope in [0, 1] as --slopes.
Expected<void> DatParser::parse_slopes(const Fields& fields)
{
    if (m_file.slopes)
        return error("a second SLOPES line; expected one at most");
    if (m_points > 0)
        return error("SLOPES after a point; expected it before the first point");
    if (fields.size() != 3)
        return error("expected 'SLOPES S0 S1', two end slopes in " + range_text(limits::end_slope));
    std::array<double, 2> slopes{};
    for (std::size_t i = 0; i < slopes.size(); ++i) {
        const std::optional<double> value = parse_number(fields[i + 1]);
        if (!value || !limits::end_slope.contains(*value))
            return error("expected an end slope in " + range_text(limits::end_slope) + ", found " +
                         quote_field(fields[i + 1]));
        slopes[i] = *value;
    }
    m_file.slopes = EndSlopes{slopes[0], slopes[1]};
    return ok;
}

Expected<void> DatParser::parse_part(const Fields& fields)
{
    m_seen_data = true;
    if (fields.size() < 2 || fields.size() > 3)
        return error("expected 'PART name' or 'PART name OPEN|CLOSED'");
    bool closed = false;
    if (fields.size() == 3) {
        if (equals_ignoring_case(fields[2], "CLOSED"))
            closed = true;
        else if (!equals_ignoring_case(fields[2], "OPEN"))
            return error("expected OPEN or CLOSED after the part name, found " + quote_field(fields[2]));
    }
    // Points before the first PART line form a part of their own; a PART line otherwise starts
    // the next part, and the part it ends must not be empty.
    if (!m_part_lines.empty() && part_size(m_file.parts.size() - 1) == 0)
        return error("part '" + m_file.parts.back().name + "' has no points; expected at least one",
                     m_part_lines.back());
    end_part();
    m_file.parts.push_back({std::string(fields[1]), Closure::open, {}});
    if (m_positions_only)
        m_positions.emplace_back();
    m_part_lines.push_back(m_line);
    m_marked_closed.push_back(closed);
    return ok;
}

Expected<void> DatParser::parse_point(const Fields& fields)
{
    using dat_lines::PointFault;
    m_seen_data = true;
    if (fields.size() != 2 && fields.size() != 3 && fields.size() != 7)
        return error("expected a point of 2, 3 or 7 numbers (x y [z] [t c b a]), found " +
                     std::to_string(fields.size()) + " fields");
    if (m_points == max_dat_points)
        return error("more than " + std::to_string(max_dat_points) + " points; expected at most that many");
    dat_lines::ReadPoint read = dat_lines::read_point(fields);
    const std::string_view field = fields[read.field];
    switch (read.fault) {
    case PointFault::none: break;
    case PointFault::field_count: break; // checked above
    case PointFault::not_a_number: return error("expected a number, found " + quote_field(field));
    case PointFault::not_finite: return error("expected a finite number, found " + quote_field(field));
    case PointFault::too_large:
        return error("number " + quote_field(field) + " is out of range; expected |value| <= 1e9");
    case PointFault::staff_outside:
        return error(ascii_lower_case(staff_line_name(staff_lines[read.field - 3])) + " " + quote_field(field) +
                     " is outside " + range_text(limits::staff_value));
    }
    read.point.line = m_line;
    add_point(read.point);
    return ok;
}

void DatParser::start_unnamed_part()
{
    m_file.parts.push_back({"", Closure::open, {}});
    m_part_lines.push_back(0);
    m_marked_closed.push_back(false);
    if (m_positions_only)
        m_positions.emplace_back();
}

// A point read (its line set) joins the last part, or the unnamed part that points before any
// PART line form.
void DatParser::add_point(const DatPoint& point)
{
    if (m_file.parts.empty())
        start_unnamed_part();
    ++m_points;
    if (m_positions_only) {
        std::vector<Vec3>& positions = m_positions.back();
        if (positions.capacity() == 0)
            reserve_for_lines_left(positions);
        positions.push_back(point.position);
        return;
    }
    std::vector<DatPoint>& points = m_file.parts.back().points;
    if (points.capacity() == 0)
        reserve_for_lines_left(points);
    points.push_back(point);
}

Expected<DatFile> DatParser::parse_in_halves(std::string_view text)
{
    const std::size_t split = text.find('\n', text.size() / 2);
    if (split == std::string_view::npos || split + 1 >= text.size())
        return parse(text);
    const std::array<std::string_view, 2> halves{text.substr(0, split + 1), text.substr(split + 1)};
    std::array<dat_lines::ScannedHalf, 2> scanned;
    std::size_t text_lines = 0;
    split_across_cores(2, 1, [&](std::size_t first, std::size_t end) {
        for (std::size_t h = first; h < end; ++h) {
            // The first half's points take the second's too (it becomes the part's vector): room
            // for every line of the text, as parse_all reserves.
            if (h == 0)
                text_lines = line_count_of(text);
            const std::size_t expected = h == 0 ? text_lines : line_count_of(halves[1]);
            scanned[h] = dat_lines::scan_half(halves[h], m_file_name, h == 0, expected);
        }
    });
    if (scanned[0].needs_whole_text || scanned[1].needs_whole_text)
        return parse(text);
    m_text_lines = text_lines;
    if (auto outcome = take_half(scanned[0], 0); !outcome)
        return outcome.error();
    if (auto outcome = take_half(scanned[1], scanned[0].line_count); !outcome)
        return outcome.error();
    if (auto outcome = finish(); !outcome)
        return outcome.error();
    return std::move(m_file);
}

// A scanned half's lines in order: its points taken between the other lines, which are read as
// parse_all reads them; the half's own problem ends it. `line_offset`: the lines before the half.
Expected<void> DatParser::take_half(dat_lines::ScannedHalf& half, int line_offset)
{
    std::size_t taken = 0;
    for (const dat_lines::OtherLine& other : half.others) {
        if (auto outcome = take_points(half.points, taken, other.points_before, line_offset); !outcome)
            return outcome;
        taken = other.points_before;
        m_line = other.line + line_offset;
        if (auto outcome = parse_line(other.content); !outcome)
            return outcome;
    }
    if (auto outcome = take_points(half.points, taken, half.points.size(), line_offset); !outcome)
        return outcome;
    if (half.problem) {
        Diagnostic problem = *half.problem;
        problem.line += line_offset;
        return problem;
    }
    return ok;
}

// Points first … end − 1 of a half, as parse_point would take them (the limit on points checked
// before each). The first half's points, when they start the first part, become its vector.
Expected<void> DatParser::take_points(std::vector<DatPoint>& points, std::size_t first, std::size_t end,
                                      int line_offset)
{
    if (first == end)
        return ok;
    m_seen_data = true;
    const bool whole_vector = first == 0 && end == points.size() && line_offset == 0;
    if (whole_vector && m_file.parts.empty() && m_points + points.size() <= max_dat_points) {
        start_unnamed_part();
        m_points += points.size();
        m_file.parts.back().points = std::move(points);
        return ok;
    }
    for (std::size_t k = first; k < end; ++k) {
        m_line = points[k].line + line_offset;
        if (m_points == max_dat_points)
            return error("more than " + std::to_string(max_dat_points) + " points; expected at most that many");
        DatPoint point = points[k];
        point.line = m_line;
        add_point(point);
    }
    return ok;
}

void DatParser::end_part()
{
    const auto give_back_room = [](auto& points) {
        if (points.capacity() > points.size() + points.size() / 8 + 16)
            points.shrink_to_fit();
    };
    if (m_positions_only && !m_positions.empty())
        give_back_room(m_positions.back());
    if (!m_file.parts.empty())
        give_back_room(m_file.parts.back().points);
}

Expected<void> DatParser::finish()
{
    end_part();
    if (!m_file.parts.empty() && part_size(m_file.parts.size() - 1) == 0)
        return error("part '" + m_file.parts.back().name + "' has no points; expected at least one",
                     m_part_lines.back());
    if (m_declared_count && *m_declared_count != m_points)
        return error("the count line says " + std::to_string(*m_declared_count) + " points but " +
                         std::to_string(m_points) + " follow",
                     m_count_line);
    if (m_points < m_minimum_points)
        return error("expected at least " + std::to_string(m_minimum_points) + " points, found " +
                         std::to_string(m_points),
                     0);
    for (std::size_t i = 0; i < m_file.parts.size(); ++i) {
        const bool ends_meet = part_size(i) >= 3 && part_end(i, false) == part_end(i, true);
        m_file.parts[i].closure = m_marked_closed[i] || ends_meet ? Closure::closed : Closure::open;
    }
    return ok;
}

// "PART name OPEN|CLOSED" for part `index`: an unnamed part is called P1, P2, …; blanks and
// comment characters in a name become '_' so that it reads back as one field.
void append_part_line(std::string& text, const std::string& part_name, Closure closure, std::size_t index)
{
    text += part_line(part_name, closure, index) + '\n';
}

// A file of one open unnamed part is written without PART lines.
bool needs_part_lines(std::size_t part_count, const std::string& first_name, Closure first_closure)
{
    return part_count != 1 || !first_name.empty() || first_closure != Closure::open;
}

} // namespace

std::string part_line(const std::string& part_name, Closure closure, std::size_t index)
{
    std::string name = part_name.empty() ? "P" + std::to_string(index + 1) : part_name;
    std::replace_if(name.begin(), name.end(), [](char c) { return is_field_blank(c) || c == ';' || c == '#'; }, '_');
    return "PART " + name + (closure == Closure::closed ? " CLOSED" : " OPEN");
}

Expected<DatFile> parse_dat(std::string_view text, const std::string& file_name, std::size_t minimum_points)
{
    // Below a megabyte (some 40000 points) a second thread costs more than it saves.
    constexpr std::size_t worth_halves = std::size_t{1} << 20;
    return parse_dat(text, file_name, minimum_points, text.size() >= worth_halves ? DatReading::in_halves : DatReading::in_order);
}

Expected<DatFile> parse_dat(std::string_view text, const std::string& file_name, std::size_t minimum_points,
                            DatReading reading)
{
    DatParser parser(file_name, minimum_points);
    return reading == DatReading::in_halves ? parser.parse_in_halves(text) : parser.parse(text);
}

Expected<Graphic> parse_key_frame(std::string_view text, const std::string& file_name, std::size_t minimum_points)
{
    return DatParser(file_name, minimum_points, true).parse_graphic_pieces(line_count_of(text), whole(text));
}

Expected<Graphic> parse_key_frame_pieces(const std::string& file_name, std::size_t line_count, const TextPieces& read,
                                         std::size_t minimum_points)
{
    return DatParser(file_name, minimum_points, true).parse_graphic_pieces(line_count, read);
}

std::string format_dat(const DatFile& file)
{
    std::string text;
    // About 40 bytes a point: one allocation for the whole file.
    text.reserve(file.point_count() * 40 + file.parts.size() * 24);
    if (file.slopes)
        text += slopes_line(*file.slopes) + '\n';
    const bool part_lines =
        !file.parts.empty() && needs_part_lines(file.parts.size(), file.parts[0].name, file.parts[0].closure);
    for (std::size_t i = 0; i < file.parts.size(); ++i) {
        const DatPart& part = file.parts[i];
        if (part_lines)
            append_part_line(text, part.name, part.closure, i);
        for (const DatPoint& point : part.points) {
            append_point_line(text, point.position, point.staff);
            text += '\n';
        }
    }
    return text;
}

std::string slopes_line(const EndSlopes& slopes)
{
    std::string text = "SLOPES ";
    append_shortest(text, slopes.start);
    text += ' ';
    append_shortest(text, slopes.end);
    return text;
}

void append_point_line(std::string& text, const Vec3& position, const std::optional<StaffValues>& staff)
{
    append_xyz(text, position);
    if (!staff)
        return;
    for (const StaffLine line : staff_lines) {
        text += ' ';
        append_shortest(text, (*staff)[line]);
    }
}

bool format_graphic_in_chunks(const Graphic& structure, std::size_t point_count, const GraphicPoints& points_at,
                              int decimals, const std::function<bool(std::string_view)>& sink)
{
    // About 4000 points a chunk: about 150 KB of text, small beside a frame of 10^5 points.
    constexpr std::size_t chunk_points = 4096;
    std::vector<Vec3> points(std::min(chunk_points, point_count));
    std::string text;
    text.reserve(points.size() * 64 + 64);
    const bool part_lines = !structure.parts.empty() &&
                            needs_part_lines(structure.parts.size(), structure.parts[0].name, structure.parts[0].closure);
    std::size_t next = 0;
    for (std::size_t i = 0; i < structure.parts.size(); ++i) {
        const GraphicPart& part = structure.parts[i];
        if (part_lines)
            append_part_line(text, part.name, part.closure, i);
        for (std::size_t done = 0; done < part.points.size() && next < point_count;) {
            const std::size_t run = std::min({chunk_points, part.points.size() - done, point_count - next});
            const std::span<Vec3> chunk = std::span(points).first(run);
            points_at(next, chunk);
            for (const Vec3& point : chunk) {
                append_fixed(text, point.x, decimals);
                text += ' ';
                append_fixed(text, point.y, decimals);
                text += ' ';
                append_fixed(text, point.z, decimals);
                text += '\n';
            }
            done += run;
            next += run;
            if (text.size() >= chunk_points * 32) {
                if (!sink(text))
                    return false;
                text.clear();
            }
        }
    }
    return text.empty() || sink(text);
}

std::string format_graphic(const Graphic& structure, std::span<const Vec3> points, int decimals)
{
    std::string text;
    // Three shortest numbers are at most 72 bytes; typical ones about 55: one allocation.
    text.reserve(points.size() * 64 + structure.parts.size() * 24);
    const auto copy_points = [points](std::size_t first, std::span<Vec3> out) {
        std::copy_n(points.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
    };
    format_graphic_in_chunks(structure, points.size(), copy_points, decimals, [&text](std::string_view chunk) {
        text += chunk;
        return true;
    });
    return text;
}

Graphic graphic_from(const DatFile& file)
{
    Graphic graphic;
    graphic.parts.reserve(file.parts.size());
    for (const DatPart& part : file.parts) {
        GraphicPart converted{part.name, part.closure, {}};
        converted.points.reserve(part.points.size());
        for (const DatPoint& point : part.points)
            converted.points.push_back(point.position);
        graphic.parts.push_back(std::move(converted));
    }
    return graphic;
}

} // namespace apcs
