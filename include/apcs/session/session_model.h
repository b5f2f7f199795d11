#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/base/diagnostic.h"
#include "apcs/session/session_files.h"
#include "apcs/session/session_settings.h"
#include "apcs/screens/text_console.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace apcs {

// One graphic point's path as the session has it: the file it came from (its text as read, so
// that accepting rewrites it with its comments), its control points and its end slopes.
struct SessionPath {
    std::string name;
    std::string text;
    ControlPoints points;
    EndSlopes slopes;
    // The file's own SLOPES line (SPEC §2.1): an empty slope answer takes it when --slopes is not given.
    std::optional<EndSlopes> file_slopes;
    // A long path's evaluation arrays, made while the slopes prompt waits (make_room); the editor
    // takes them.
    EvaluatedPath evaluation_room;
};

// The files the session wrote, in order, for the last screen; and the last write that failed.
class WrittenFiles {
public:
    void add(const std::string& name);
    const std::vector<std::string>& names() const { return m_names; }
    // ok, or the last write that failed.
    const Expected<void>& outcome() const { return m_outcome; }
    void set_problem(const Diagnostic& problem) { m_outcome = problem; }

private:
    std::vector<std::string> m_names;
    std::unordered_set<std::string> m_known; // m_names', to find one among 10^6 at once
    Expected<void> m_outcome = ok;
};

// What the steps made that the steps after them read: the key frames, the view, both paths.
// What one step alone uses stays in that step (session_steps.h).
struct SessionModel {
    std::array<std::string, 2> key_names;
    std::array<Graphic, 2> key_frames;
    // Both keys with equal point counts (addpoint.c): what the paths and the fitting use.
    EqualisedKeys keys;
    std::size_t point_count = 0;
    ViewAngles view_angles;
    int delay_ms = 200;
    // 0: the first graphic point's path; 1: the last's.
    std::array<SessionPath, 2> paths;
    WrittenFiles written;
};

// What a step may use while it acts: the settings, the files, the model and the console.
struct StepContext {
    const SessionSettings& settings;
    SessionFiles& files;
    SessionModel& model;
    TextConsole& console;
    // What the last key did, said once on the message line.
    std::string& notice;

    void say(const std::string& line) { console.print_line(line); }
    // Writes through SessionFiles; a failure is remembered as the model's write problem.
    [[nodiscard]] Expected<void> write_file(const std::string& name, const std::string& content);
    PathSettings path_settings(int path) const;
};

} // namespace apcs
