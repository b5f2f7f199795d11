#pragma once

// The scene file's parser (SPEC §8), one class whose lines are read in three files:
// scene_file.cpp (the scene's and the object's own lines, and what needs the whole object),
// scene_file_motions.cpp (MOVE, ROTATE, ROLL, SCALE and their clauses) and scene_file_joints.cpp
// (JOINT and RIGID).
#include "apcs/scene/scene_file.h"

#include "apcs/formats/dat_file.h"
#include "apcs/formats/text_fields.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs::scene_parsing {

using Fields = std::vector<std::string_view>;

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

} // namespace apcs::scene_parsing
