#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_event.h"
#include "apcs/formats/script_goal.h"
#include "apcs/formats/script_input.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// A keystroke script (SPEC §3): a line starting with "TEXT " types the rest of the line
// literally; any other line holds tokens — a printable character, or a physical key's script name
// (ENTER, ESC, … CTRL-L: physical_key.h); ';' starts a comment. START, GOAL (script_goal.h),
// INPUT (script_input.h) and OPTIONS lines are a lesson's, an exercise's and a recording's, kept
// by parse_captioned_key_script. Returns the events, or the first
// problem with its line, named as `file_name`.
// A longer script is refused before it is read: 16 MiB is 16 million keystrokes or more, and
// each takes sizeof(KeyEvent) = 8 bytes once parsed.
inline constexpr std::uintmax_t max_key_script_bytes = 16ull << 20;

[[nodiscard]] Expected<std::vector<KeyEvent>> parse_key_script(std::string_view text, const std::string& file_name);

// A comment that starts with ";;" is a caption for a class: shown when a replay has played the
// keys before it (`before_event` of them), until the next caption.
struct ScriptCaption {
    std::size_t before_event = 0;
    std::string text;
    bool operator==(const ScriptCaption&) const = default;
};

// The widest caption a script may hold, in terminal columns (a wide character counts two): the
// key-hint row of the 80x24 screen less its first column, which every text row of the session
// leaves blank. A wider caption is refused when the script is read, not cut on the screen.
inline constexpr int max_caption_columns = 79;

// The keys one TEXT line types: a paced replay plays them as one step.
struct TypedLine {
    std::size_t first_event = 0;
    std::size_t event_count = 0;
    bool operator==(const TypedLine&) const = default;
};

// The session options a script was made with: its OPTIONS line, before the first key, the words
// after OPTIONS as the command line gives them ("--step 0.1 --inbetweens 20"). --record writes
// the line; a replay takes each option the command line does not give (script_options.h). Empty
// words: no OPTIONS line.
struct ScriptOptions {
    std::string words;
    int line_number = 0;
    bool operator==(const ScriptOptions&) const = default;
};

// A script with its captions and its TEXT lines, in order.
struct KeyScript {
    std::vector<KeyEvent> events;
    std::vector<int> event_lines; // the line each event is on, for FILE:LINE (apcs grade)
    std::vector<ScriptCaption> captions;
    std::vector<int> caption_lines; // the line of each caption
    std::vector<TypedLine> typed_lines;
    std::vector<ScriptGoal> goals; // GOAL lines (script_goal.h), in order
    std::vector<ScriptInput> inputs; // INPUT lines (script_input.h): the files an exercise is made for
    ScriptOptions options;           // its OPTIONS line
    // The keys before the script's START line (SPEC §3.1): the opening prompts' answers, which a
    // paced replay plays as one step when it begins; 0 without START.
    std::size_t preamble_end = 0;
};

// parse_key_script, keeping the captions (each at most max_caption_columns wide, or FILE:LINE:
// the problem) and the TEXT lines. A script of more than `most_keys` keys is refused at the line
// that passes it ("too long: more than N keys, at most N are read"), never held whole (apcs grade).
[[nodiscard]] Expected<KeyScript> parse_captioned_key_script(
    std::string_view text, const std::string& file_name,
    std::size_t most_keys = std::numeric_limits<std::size_t>::max());

// The caption shown once `played` keys of `script` are played: the last one reached, or none.
const ScriptCaption* caption_at(const KeyScript& script, std::size_t played);

// How many of `script`'s events the step starting at event `first` plays: the preamble's keys
// (before START) together, a TEXT line's keys together, any other key alone; 0 at the end of the
// script.
std::size_t step_length(const KeyScript& script, std::size_t first);

// What the step starting at event `first` plays, as a screencast names it: the TEXT line
// ("TEXT 0 90 100"), the key's script token ("ENTER", "4") or "START" for the preamble; empty at
// the end of the script.
std::string step_label(const KeyScript& script, std::size_t first);

// A character a script names by a token of its own ("L", "6"): printable, not a blank.
bool is_token_character(char32_t character);

// The typed text `pending_text` as a script's TEXT line, emptying it: "TEXT way1.dat\n" (its
// trailing spaces as SPACE lines, which no editor strips); empty for no text.
std::string take_text_line(std::string& pending_text);

// Writes events as a script that parse_key_script reads back to the same events: runs of
// printable characters typed in a line become TEXT lines.
std::string format_key_script(const std::vector<KeyEvent>& events);

} // namespace apcs
