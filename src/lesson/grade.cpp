#include "apcs/lesson/grade.h"

#include "apcs/base/utf8.h"
#include "apcs/formats/physical_key.h"

#include <algorithm>

namespace apcs {

namespace {

// A goal as the exercise states it: where its line stands in the file is the recording's own.
bool same_goal(ScriptGoal left, ScriptGoal right)
{
    for (ScriptGoal* goal : {&left, &right}) {
        goal->before_event = 0;
        goal->answer_end = 0;
        goal->line_number = 0;
        goal->captions_before = 0;
    }
    return left == right;
}

bool same_input(const ScriptInput& left, const ScriptInput& right)
{
    return left.name == right.name && left.crc32 == right.crc32;
}

// The TEXT line of `script` whose keys start at event `first`, if one does.
const TypedLine* typed_line_at(const KeyScript& script, std::size_t first)
{
    const auto typed = std::ranges::find(script.typed_lines, first, &TypedLine::first_event);
    return typed == script.typed_lines.end() ? nullptr : &*typed;
}

// One key's token: a ';' alone would start a comment in a script, so it is a TEXT line's.
std::string key_token(const KeyEvent& key)
{
    if (key.key != Key::character) {
        const PhysicalKey* row = find_physical_key(key.key);
        return row == nullptr ? std::string() : std::string(row->script_name);
    }
    std::string token = key.character == U';' ? "TEXT " : "";
    append_utf8(token, key.character);
    return token;
}

// The keys of the TEXT line starting at `first`, up to `end`, as "TEXT " and the text they type.
std::string text_token(const KeyScript& script, std::size_t first, std::size_t end)
{
    std::string token = "TEXT ";
    for (std::size_t event = first; event < end; ++event)
        append_utf8(token, script.events[event].key == Key::space ? U' ' : script.events[event].character);
    return token;
}

GradeRow row_of(const GradeNames& names, const ScriptGoal& goal, GradeVerdict reached)
{
    return {names.recording, names.exercise, goal_line(goal), reached, {}, {}, {}, goal_text(goal), {}};
}

std::string line_of(const std::string& file, int line) { return file + ":" + std::to_string(line); }

// The line of event `event` in `script`, or of its last one past the end (0 when it has none).
int event_line(const KeyScript& script, std::size_t event)
{
    if (script.event_lines.empty())
        return 0;
    return script.event_lines[std::min(event, script.event_lines.size() - 1)];
}

std::optional<ScriptDeparture> inputs_departure(const KeyScript& exercise, const KeyScript& recording,
                                                const std::string& name)
{
    for (std::size_t k = 0; k < std::max(exercise.inputs.size(), recording.inputs.size()); ++k) {
        if (k >= recording.inputs.size())
            return ScriptDeparture{0, "no INPUT " + exercise.inputs[k].name + " line, as " +
                                          line_of(name, exercise.inputs[k].line_number) + " has"};
        if (k >= exercise.inputs.size())
            return ScriptDeparture{recording.inputs[k].line_number, "an INPUT line the exercise does not have"};
        if (!same_input(exercise.inputs[k], recording.inputs[k]))
            return ScriptDeparture{recording.inputs[k].line_number,
                                   "INPUT " + recording.inputs[k].name + " where " +
                                       line_of(name, exercise.inputs[k].line_number) + " has INPUT " +
                                       exercise.inputs[k].name + " with its checksum"};
    }
    return std::nullopt;
}

std::optional<ScriptDeparture> goals_departure(const KeyScript& exercise, const KeyScript& recording,
                                               const std::string& name)
{
    for (std::size_t k = 0; k < std::max(exercise.goals.size(), recording.goals.size()); ++k) {
        if (k >= recording.goals.size())
            return ScriptDeparture{0, "no " + goal_line(exercise.goals[k]) + " line, as " +
                                          line_of(name, exercise.goals[k].line_number) + " has"};
        const ScriptGoal& goal = recording.goals[k];
        if (k >= exercise.goals.size())
            return ScriptDeparture{goal.line_number, "a GOAL line the exercise does not have"};
        if (!same_goal(exercise.goals[k], goal) || exercise.goals[k].captions_before != goal.captions_before)
            return ScriptDeparture{goal.line_number, goal_line(goal) + " where " +
                                                         line_of(name, exercise.goals[k].line_number) + " has " +
                                                         goal_line(exercise.goals[k]) + " after the same captions"};
    }
    return std::nullopt;
}

std::string token_or_end(const KeyScript& script, std::size_t event, std::size_t end)
{
    return event < end ? "'" + key_token(script.events[event]) + "'" : "the GOAL line";
}

// The keys up to the first GOAL line, and where START stands among them.
std::optional<ScriptDeparture> keys_departure(const KeyScript& exercise, const KeyScript& recording,
                                              const std::string& name)
{
    const std::size_t exercise_end = exercise.goals.front().before_event;
    const std::size_t recording_end = recording.goals.front().before_event;
    for (std::size_t event = 0; event < std::max(exercise_end, recording_end); ++event) {
        const bool same = event < exercise_end && event < recording_end &&
                          exercise.events[event] == recording.events[event];
        if (!same)
            return ScriptDeparture{event < recording_end ? event_line(recording, event)
                                                         : recording.goals.front().line_number,
                                   token_or_end(recording, event, recording_end) + " where " +
                                       line_of(name, event < exercise_end ? event_line(exercise, event)
                                                                          : exercise.goals.front().line_number) +
                                       " has " + token_or_end(exercise, event, exercise_end) +
                                       " (before the first GOAL line the keys are the exercise's)"};
    }
    if (exercise.preamble_end != recording.preamble_end)
        return ScriptDeparture{event_line(recording, recording.preamble_end),
                               "START after " + std::to_string(recording.preamble_end) +
                                   " keys, where the exercise has it after " + std::to_string(exercise.preamble_end)};
    return std::nullopt;
}

// The captions: the same, in order; those before the first GOAL line after the same keys.
std::optional<ScriptDeparture> captions_departure(const KeyScript& exercise, const KeyScript& recording,
                                                  const std::string& name)
{
    const std::size_t pinned = exercise.goals.front().captions_before;
    for (std::size_t k = 0; k < std::max(exercise.captions.size(), recording.captions.size()); ++k) {
        if (k >= recording.captions.size())
            return ScriptDeparture{0, "no caption ';; " + exercise.captions[k].text + "', as " +
                                          line_of(name, exercise.caption_lines[k]) + " has"};
        const int line = recording.caption_lines[k];
        if (k >= exercise.captions.size())
            return ScriptDeparture{line, "a caption the exercise does not have"};
        if (exercise.captions[k].text != recording.captions[k].text)
            return ScriptDeparture{line,
                                   "a caption that differs from " + line_of(name, exercise.caption_lines[k]) + "'s"};
        if (k < pinned && exercise.captions[k].before_event != recording.captions[k].before_event)
            return ScriptDeparture{line,
                                   "the caption after other keys than at " + line_of(name, exercise.caption_lines[k])};
    }
    return std::nullopt;
}

// A number as a spreadsheet reads one: a sign, digits with at most one point, an exponent.
bool plain_number(std::string_view text)
{
    std::size_t at = text.find_first_not_of("+-") == 1 ? 1 : 0;
    const auto digits = [&text, &at] {
        const std::size_t from = at;
        while (at < text.size() && text[at] >= '0' && text[at] <= '9')
            ++at;
        return at - from;
    };
    std::size_t mantissa = digits();
    if (at < text.size() && text[at] == '.') {
        ++at;
        mantissa += digits();
    }
    if (mantissa == 0)
        return false;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        const bool signed_exponent = at + 1 < text.size() && (text[at + 1] == '+' || text[at + 1] == '-');
        at += signed_exponent ? 2u : 1u;
        if (digits() == 0)
            return false;
    }
    return at == text.size();
}

// What Excel, LibreOffice and Google Sheets read as the start of a formula (OWASP's list), and an
// apostrophe, so that a program dropping the first apostrophe gets every field back as it was.
bool formula_like(std::string_view text)
{
    return !text.empty() && std::string_view("=+-@\t\r'").find(text.front()) != std::string_view::npos &&
           !plain_number(text);
}

} // namespace

