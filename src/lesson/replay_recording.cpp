#include "apcs/lesson/replay_driver.h"

#include <algorithm>

// What --record writes of a replay: every key the session handled, with the script's START,
// caption and GOAL lines where the replay met them.
namespace apcs {

void ReplayDriver::to_session(const KeyEvent& key)
{
    if (m_hooks.keeps_recording) {
        record_lines(m_recording, m_lines_recorded, m_played);
        m_recording.add_key(key, m_session->takes_typed_text());
    }
    m_handled.push_back(key);
    m_work_done += m_session->key_work(key);
    m_session->handle(key);
}

std::vector<ReplayDriver::ScriptLine> ReplayDriver::script_lines(const KeyScript& script)
{
    std::vector<ScriptLine> lines;
    if (script.preamble_end > 0)
        lines.push_back({script.preamble_end, ScriptLine::Kind::start, 0});
    for (std::size_t caption = 0; caption < script.captions.size(); ++caption)
        lines.push_back({script.captions[caption].before_event, ScriptLine::Kind::caption, caption});
    for (std::size_t goal = 0; goal < script.goals.size(); ++goal)
        lines.push_back({script.goals[goal].before_event, ScriptLine::Kind::goal, goal});
    // At one key, in the script's order: START first, then captions and GOAL lines as the goals'
    // captions_before place them (caption i before goal g when i < captions_before).
    const auto rank = [&script](const ScriptLine& line) -> std::size_t {
        switch (line.kind) {
        case ScriptLine::Kind::start: return 0;
        case ScriptLine::Kind::caption: return 2 * line.index + 1;
        case ScriptLine::Kind::goal: return 2 * script.goals[line.index].captions_before;
        }
        return 0;
    };
    std::stable_sort(lines.begin(), lines.end(), [&rank](const ScriptLine& a, const ScriptLine& b) {
        return a.before_event < b.before_event || (a.before_event == b.before_event && rank(a) < rank(b));
    });
    return lines;
}

void ReplayDriver::record_lines(KeyRecording& recording, std::size_t& lines_recorded, std::size_t event) const
{
    for (; lines_recorded < m_script_lines.size() && m_script_lines[lines_recorded].before_event <= event;
         ++lines_recorded) {
        const ScriptLine& line = m_script_lines[lines_recorded];
        // The student's keys at a goal come before the lines after its GOAL line (a closing caption).
        if (waiting_goal() && line.before_event == event && line.kind != ScriptLine::Kind::start &&
            lines_recorded > m_waiting_goal_line)
            return;
        if (!line_met(line))
            return;
        switch (line.kind) {
        case ScriptLine::Kind::start: recording.add_start(); break;
        case ScriptLine::Kind::caption: recording.add_caption(m_script.captions[line.index].text); break;
        case ScriptLine::Kind::goal: recording.add_goal(m_script.goals[line.index]); break;
        }
    }
}

bool ReplayDriver::line_met(const ScriptLine& line) const
{
    if (!paced())
        return true;
    switch (line.kind) {
    case ScriptLine::Kind::start: return true;
    case ScriptLine::Kind::caption: return line.index < m_captions_shown;
    case ScriptLine::Kind::goal: return task_shown(line.index);
    }
    return true;
}

KeyRecording ReplayDriver::recording() const
{
    KeyRecording recording = m_recording;
    std::size_t lines_recorded = m_lines_recorded;
    record_lines(recording, lines_recorded, m_played);
    return recording;
}

} // namespace apcs
