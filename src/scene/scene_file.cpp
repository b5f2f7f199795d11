#include "apcs/scene/scene_file.h"
#include "apcs/scene/rigid_turn.h"
#include "apcs/scene/scene_joints.h"
#include "scene_numbers.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"
#include "apcs/geometry/bounding_box.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace apcs {

namespace {

using Fields = std::vector<std::string_view>;

// The scene's largest scale: a SCALE whose power over its frames leaves 1e-6 … 1e6 is refused.
constexpr double most_scale_growth = 1e6;

// ALIGN's directions are differences of points on the path, squared for their length: a path (or
// an AHEAD distance) of 1e-150 or less has steps whose squares vanish below the smallest double,
// and one of 1e-12 of its coordinates or less has steps made of round-off (issue 45: AHEAD 1e-300
// gave NaN turns; a path 1e-300 long silently did not turn).
constexpr double shortest_align_span = 1e-150;
constexpr double least_align_fraction = 1e-12;

Fields split(std::string_view content)
{
    Fields fields;
    for_each_field(content, [&](std::string_view field) { fields.push_back(field); });
    return fields;
}


// A path file, kept until the object's staff values are known.
struct PendingPath {
    DatFile file;
    std::string name;
    int line = 0;
};

// What an object's lines said that needs the whole object (its STAFF may come last).
struct PendingObject {
    std::optional<PendingPath> move_path;
    std::optional<std::array<PendingPath, 2>> paths;
};

// The optional clauses after a keyword's own fields: FROM F, TO G, AXIS A, ABOUT X Y Z, TIMES …,
// LOOP, TOLERANCE D; each at most once.
class Clauses {
public:
    Clauses(const Fields& fields, std::size_t first) : m_fields(fields), m_next(first) {}
    bool done() const { return m_next >= m_fields.size(); }
    std::string_view peek() const { return m_fields[m_next]; }
    std::string_view take() { return m_fields[m_next++]; }
    std::size_t left() const { return m_fields.size() - m_next; }
    bool seen(std::string_view keyword)
    {
        const std::string lower = ascii_lower_case(keyword);
        if (std::find(m_seen.begin(), m_seen.end(), lower) != m_seen.end())
            return true;
        m_seen.push_back(lower);
        return false;
    }

private:
    const Fields& m_fields;
    std::size_t m_next;
    std::vector<std::string> m_seen;
};

class SceneParser {
public:
    SceneParser(const std::string& file_name, const SceneFileReader& read, const StaffValues& defaults)
        : m_file_name(file_name)
        , m_read(read)
        , m_defaults(defaults)
    {
    }

    Expected<Scene> parse(std::string_view text);

private:
    Expected<void> parse_line(const Fields& fields);
    Expected<void> parse_frames(const Fields& fields);
    Expected<void> parse_view(const Fields& fields);
    Expected<void> parse_spacing(const Fields& fields);
    Expected<void> parse_object(const Fields& fields);
    Expected<void> parse_shape(const Fields& fields);
    Expected<void> parse_keys(const Fields& fields);
    Expected<void> parse_paths(const Fields& fields);
    Expected<void> parse_staff(const Fields& fields);
    Expected<void> parse_move(const Fields& fields);
    Expected<void> parse_rotate(const Fields& fields);
    Expected<void> parse_roll(const Fields& fields);
    Expected<void> parse_scale(const Fields& fields);
    Expected<void> parse_joint(const Fields& fields);
    Expected<void> parse_rigid(const Fields& fields);
    Expected<void> finish_object();
    Expected<void> finish_rigid();

