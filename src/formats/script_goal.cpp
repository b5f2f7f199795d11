#include "apcs/formats/script_goal.h"

#include "apcs/animation/input_limits.h"
#include "apcs/formats/number_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

namespace apcs {

namespace {

// A goal's point and distance, in world units: beyond 1e9 nothing is drawn (the .dat reader's
// limit), and below 0.01 the feedback, in two decimals, could not show it.
constexpr double most_goal_coordinate = 1e9;
constexpr double least_goal_distance = 0.01;

std::vector<std::string_view> words_of(std::string_view text)
{
    std::vector<std::string_view> words;
    while (true) {
        const std::size_t first = text.find_first_not_of(" \t");
        if (first == std::string_view::npos)
            return words;
        text.remove_prefix(first);
        const std::size_t end = std::min(text.find_first_of(" \t"), text.size());
        words.push_back(text.substr(0, end));
        text.remove_prefix(end);
    }
}

std::optional<double> number_of(std::string_view word)
{
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::string upper(std::string_view word)
{
    std::string text(word);
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
    return text;
}

std::string lower(std::string_view word)
{
    std::string text(word);
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::optional<StaffLine> staff_line_of(std::string_view word)
{
    for (const StaffLine line : staff_lines)
        if (upper(word) == staff_line_name(line))
            return line;
    return std::nullopt;
}

// The numbers of `words` from `first` on, or nullopt when one is not a number.
std::optional<std::vector<double>> numbers_of(const std::vector<std::string_view>& words, std::size_t first)
{
    std::vector<double> numbers;
    for (std::size_t index = first; index < words.size(); ++index) {
        const std::optional<double> number = number_of(words[index]);
        if (!number)
            return std::nullopt;
        numbers.push_back(*number);
    }
    return numbers;
}

// The goal the words name, or why not.
Expected<ScriptGoal> goal_of(const std::vector<std::string_view>& words)
{
    const std::string kind = words.empty() ? std::string() : upper(words[0]);
    ScriptGoal goal;
    if (kind == "VALUE") {
        const std::optional<StaffLine> line = words.size() > 1 ? staff_line_of(words[1]) : std::nullopt;
        const std::optional<std::vector<double>> range = numbers_of(words, 2);
        if (words.size() != 4 || !line || !range || (*range)[0] > (*range)[1])
            return Diagnostic{"", 0, "a staff line's name and LO <= HI after VALUE"};
        if (!limits::staff_value.contains((*range)[0]) || !limits::staff_value.contains((*range)[1]))
            return Diagnostic{"", 0, "LO and HI within the staff's -1 to +1"};
        goal.line = *line;
        goal.low = (*range)[0];
        goal.high = (*range)[1];
        return goal;
    }
    const std::size_t point_at = kind == "INBETWEEN" ? 2 : 1;
    const std::optional<std::vector<double>> numbers = numbers_of(words, point_at);
    if ((kind != "NEAR" && kind != "INBETWEEN") || words.size() != point_at + 4 || !numbers || (*numbers)[3] <= 0)
        return Diagnostic{"", 0, "a point X Y Z and a distance D > 0"};
    const auto beyond = [](double value) { return std::abs(value) > most_goal_coordinate; };
    if (std::any_of(numbers->begin(), numbers->end(), beyond))
        return Diagnostic{"", 0, "X, Y, Z and D of at most 1e9 in size"};
    if ((*numbers)[3] < least_goal_distance)
        return Diagnostic{"", 0, "a distance D of at least 0.01 (the feedback's precision)"};
    goal.kind = kind == "NEAR" ? ScriptGoal::Kind::near : ScriptGoal::Kind::inbetween;
    goal.point = {(*numbers)[0], (*numbers)[1], (*numbers)[2]};
    goal.within = (*numbers)[3];
    if (goal.kind == ScriptGoal::Kind::inbetween) {
        const std::optional<double> number = number_of(words[1]);
        if (!number || *number < 1 || *number != std::floor(*number) || *number > limits::inbetween_count.max)
            return Diagnostic{"", 0, "an in-between's number K from 1 to 100000 after INBETWEEN"};
        goal.inbetween = static_cast<std::size_t>(*number);
    }
    return goal;
}

std::string signed_value(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%+.2f", value);
    return text;
}

std::string point_text(const Vec3& point)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", point.x, point.y, point.z);
    return text;
}

} // namespace

Expected<ScriptGoal> parse_goal_line(std::string_view words, const std::string& file_name, int line_number)
{
    Expected<ScriptGoal> goal = goal_of(words_of(words.substr(0, words.find(';'))));
    if (!goal)
        return Diagnostic{file_name, line_number,
                          "expected GOAL VALUE NAME LO HI, GOAL NEAR X Y Z D or GOAL INBETWEEN K X Y Z D (" +
                              goal.error().message + "); found 'GOAL " + std::string(words) + "'"};
    goal->line_number = line_number;
    return goal;
}

Expected<void> goals_within_inbetweens(const std::vector<ScriptGoal>& goals, std::size_t inbetween_count,
                                       const std::string& file_name)
{
    for (const ScriptGoal& goal : goals) {
        if (goal.kind != ScriptGoal::Kind::inbetween || goal.inbetween <= inbetween_count)
            continue;
        const std::string count = std::to_string(inbetween_count);
        return Diagnostic{file_name, goal.line_number,
                          "GOAL INBETWEEN " + std::to_string(goal.inbetween) + " names an in-between beyond the " +
                              count + " the session makes (--inbetweens " + count + "); expected K from 1 to " + count};
    }
    return ok;
}

std::string goal_text(const ScriptGoal& goal)
{
    char within[32];
    std::snprintf(within, sizeof within, "%.2f", goal.within);
    switch (goal.kind) {
    case ScriptGoal::Kind::value:
        return lower(staff_line_name(goal.line)) + " within " + signed_value(goal.low) + " to " +
               signed_value(goal.high);
    case ScriptGoal::Kind::near: return "the curve within " + std::string(within) + " of " + point_text(goal.point);
    case ScriptGoal::Kind::inbetween:
        return "in-between " + std::to_string(goal.inbetween) + " within " + within + " of " + point_text(goal.point);
    }
    return {};
}

std::string goal_line(const ScriptGoal& goal)
{
    std::string line = "GOAL ";
    const auto number = [&line](double value) {
        line += ' ';
        append_shortest(line, value);
    };
    switch (goal.kind) {
    case ScriptGoal::Kind::value:
        line += "VALUE " + std::string(staff_line_name(goal.line));
        number(goal.low);
        number(goal.high);
        return line;
    case ScriptGoal::Kind::near: line += "NEAR"; break;
    case ScriptGoal::Kind::inbetween: line += "INBETWEEN " + std::to_string(goal.inbetween); break;
    }
    for (const double coordinate : {goal.point.x, goal.point.y, goal.point.z})
        number(coordinate);
    number(goal.within);
    return line;
}

std::optional<Vec3> goal_point(const ScriptGoal& goal)
{
    if (goal.kind == ScriptGoal::Kind::value)
        return std::nullopt;
    return goal.point;
}

} // namespace apcs
