// A scene file's MOVE, ROTATE, ROLL and SCALE lines, and their clauses (SPEC §8.1).
#include "scene_parser.h"
#include "scene_numbers.h"

#include "apcs/formats/number_text.h"

#include <cmath>

namespace apcs::scene_parsing {

namespace {

// The scene's largest scale: a SCALE whose power over its frames leaves 1e-6 … 1e6 is refused.
constexpr double most_scale_growth = 1e6;

// ALIGN's directions are differences of points on the path, squared for their length: a path (or
// an AHEAD distance) of 1e-150 or less has steps whose squares vanish below the smallest double,
// and one of 1e-12 of its coordinates or less has steps made of round-off (issue 45: AHEAD 1e-300
// gave NaN turns; a path 1e-300 long silently did not turn).
constexpr double shortest_align_span = 1e-150;
constexpr double least_align_fraction = 1e-12;

} // namespace

Expected<void> SceneParser::parse_move(const Fields& fields)
{
    if (auto outcome = once(object().move.has_value(), "MOVE"); !outcome)
        return outcome.error();
    if (fields.size() < 2)
        return error("expected 'MOVE PATH.dat [TIMES F0 F1 ... | FROM F TO G] [LOOP] [ALIGN [AHEAD D]]'");
    Expected<DatFile> file = read_file(fields[1]);
    if (!file)
        return file.error();
    PendingPath path{std::move(*file), std::string(fields[1]), m_line};
    SceneMove move;
    move.frames = {0, m_scene.last_frame};
    bool span_given = false;
    Clauses clauses(fields, 2);
    while (!clauses.done()) {
        const std::string_view clause = clauses.peek();
        if (equals_ignoring_case(clause, "LOOP")) {
            clauses.take();
            if (clauses.seen("LOOP"))
                return error("LOOP is given twice; expected it once");
            move.loop = true;
        } else if (equals_ignoring_case(clause, "ALIGN")) {
            clauses.take();
            if (auto outcome = align_clause(clauses, move); !outcome)
                return outcome.error();
        } else if (equals_ignoring_case(clause, "TIMES")) {
            clauses.take();
            if (auto outcome = times_clause(clauses, path, move); !outcome)
                return outcome.error();
        } else {
            span_given = true;
            if (auto outcome = span_clause(clauses, "MOVE", move.frames); !outcome)
                return outcome.error();
        }
    }
    if (auto outcome = check_move_frames(move, path, span_given); !outcome)
        return outcome.error();
    object().move = std::move(move);
    m_pending.move_path = std::move(path);
    return ok;
}

// TIMES F0 F1 … Fn, after the TIMES taken: increasing frames, at least one.
Expected<void> SceneParser::times_clause(Clauses& clauses, const PendingPath& path, SceneMove& move) const
{
    if (clauses.seen("TIMES"))
        return error("TIMES is given twice; expected it once");
    // The frames run to the first field that is not a whole number (LOOP, FROM, ...).
    while (!clauses.done() && parse_count_value(clauses.peek())) {
        const Expected<int> time = frame(clauses.take(), "TIMES");
        if (!time)
            return time.error();
        if (!move.times.empty() && *time <= move.times.back())
            return error("TIMES " + std::to_string(*time) + " after " + std::to_string(move.times.back()) +
                         ": expected increasing frames, one per control point");
        move.times.push_back(*time);
    }
    // Without frames the MOVE would be read as one without TIMES, the user's keys silently gone.
    if (move.times.empty())
        return error("TIMES without frames; expected one frame per control point of " + quote_field(path.name) + " (" +
                     std::to_string(path.file.point_count()) + ")");
    return ok;
}

// The MOVE's frames once its clauses are read: TIMES (one per control point) or FROM/TO, and at
// least one frame to move over.
Expected<void> SceneParser::check_move_frames(SceneMove& move, const PendingPath& path, bool span_given) const
{
    if (!move.times.empty() && span_given)
        return error("MOVE with both TIMES and FROM/TO; expected one of them (TIMES gives every control point's frame)");
    if (!move.times.empty()) {
        if (move.times.size() != path.file.point_count())
            return error("TIMES gives " + std::to_string(move.times.size()) + " frames but " + quote_field(path.name) +
                         " has " + std::to_string(path.file.point_count()) +
                         " control points; expected one frame per control point");
        move.frames = {move.times.front(), move.times.back()};
    }
    if (auto outcome = check_span(move.frames, "MOVE"); !outcome)
        return outcome;
    // FROM F TO F would put the object at the path's end at frame F with nothing between: a jump,
    // not a move, and at frame 0 against "frame 0 shows every drawing as given" (SPEC §8.2).
    if (move.frames.from < move.frames.to)
        return ok;
    const std::string at = std::to_string(move.frames.from);
    return error("MOVE FROM " + at + " TO " + at + " covers no frame: the object would jump to the path's end at frame " +
                 at + "; expected FROM before TO");
}

// ALIGN [AHEAD D], after the ALIGN taken: D a distance above 0.
Expected<void> SceneParser::align_clause(Clauses& clauses, SceneMove& move) const
{
    if (move.align)
        return error("ALIGN is given twice; expected it once");
    move.align = true;
    if (clauses.done() || !equals_ignoring_case(clauses.peek(), "AHEAD"))
        return ok;
    clauses.take();
    if (clauses.done())
        return error("expected 'ALIGN AHEAD D' with D the distance between the axles");
    const std::string_view field = clauses.take();
    const Expected<double> ahead = number(field, "AHEAD");
    if (!ahead)
        return ahead.error();
    if (!(*ahead > 0.0))
        return error("ALIGN AHEAD " + quote_field(field) + " is not above 0; expected the distance between the axles");
    move.ahead = *ahead;
    return ok;
}

Expected<void> SceneParser::parse_rotate(const Fields& fields)
{
    if (auto outcome = once(object().rotate || object().roll, object().rotate ? "ROTATE" : "ROTATE or ROLL");
        !outcome)
        return outcome.error();
    if (fields.size() < 2)
        return error("expected 'ROTATE DEG [AXIS x|y|z] [ABOUT X Y Z] [FROM F TO G]'");
    SceneRotate rotate;
    rotate.frames = {0, m_scene.last_frame};
    const Expected<double> degrees = number(fields[1], "the degrees per frame");
    if (!degrees)
        return degrees.error();
    rotate.degrees_per_frame = *degrees;
    Clauses clauses(fields, 2);
    if (auto outcome = turn_clauses(clauses, "ROTATE", rotate.about, &rotate.frames, &rotate.axis); !outcome)
        return outcome.error();
    object().rotate = rotate;
    return ok;
}

// ROLL RADIUS [AXIS x|y|z] [ABOUT X Y Z] (SPEC §8.1): no FROM/TO, it rolls whenever its hub moves.
Expected<void> SceneParser::parse_roll(const Fields& fields)
{
    if (auto outcome = once(object().rotate || object().roll, object().roll ? "ROLL" : "ROTATE or ROLL");
        !outcome)
        return outcome.error();
    if (fields.size() < 2 || !parse_number(fields[1]))
        return error("expected 'ROLL RADIUS [AXIS x|y|z] [ABOUT X Y Z]' with RADIUS the wheel's radius" +
                     std::string(fields.size() < 2 ? "; found nothing after ROLL" : ", found " + quote_field(fields[1])));
    SceneRoll roll;
    const Expected<double> radius = number(fields[1], "RADIUS");
    if (!radius)
        return radius.error();
    if (*radius == 0.0)
        return error("ROLL RADIUS " + quote_field(fields[1]) +
                     " is 0; expected the wheel's radius (above 0, or below 0 to roll the other way)");
    roll.radius = *radius;
    roll.line = m_line;
    Clauses clauses(fields, 2);
    if (auto outcome = turn_clauses(clauses, "ROLL", roll.about, nullptr, &roll.axis); !outcome)
        return outcome.error();
    object().roll = roll;
    return ok;
}

Expected<void> SceneParser::parse_scale(const Fields& fields)
{
    if (auto outcome = once(object().scale.has_value(), "SCALE"); !outcome)
        return outcome.error();
    if (fields.size() < 2)
        return error("expected 'SCALE FACTOR [FY FZ] [ABOUT X Y Z] [FROM F TO G]'");
    SceneScale scale;
    scale.frames = {0, m_scene.last_frame};
    // One factor for all axes, or three (x, y, z): a keyword or the end follows the first or third.
    const std::size_t count = fields.size() >= 4 && parse_number(fields[2]) ? 3 : 1;
    if (fields.size() >= 2 + count && parse_number(fields[1 + count]))
        return error("expected 'SCALE FACTOR' or 'SCALE FX FY FZ', one factor or three; found " +
                     quote_field(fields[1 + count]) + " after " + (count == 1 ? "one" : "three"));
    std::array<double, 3> factors{};
    for (std::size_t axis = 0; axis < count; ++axis) {
        const Expected<double> factor = number(fields[1 + axis], "FACTOR");
        if (!factor)
            return factor.error();
        if (*factor <= 0.0)
            return error("SCALE FACTOR " + quote_field(fields[1 + axis]) + " is not above 0; expected a factor > 0");
        factors[axis] = *factor;
    }
    if (count == 1)
        factors[1] = factors[2] = factors[0];
    scale.factors = {factors[0], factors[1], factors[2]};
    Clauses clauses(fields, 1 + count);
    if (auto outcome = turn_clauses(clauses, "SCALE", scale.about, &scale.frames, nullptr); !outcome)
        return outcome.error();
    for (std::size_t axis = 0; axis < count; ++axis) {
        const double growth = std::abs(std::log(factors[axis])) * (scale.frames.to - scale.frames.from);
        if (growth > std::log(most_scale_growth))
            return error("SCALE " + quote_field(fields[1 + axis]) + " over " +
                         std::to_string(scale.frames.to - scale.frames.from) +
                         " frames leaves 1e-6 ... 1e6; expected a factor nearer 1 or fewer frames (FROM/TO)");
    }
    object().scale = scale;
    return ok;
}

Expected<void> SceneParser::span_clause(Clauses& clauses, std::string_view keyword, FrameSpan& span) const
{
    const std::string_view clause = clauses.take();
    const bool from = equals_ignoring_case(clause, "FROM");
    if (!from && !equals_ignoring_case(clause, "TO"))
        return error("unexpected " + quote_field(clause) + " in " + std::string(keyword) +
                     "; expected its optional clauses (FROM F, TO G" +
                     (keyword == "ROTATE" ? ", AXIS, ABOUT" : keyword == "SCALE" ? ", ABOUT" : keyword == "MOVE" ? ", TIMES, LOOP" : "") + ")");
    if (clauses.seen(clause))
        return error(std::string(from ? "FROM" : "TO") + " is given twice; expected it once");
    if (clauses.done())
        return error("expected a frame after " + std::string(from ? "FROM" : "TO"));
    const Expected<int> value = frame(clauses.take(), from ? "FROM" : "TO");
    if (!value)
        return value.error();
    (from ? span.from : span.to) = *value;
    return ok;
}

// The clauses of ROTATE, ROLL and SCALE after their number: ABOUT X Y Z, when `frames` is given
// (not ROLL) FROM F and TO G, then FROM <= TO, and when `axis` is given (ROTATE, ROLL) AXIS x|y|z.
Expected<void> SceneParser::turn_clauses(Clauses& clauses, std::string_view keyword, std::optional<Vec3>& about,
                                         FrameSpan* frames, Axis* axis) const
{
    while (!clauses.done()) {
        const std::string_view clause = clauses.peek();
        if (axis != nullptr && equals_ignoring_case(clause, "AXIS")) {
            clauses.take();
            if (clauses.seen("AXIS") || clauses.done())
                return error("expected 'AXIS x', 'AXIS y' or 'AXIS z' once");
            const std::string name = ascii_lower_case(clauses.take());
            if (name != "x" && name != "y" && name != "z")
                return error("unknown AXIS " + quote_field(name) + "; expected x, y or z");
            *axis = name == "x" ? Axis::x : name == "y" ? Axis::y : Axis::z;
        } else if (equals_ignoring_case(clause, "ABOUT")) {
            const Expected<Vec3> centre = about_clause(clauses);
            if (!centre)
                return centre.error();
            about = *centre;
        } else if (frames == nullptr) {
            return error("unexpected " + quote_field(clause) + " in " + std::string(keyword) +
                         "; expected its optional clauses (AXIS, ABOUT): it rolls whenever its hub moves");
        } else if (Expected<void> span = span_clause(clauses, keyword, *frames); !span) {
            return span.error();
        }
    }
    if (frames == nullptr)
        return ok;
    return check_span(*frames, keyword);
}

// ABOUT X Y Z: the centre of a turn.
Expected<Vec3> SceneParser::about_clause(Clauses& clauses) const
{
    clauses.take();
    if (clauses.seen("ABOUT") || clauses.left() < 3)
        return error("expected 'ABOUT X Y Z' once");
    Vec3 centre;
    for (double* coordinate : {&centre.x, &centre.y, &centre.z}) {
        const Expected<double> value = number(clauses.take(), "ABOUT");
        if (!value)
            return value.error();
        *coordinate = *value;
    }
    return centre;
}

Expected<void> SceneParser::check_span(const FrameSpan& span, std::string_view keyword) const
{
    if (span.from <= span.to)
        return ok;
    return error(std::string(keyword) + " FROM " + std::to_string(span.from) + " TO " + std::to_string(span.to) +
                 ": expected FROM <= TO");
}

// ALIGN turns by the path's direction: the path must have one the numbers can hold (a path of zero
// length has none, nor has one 1e-300 long), and AHEAD's chord must be longer than the round-off of
// the path's points (AHEAD 1e-300's chord was 0: NaN turns, refused as values that are not numbers
// "composed with its parents'", at the OBJECT line). Told here, at the MOVE line, in the scene's terms.
Expected<void> SceneParser::check_align_path(const SceneMove& move, const PendingPath& pending) const
{
    double span = 0.0;    // the farthest control point from the first
    double largest = 0.0; // the largest |coordinate|
    for (const ControlPoint& point : move.path) {
        const Vec3 step = point.position - move.path.front().position;
        span = std::max(span, std::hypot(step.x, step.y, step.z)); // hypot: 1e-300 does not square to 0
        largest = std::max(largest, largest_coordinate(point.position));
    }
    const std::string name = quote_field(pending.name);
    if (span == 0.0)
        return error("ALIGN on " + name + ", a path of zero length: it has no direction to turn the object by", pending.line);
    const double least = std::max(shortest_align_span, least_align_fraction * largest);
    if (span <= least)
        return error("ALIGN on " + name + ": its control points are all within " + significant_number(span) +
                         " of its first, too close for a direction; expected a path that spans more than 1e-150 and "
                         "more than 1e-12 of its largest coordinate",
                     pending.line);
    if (move.ahead && *move.ahead <= least)
        return error("ALIGN AHEAD " + significant_number(*move.ahead) + " on " + name +
                         ": a chord that short is round-off, not a direction; expected D above 1e-150 and above 1e-12 "
                         "of the path's largest coordinate (" + significant_number(largest) + ")",
                     pending.line);
    return ok;
}

} // namespace apcs::scene_parsing