std::string_view verdict_name(GradeVerdict verdict)
{
    switch (verdict) {
    case GradeVerdict::yes: return "yes";
    case GradeVerdict::no: return "no";
    case GradeVerdict::other: return "other";
    case GradeVerdict::error: return "error";
    }
    return "error";
}

std::string csv_field(std::string_view text)
{
    const std::string field = formula_like(text) ? "'" + std::string(text) : std::string(text);
    if (field.find_first_of(",\"\r\n") == std::string::npos)
        return field;
    std::string quoted = "\"";
    for (const char c : field) {
        quoted += c;
        if (c == '"')
            quoted += '"';
    }
    return quoted + '"';
}

std::string grade_csv_line(const GradeRow& row)
{
    return csv_field(row.file) + ',' + csv_field(row.exercise) + ',' + csv_field(row.goal) + ',' +
           std::string(verdict_name(row.reached)) + ',' + csv_field(row.value) + ',' + csv_field(row.keys) + ',' +
           csv_field(row.options) + '\n';
}

std::optional<ScriptDeparture> departure_from_exercise(const KeyScript& exercise, const KeyScript& recording,
                                                       const std::string& exercise_name)
{
    if (std::optional<ScriptDeparture> found = inputs_departure(exercise, recording, exercise_name))
        return found;
    if (std::optional<ScriptDeparture> found = goals_departure(exercise, recording, exercise_name))
        return found;
    if (exercise.goals.empty())
        return std::nullopt;
    if (std::optional<ScriptDeparture> found = keys_departure(exercise, recording, exercise_name))
        return found;
    return captions_departure(exercise, recording, exercise_name);
}