    Expected<DatFile> read_file(std::string_view name, std::size_t minimum_points = 2);
    Expected<double> number(std::string_view field, const std::string& what) const;
    Expected<int> frame(std::string_view field, const std::string& what) const;
    Expected<void> span_clause(Clauses& clauses, std::string_view keyword, FrameSpan& span) const;
    Expected<Vec3> about_clause(Clauses& clauses) const;
    Expected<void> turn_clauses(Clauses& clauses, std::string_view keyword, std::optional<Vec3>& about,
                                FrameSpan* frames, Axis* axis) const;
    Expected<void> check_span(const FrameSpan& span, std::string_view keyword) const;
    Expected<void> align_clause(Clauses& clauses, SceneMove& move) const;
    Expected<void> times_clause(Clauses& clauses, const PendingPath& path, SceneMove& move) const;
    Expected<void> check_move_frames(SceneMove& move, const PendingPath& path, bool span_given) const;
    Expected<void> check_align_path(const SceneMove& move, const PendingPath& pending) const;
    Expected<void> once(bool already, std::string_view what) const;
    SceneObject& object() { return m_scene.objects.back(); }
    Diagnostic error(std::string message, int line = 0) const
    {
        return {m_file_name, line == 0 ? m_line : line, std::move(message)};
    }

