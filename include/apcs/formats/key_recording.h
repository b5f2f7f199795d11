#pragma once

#include "apcs/formats/key_script.h"

#include <string>
#include <vector>

namespace apcs {

// What --record writes (SPEC §3.1): the keys the session handled, each marked typed text or not,
// and the lines of the script that made it an exercise or a lesson, in the order they were met:
// its INPUT lines first, then the OPTIONS the session ran with, START after the opening answers,
// each caption and GOAL where the replay reached it. The replay controls (PgDn, PgUp, Home) never reach the session: they are not keys
// of it. Read back by parse_captioned_key_script, it replays the same keys to the same goals, so
// `apcs --keys` and `apcs grade` recheck it.
class KeyRecording {
public:
    void add_inputs(std::vector<ScriptInput> inputs) { m_inputs = std::move(inputs); }
    // The session's options, as an OPTIONS line writes them after the INPUT lines; none if empty.
    void add_options(std::string words) { m_options = std::move(words); }
    // A key, and whether the session took it as typed text (a prompt's answer, a staff value).
    void add_key(const KeyEvent& key, bool typed_text);
    void add_start() { m_entries.push_back({Entry::Kind::start, {}, false, {}}); }
    void add_caption(std::string text) { m_entries.push_back({Entry::Kind::caption, {}, false, std::move(text)}); }
    void add_goal(const ScriptGoal& goal) { m_entries.push_back({Entry::Kind::goal, {}, false, goal_line(goal)}); }
    // One token a line, typed text as TEXT lines (a ';' typed alone: "TEXT ;").
    std::string text() const;

private:
    struct Entry {
        enum class Kind { key, start, caption, goal };
        Kind kind = Kind::key;
        KeyEvent key;
        bool typed_text = false;
        std::string line; // a caption's text, a GOAL line
    };
    std::vector<ScriptInput> m_inputs;
    std::string m_options;
    std::vector<Entry> m_entries;
};

} // namespace apcs
