#include "apcs/scene/scene_file.h"
#include "scene_parser.h"
#include "apcs/scene/scene_joints.h"

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

namespace scene_parsing {

namespace {

Fields split(std::string_view content)
{
    Fields fields;
    for_each_field(content, [&](std::string_view field) { fields.push_back(field); });
    return fields;
}

} // namespace

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

} // namespace scene_parsing

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
    return scene_parsing::SceneParser(file_name, read, default_staff).parse(text);
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
