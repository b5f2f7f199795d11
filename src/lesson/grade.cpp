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
    return {names.recording, names.exercise, goal_line(goal), reached, {}, {}};
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
           std::string(verdict_name(row.reached)) + ',' + csv_field(row.value) + ',' + csv_field(row.keys) + '\n';
}

bool same_exercise(const KeyScript& exercise, const KeyScript& recording)
{
    return std::ranges::equal(exercise.goals, recording.goals, same_goal) &&
           std::ranges::equal(exercise.inputs, recording.inputs, same_input);
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

std::vector<GradeRow> replayed_rows(const GradeNames& names, const KeyScript& recording,
                                    const std::vector<GoalOutcome>& outcomes)
{
    std::vector<GradeRow> rows;
    for (std::size_t index = 0; index < recording.goals.size(); ++index) {
        const ScriptGoal& goal = recording.goals[index];
        GradeRow row = row_of(names, goal, GradeVerdict::no);
        row.keys = answer_tokens(recording, goal);
        const auto outcome = std::ranges::find(outcomes, index, &GoalOutcome::goal);
        if (outcome != outcomes.end()) {
            row.reached = outcome->verdict == GoalOutcome::Verdict::reached ? GradeVerdict::yes : GradeVerdict::no;
            row.value = outcome->progress.value;
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

std::vector<GradeRow> unreplayed_rows(const GradeNames& names, const KeyScript& exercise, GradeVerdict verdict)
{
    std::vector<GradeRow> rows;
    for (const ScriptGoal& goal : exercise.goals)
        rows.push_back(row_of(names, goal, verdict));
    return rows;
}

} // namespace apcs