bool is_blank_recording(const KeyScript& recording)
{
    return recording.events.empty() && recording.captions.empty() && recording.goals.empty() &&
           recording.inputs.empty() && recording.options.words.empty() && recording.preamble_end == 0;
}

KeyScript with_answers_to_next_goal(KeyScript recording)
{
    std::vector<ScriptGoal>& goals = recording.goals;
    for (std::size_t k = 0; k < goals.size(); ++k)
        goals[k].answer_end = k + 1 < goals.size() ? goals[k + 1].before_event : recording.events.size();
    return recording;
}

std::string answer_field(const KeyScript& script, const ScriptGoal& goal)
{
    const std::string tokens = answer_tokens(script, goal);
    const std::u32string characters = decode_utf8(tokens);
    if (characters.size() <= most_answer_characters)
        return tokens;
    std::string cut;
    for (std::size_t k = 0; k < most_answer_characters; ++k)
        append_utf8(cut, characters[k]);
    const std::size_t keys = std::min(goal.answer_end, script.events.size()) - goal.before_event;
    return cut + "\u2026 (" + std::to_string(keys) + " keys)";
}

std::string answer_tokens(const KeyScript& script, const ScriptGoal& goal)
{
    std::string tokens;
    const std::size_t end = std::min(goal.answer_end, script.events.size());
    std::size_t event = goal.before_event;
    while (event < end) {
        const TypedLine* typed = typed_line_at(script, event);
        const std::size_t next = typed == nullptr ? event + 1 : std::min(event + typed->event_count, end);
        const std::string token = typed == nullptr ? key_token(script.events[event]) : text_token(script, event, next);
        tokens += (tokens.empty() ? "" : " ") + token;
        event = std::max(next, event + 1);
    }
    return tokens;
}

std::string keys_after_goals(const KeyScript& recording)
{
    if (recording.goals.empty())
        return {};
    ScriptGoal all_answers = recording.goals.front();
    all_answers.answer_end = recording.events.size();
    return answer_tokens(recording, all_answers);
}

std::vector<GradeRow> replayed_rows(const GradeNames& names, const KeyScript& recording,
                                    const std::vector<GoalOutcome>& outcomes)
{
    std::vector<GradeRow> rows;
    for (std::size_t index = 0; index < recording.goals.size(); ++index) {
        const ScriptGoal& goal = recording.goals[index];
        GradeRow row = row_of(names, goal, GradeVerdict::no);
        row.keys = answer_field(recording, goal);
        const auto outcome = std::ranges::find(outcomes, index, &GoalOutcome::goal);
        if (outcome != outcomes.end()) {
            row.reached = outcome->verdict == GoalOutcome::Verdict::reached ? GradeVerdict::yes : GradeVerdict::no;
            row.value = outcome->progress.value;
            row.said = outcome->progress.said;
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<GradeRow> blank_rows(const GradeNames& names, const KeyScript& exercise)
{
    return unreplayed_rows(names, exercise, GradeVerdict::no);
}

std::vector<GradeRow> unreplayed_rows(const GradeNames& names, const KeyScript& exercise, GradeVerdict verdict)
{
    std::vector<GradeRow> rows;
    for (const ScriptGoal& goal : exercise.goals)
        rows.push_back(row_of(names, goal, verdict));
    return rows;
}

} // namespace apcs