    const std::string& m_file_name;
    const SceneFileReader& m_read;
    StaffValues m_defaults;
    Scene m_scene;
    bool m_frames_seen = false;
    int m_line = 0;
    PendingObject m_pending;
};

Expected<Scene> SceneParser::parse(std::string_view text)
{
    const Expected<void> lines = for_each_data_line(text, m_file_name, [this](int line, std::string_view content) {
        m_line = line;
        if (Expected<void> printable = printable_line(content, m_file_name, line); !printable)
            return printable;
        const Fields fields = split(content);
        return fields.empty() ? Expected<void>(ok) : parse_line(fields);
    });
    if (!lines)
        return lines.error();
    if (!m_frames_seen)
        return Diagnostic{m_file_name, 0, "expected 'FRAMES N' as the first data line; the file has none"};
    if (m_scene.objects.empty())
        return Diagnostic{m_file_name, 0, "expected at least one OBJECT line; the file has none"};
    if (Expected<void> object = finish_object(); !object)
        return object.error();
    if (Expected<void> joints = connect_joints(m_scene, m_file_name); !joints)
        return joints.error();
    return std::move(m_scene);
}

Expected<void> SceneParser::parse_line(const Fields& fields)
{
    const std::string keyword = ascii_lower_case(fields[0]);
    if (!m_frames_seen) {
        if (keyword != "frames")
            return error("expected 'FRAMES N' as the first data line, found " + quote_field(fields[0]));
        return parse_frames(fields);
    }
    using Parse = Expected<void> (SceneParser::*)(const Fields&);
    static const std::map<std::string, Parse> object_keywords{
        {"shape", &SceneParser::parse_shape}, {"keys", &SceneParser::parse_keys},
        {"paths", &SceneParser::parse_paths}, {"staff", &SceneParser::parse_staff},
        {"move", &SceneParser::parse_move},   {"rotate", &SceneParser::parse_rotate},
        {"roll", &SceneParser::parse_roll},   {"scale", &SceneParser::parse_scale},
        {"joint", &SceneParser::parse_joint}, {"rigid", &SceneParser::parse_rigid}};
    if (keyword == "object")
        return parse_object(fields);
    if (keyword == "view")
        return parse_view(fields);
    if (keyword == "spacing")
        return parse_spacing(fields);
    if (keyword == "frames")
        return error("a second FRAMES line; the scene's frames are given once, on the first data line");
    const auto found = object_keywords.find(keyword);
    if (found == object_keywords.end())
        return error("unknown keyword " + quote_field(fields[0]) +
                     "; expected OBJECT, SHAPE, KEYS, PATHS, STAFF, MOVE, ROTATE, ROLL, SCALE, JOINT, RIGID, VIEW "
                     "or SPACING");
    if (m_scene.objects.empty())
        return error(std::string(fields[0]) + " before the first OBJECT line; expected 'OBJECT NAME' first");
    return (this->*found->second)(fields);
}

Expected<void> SceneParser::parse_frames(const Fields& fields)
{
    m_frames_seen = true;
    const std::optional<std::size_t> count = fields.size() == 2 ? parse_count_value(fields[1]) : std::nullopt;
    if (!count || *count < 1 || *count > static_cast<std::size_t>(max_scene_frames))
        return error("expected 'FRAMES N' with N a whole number from 1 to " + std::to_string(max_scene_frames));
    m_scene.last_frame = static_cast<int>(*count);
    return ok;
}

Expected<void> SceneParser::parse_view(const Fields& fields)
{
    if (!m_scene.objects.empty())
        return error("VIEW after an OBJECT line; expected it before the first OBJECT");
    if (m_scene.view)
        return error("a second VIEW line; expected one at most");
    if (fields.size() != 3)
        return error("expected 'VIEW THETA PHI' (degrees)");
    const Expected<double> theta = number(fields[1], "THETA");
    if (!theta)
        return theta.error();
    const Expected<double> phi = number(fields[2], "PHI");
    if (!phi)
        return phi.error();
    m_scene.view = ViewAngles{.theta_degrees = *theta, .phi_degrees = *phi};
    return ok;
}

// SPACING applies to every path of the scene, so it comes before the first OBJECT, as VIEW does:
// a line among the objects would look as if it were one object's.
Expected<void> SceneParser::parse_spacing(const Fields& fields)
{
    if (!m_scene.objects.empty())
        return error("SPACING after an OBJECT line; expected it before the first OBJECT");
    if (m_scene.spacing)
        return error("a second SPACING line; expected one at most");
    const std::string expected = "expected 'SPACING nearest' or 'SPACING exact'";
    if (fields.size() == 1)
        return error(expected + "; found nothing after SPACING");
    if (fields.size() > 2)
        return error(expected + ", found " + quote_field(fields[2]) + " after " + quote_field(fields[1]));
    const std::string word = ascii_lower_case(fields[1]);
    if (word != "nearest" && word != "exact")
        return error(expected + ", found " + quote_field(fields[1]));
    m_scene.spacing = word == "exact" ? Spacing::exact : Spacing::nearest;
    return ok;
}

Expected<void> SceneParser::parse_object(const Fields& fields)
{
    if (!m_scene.objects.empty())
        if (auto outcome = finish_object(); !outcome)
            return outcome.error();
    const bool with_parent = fields.size() == 4 && equals_ignoring_case(fields[2], "PARENT");
    if (fields.size() != 2 && !with_parent)
        return error("expected 'OBJECT NAME' or 'OBJECT NAME PARENT NAME'");
    if (m_scene.objects.size() == max_scene_objects)
        return error("more than " + std::to_string(max_scene_objects) + " objects; expected at most that many");
    const auto named = [&](std::string_view name) {
        return std::find_if(m_scene.objects.begin(), m_scene.objects.end(),
                            [&](const SceneObject& o) { return o.name == name; });
    };
    if (const auto same = named(fields[1]); same != m_scene.objects.end())
        return error("object " + quote_field(fields[1]) + " is declared again; its first OBJECT line is line " +
                     std::to_string(same->line) + " (names are unique)");
    SceneObject declared;
    declared.name = std::string(fields[1]);
    declared.line = m_line;
    declared.staff = m_defaults;
    if (with_parent) {
        const auto parent = named(fields[3]);
        if (parent == m_scene.objects.end())
            return error("parent " + quote_field(fields[3]) +
                         " is not an object declared above; a parent is declared before its parts");
        declared.parent = static_cast<std::size_t>(parent - m_scene.objects.begin());
        declared.staff = parent->staff;
    }
    m_scene.objects.push_back(std::move(declared));
    m_pending = {};
    return ok;
}

Expected<void> SceneParser::once(bool already, std::string_view what) const
{
    if (!already)
        return ok;
    return error("a second " + std::string(what) + " for object '" + m_scene.objects.back().name +
                 "'; expected one at most");
}

Expected<DatFile> SceneParser::read_file(std::string_view name, std::size_t minimum_points)
{
    Expected<DatFile> read = m_read(std::string(name));
    if (!read)
        return error("cannot use " + quote_field(name) + ": " + read.error().to_string());
    if (read->point_count() < minimum_points)
        return error("cannot use " + quote_field(name) + ": expected at least " + std::to_string(minimum_points) +
                     " points");
    return read;
}

Expected<void> SceneParser::parse_shape(const Fields& fields)
{
    if (auto outcome = once(object().has_drawing(), "SHAPE or KEYS"); !outcome)
        return outcome.error();
    if (fields.size() != 2)
        return error("expected 'SHAPE FILE.dat'");
    const Expected<DatFile> file = read_file(fields[1], 1);
    if (!file)
        return file.error();
    object().shape = graphic_from(*file);
    return ok;
}

Expected<void> SceneParser::parse_keys(const Fields& fields)
{
    if (auto outcome = once(object().has_drawing(), "SHAPE or KEYS"); !outcome)
        return outcome.error();
    if (fields.size() < 3)
        return error("expected 'KEYS KEY1.dat KEY2.dat [FROM F TO G]'");
    const Expected<DatFile> key1 = read_file(fields[1]);
    if (!key1)
        return key1.error();
    const Expected<DatFile> key2 = read_file(fields[2]);
    if (!key2)
        return key2.error();
    SceneKeys keys{equalise_key_frames(graphic_from(*key1), graphic_from(*key2)), {}, {}, {}, {}, {0, m_scene.last_frame}};
    Clauses clauses(fields, 3);
    while (!clauses.done())
        if (auto outcome = span_clause(clauses, "KEYS", keys.frames); !outcome)
            return outcome.error();
    if (auto outcome = check_span(keys.frames, "KEYS"); !outcome)
        return outcome.error();
    if (keys.frames.from == keys.frames.to)
        return error("KEYS FROM " + std::to_string(keys.frames.from) + " TO " + std::to_string(keys.frames.to) +
                     ": expected FROM before TO (KEY1 at FROM, KEY2 at TO)");
    object().keys = std::move(keys);
    return ok;
}

Expected<void> SceneParser::parse_paths(const Fields& fields)
{
    if (auto outcome = once(m_pending.paths.has_value(), "PATHS"); !outcome)
        return outcome.error();
    if (fields.size() != 3)
        return error("expected 'PATHS FIRST.dat LAST.dat'");
    std::array<PendingPath, 2> paths;
    for (std::size_t i = 0; i < 2; ++i) {
        Expected<DatFile> file = read_file(fields[1 + i]);
        if (!file)
            return file.error();
        paths[i].file = std::move(*file);
        paths[i].name = std::string(fields[1 + i]);
        paths[i].line = m_line;
    }
    m_pending.paths = std::move(paths);
    return ok;
}

Expected<void> SceneParser::parse_staff(const Fields& fields)
{
    if (auto outcome = once(object().own_staff, "STAFF"); !outcome)
        return outcome.error();
    if (fields.size() != 5)
        return error("expected 'STAFF T C B A' (four values from -1 to 1)");
    StaffValues staff;
    for (std::size_t i = 0; i < staff_lines.size(); ++i) {
        const std::string what = ascii_lower_case(staff_line_name(staff_lines[i]));
        const Expected<double> value = number(fields[1 + i], what);
        if (!value)
            return value.error();
        if (!limits::staff_value.contains(*value))
            return error(what + " " + quote_field(fields[1 + i]) + " is outside " + range_text(limits::staff_value));
        staff[staff_lines[i]] = *value;
    }
    object().staff = staff;
    object().own_staff = true;
    // Parts declared later inherit it (parse_object copies the parent's values).
    return ok;
}

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

Expected<void> SceneParser::parse_joint(const Fields& fields)
{
    if (fields.size() != 3 && fields.size() != 5)
        return error("expected 'JOINT NAME INDEX[-INDEX2] [TOLERANCE D]'");
    SceneJoint joint;
    joint.name = std::string(fields[1]);
    joint.line = m_line;
    // INDEX, or INDEX-INDEX2: the centroid of a contact region of points.
    const std::string_view range = fields[2];
    const std::size_t dash = range.find('-', 1);
    const std::optional<std::size_t> index = parse_count_value(range.substr(0, dash));
    const std::optional<std::size_t> last =
        dash == std::string_view::npos ? index : parse_count_value(range.substr(dash + 1));
    // No drawing has more points than a .dat file holds: a larger index is named as it was written.
    const auto valid = [](const std::optional<std::size_t>& value) { return value && *value >= 1 && *value <= max_dat_points; };
    if (!valid(index) || !valid(last))
        return error("expected the joint's point INDEX or points INDEX-INDEX2, whole numbers from 1 to " +
                     std::to_string(max_dat_points) + ", found " + quote_field(range));
    if (*last < *index)
        return error("joint points " + quote_field(range) + " run backwards; expected INDEX-INDEX2 with INDEX <= INDEX2");
    joint.point = *index - 1;
    joint.last_point = *last - 1;
    if (fields.size() == 5) {
        if (!equals_ignoring_case(fields[3], "TOLERANCE"))
            return error("expected TOLERANCE D after the index, found " + quote_field(fields[3]));
        const Expected<double> tolerance = number(fields[4], "TOLERANCE");
        if (!tolerance)
            return tolerance.error();
        if (*tolerance < 0.0)
            return error("TOLERANCE " + quote_field(fields[4]) + " is negative; expected a distance >= 0");
        joint.tolerance = *tolerance;
    }
    for (const SceneJoint& other : object().joints)
        if (other.name == joint.name)
            return error("joint " + quote_field(joint.name) + " is named twice in object '" + object().name +
                         "' (line " + std::to_string(other.line) + "); a joint joins two parts, each naming it once");
    object().joints.push_back(std::move(joint));
    return ok;
}

Expected<void> SceneParser::parse_rigid(const Fields& fields)
{
    if (fields.size() != 1)
        return error("expected 'RIGID' alone on its line, found " + quote_field(fields[1]) + " after it");
    if (Expected<void> first = once(object().rigid(), "RIGID"); !first)
        return first;
    object().rigid_line = m_line;
    return ok;
}

// A RIGID part turns from its KEY1 drawing to its KEY2 drawing: it needs both, congruent.
Expected<void> SceneParser::finish_rigid()
{
    const SceneObject& current = object();
    if (!current.rigid())
        return ok;
    if (!current.keys)
        return error("RIGID part '" + current.name +
                         "' has no KEYS; expected KEYS KEY1.dat KEY2.dat, the two poses it turns between",
                     current.rigid_line);
    const EqualisedKeys& keys = current.keys->keys;
    const RigidTurn turn = fit_rigid_turn(keys.key1.all_points(), keys.key2.all_points());
    // A part of no size (every point at one place) is allowed 0: the round-off of its coordinates,
    // not the drawing, decided (4.6e-16 off refused it).
    const double allowed = rigid_congruence * turn.size;
    double largest = 0.0;
    for (const Graphic* key : {&keys.key1, &keys.key2})
        for (const GraphicPart& part : key->parts)
            for (const Vec3& point : part.points)
                largest = std::max(largest, largest_coordinate(point));
    if (at_most_within_round_off(turn.worst_deviation, allowed, largest))
        return ok;
    return error("RIGID part '" + current.name + "': its KEY2 drawing is not its KEY1 drawing turned and moved: point " +
                     std::to_string(turn.worst_point + 1) + " is " + significant_number(turn.worst_deviation) +
                     " off; expected within 1e-4 of its size (" + significant_number(turn.size) + ")",
                 current.rigid_line);
}

Expected<double> SceneParser::number(std::string_view field, const std::string& what) const
{
    const std::optional<double> parsed = parse_number(field);
    if (!parsed || !std::isfinite(*parsed) || std::abs(*parsed) > max_dat_magnitude)
        return error("expected a number with |value| <= 1e9 for " + what + ", found " + quote_field(field));
    return *parsed;
}

Expected<int> SceneParser::frame(std::string_view field, const std::string& what) const
{
    const std::optional<std::size_t> parsed = parse_count_value(field);
    if (!parsed || *parsed > static_cast<std::size_t>(m_scene.last_frame))
        return error("expected a frame from 0 to " + std::to_string(m_scene.last_frame) + " after " + what +
                     ", found " + quote_field(field));
    return static_cast<int>(*parsed);
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

// What needs the whole object: the paths of KEYS and MOVE take its staff values; every joint's
// point lies in its drawing.
Expected<void> SceneParser::finish_object()
{
    SceneObject& current = object();
    if (m_pending.paths && !current.keys)
        return error("PATHS without KEYS in object '" + current.name + "'; expected KEYS KEY1.dat KEY2.dat",
                     m_pending.paths->front().line);
    if (current.keys) {
        const EqualisedKeys& keys = current.keys->keys;
        if (m_pending.paths) {
            const std::array<PathEnd, 2> ends{PathEnd::first, PathEnd::last};
            std::array<ControlPoints, 2> paths;
            for (std::size_t i = 0; i < 2; ++i) {
                const PendingPath& path = (*m_pending.paths)[i];
                Expected<ControlPoints> points =
                    i == 1 && keys.key1.is_closed()
                        ? Expected<ControlPoints>(control_points_from(path.file, current.staff))
                        : point_path_from(path.file, path.name, ends[i], keys, current.staff);
                if (!points)
                    return error("cannot use " + quote_field(path.name) + ": " + points.error().to_string(), path.line);
                paths[i] = std::move(*points);
            }
            current.keys->first_path = std::move(paths[0]);
            current.keys->last_path = std::move(paths[1]);
            current.keys->first_slopes = (*m_pending.paths)[0].file.slopes;
            current.keys->last_slopes = (*m_pending.paths)[1].file.slopes;
        } else {
            current.keys->first_path = {{keys.key1.first_point(), current.staff}, {keys.key2.first_point(), current.staff}};
            current.keys->last_path = {{keys.key1.last_point(), current.staff}, {keys.key2.last_point(), current.staff}};
        }
    }
    if (m_pending.move_path) {
        current.move->path = control_points_from(m_pending.move_path->file, current.staff);
        if (current.move->align)
            if (Expected<void> align = check_align_path(*current.move, *m_pending.move_path); !align)
                return align;
    }
    const Graphic* drawing = current.first_drawing();
    const std::size_t points = drawing == nullptr ? 0 : drawing->point_count();
    for (const SceneJoint& joint : current.joints)
        if (joint.last_point >= points)
            return error("joint " + quote_field(joint.name) + " names point " + std::to_string(joint.last_point + 1) +
                             " of object '" + current.name + "', whose drawing has " + std::to_string(points) +
                             " points" + (current.keys ? " (after adding points)" : ""),
                         joint.line);
    return finish_rigid();
}

} // namespace

double default_joint_tolerance(const Scene& scene)
{
    BoundingBox box;
    for (const SceneObject& object : scene.objects)
        if (const Graphic* drawing = object.first_drawing())
            for (const GraphicPart& part : drawing->parts)
                box.add(part.points);
    return box.empty() ? 0.0 : 0.001 * length(box.high() - box.low());
}

Expected<Scene> parse_scene(std::string_view text, const std::string& file_name, const SceneFileReader& read,
                            const StaffValues& default_staff)
{
    return SceneParser(file_name, read, default_staff).parse(text);
}

Expected<Scene> read_scene_file(const std::filesystem::path& name, const StaffValues& default_staff,
                                std::vector<std::filesystem::path>* inputs)
{
    // "-" is standard input, read as a keystroke script is (a pipe, once, to its end); its SHAPE
    // and KEYS files are found from the current folder.
    const bool standard_input = name == "-";
    Expected<std::string> text = standard_input ? read_script_text(name) : read_text_file(name);
    if (!text)
        return text.error();
    if (inputs != nullptr)
        inputs->push_back(name);
    const std::filesystem::path folder = name.parent_path();
    const SceneFileReader read = [&folder, inputs](const std::string& file) {
        const std::filesystem::path relative(file);
        const std::filesystem::path path = relative.is_absolute() ? relative : folder / relative;
        if (inputs != nullptr)
            inputs->push_back(path);
        return read_dat_file(path, 1);
    };
    return parse_scene(*text, standard_input ? "standard input" : name.string(), read, default_staff);
}

} // namespace apcs
