#include "apcs/cli/script_options.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "option_sets.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <functional>
#include <optional>
#include <vector>

namespace apcs {

namespace {

// How one carried option is taken from the options a script gave and written for a recording.
struct CarriedOption {
    std::string_view name;
    void (*take)(CommonOptions& to, const CommonOptions& from);
    std::string (*value)(const CommonOptions& options);
};

std::string number(double value) { return shortest_number(value); }

constexpr std::array<CarriedOption, carried_option_names.size()> carried_options{{
    {"--tension", [](CommonOptions& to, const CommonOptions& from) { to.staff.tension = from.staff.tension; },
     [](const CommonOptions& options) { return number(options.staff.tension); }},
    {"--continuity", [](CommonOptions& to, const CommonOptions& from) { to.staff.continuity = from.staff.continuity; },
     [](const CommonOptions& options) { return number(options.staff.continuity); }},
    {"--bias", [](CommonOptions& to, const CommonOptions& from) { to.staff.bias = from.staff.bias; },
     [](const CommonOptions& options) { return number(options.staff.bias); }},
    {"--accel", [](CommonOptions& to, const CommonOptions& from) { to.staff.acceleration = from.staff.acceleration; },
     [](const CommonOptions& options) { return number(options.staff.acceleration); }},
    {"--slopes",
     [](CommonOptions& to, const CommonOptions& from) {
         to.path.slopes = from.path.slopes;
         to.given.slopes = true;
     },
     [](const CommonOptions& options) {
         return number(options.path.slopes.start) + " " + number(options.path.slopes.end);
     }},
    {"--samples",
     [](CommonOptions& to, const CommonOptions& from) { to.path.samples_per_segment = from.path.samples_per_segment; },
     [](const CommonOptions& options) { return std::to_string(options.path.samples_per_segment); }},
    {"--spacing",
     [](CommonOptions& to, const CommonOptions& from) {
         to.path.spacing = from.path.spacing;
         to.given.spacing = true;
     },
     [](const CommonOptions& options) {
         return std::string(options.path.spacing == Spacing::exact ? "exact" : "nearest");
     }},
    {"--surface", [](CommonOptions& to, const CommonOptions& from) { to.surface = from.surface; },
     [](const CommonOptions& options) {
         return std::string(options.surface == SurfaceConstruction::ferguson ? "ferguson" : "blend");
     }},
    {"--inbetweens",
     [](CommonOptions& to, const CommonOptions& from) { to.path.inbetween_count = from.path.inbetween_count; },
     [](const CommonOptions& options) { return std::to_string(options.path.inbetween_count); }},
    {"--theta",
     [](CommonOptions& to, const CommonOptions& from) {
         to.view.theta_degrees = from.view.theta_degrees;
         to.given.theta = true;
     },
     [](const CommonOptions& options) { return number(options.view.theta_degrees); }},
    {"--phi",
     [](CommonOptions& to, const CommonOptions& from) {
         to.view.phi_degrees = from.view.phi_degrees;
         to.given.phi = true;
     },
     [](const CommonOptions& options) { return number(options.view.phi_degrees); }},
    {"--delay",
     [](CommonOptions& to, const CommonOptions& from) {
         to.delay_ms = from.delay_ms;
         to.given.delay = true;
     },
     [](const CommonOptions& options) { return std::to_string(options.delay_ms); }},
    {"--step", [](CommonOptions& to, const CommonOptions& from) { to.step = from.step; },
     [](const CommonOptions& options) { return number(options.step); }},
}};

bool given(const std::vector<std::string>& names, std::string_view name)
{
    return std::ranges::find(names, name) != names.end();
}

std::string carried_list()
{
    std::string list;
    for (const std::string_view name : carried_option_names)
        list += (list.empty() ? "" : ", ") + std::string(name);
    return list + " or --view";
}

// A word as the message shows it: as it is when it is printable ASCII, else quoted with its other
// bytes escaped ('--st\xFFep').
std::string as_written(std::string_view word)
{
    const bool plain = std::ranges::all_of(word, [](char c) { return c > ' ' && c < '\x7f'; });
    return plain ? std::string(word) : quote_field(word);
}

// What is wrong with the words of an OPTIONS line before CLI11 reads them, if anything: a word
// that names an option a script does not carry ("--png"), or an option named twice. A word that
// starts with '-' and is a number is a value ("-0.5", --tension's).
std::optional<std::string> misnamed_option(std::string_view words)
{
    std::optional<std::string> found;
    std::vector<std::string_view> named;
    for_each_field(words, [&found, &named](std::string_view word) {
        if (found || !word.starts_with('-') || parse_number(word))
            return;
        const std::string_view name = word.substr(0, word.find('='));
        if (name != "--view" && std::ranges::find(carried_option_names, name) == carried_option_names.end())
            found = as_written(name) + ": not an option a script carries; expected the session's options " +
                    carried_list() + ", each with its value, as on the command line";
        else if (std::ranges::find(named, name) != named.end())
            found = std::string(name) + " given twice; expected each option once";
        named.push_back(name);
    });
    return found;
}

// CLI11's refusal of the words, said as APCS says a problem: a value a check refused says what
// was expected already; a word left over is named as written, in its place.
std::string refusal_text(const CLI::ParseError& error, const CLI::App& app)
{
    if (dynamic_cast<const CLI::ValidationError*>(&error) != nullptr)
        return error.what();
    const std::vector<std::string> left = app.remaining();
    if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr && !left.empty())
        return as_written(left.front()) + ": neither an option nor its value; expected the session's options " +
               carried_list() + ", each with its value, as on the command line";
    return std::string(error.what()) + "; expected each option with its value, as on the command line";
}

} // namespace

std::vector<std::string> given_carried_options(const std::function<bool(const std::string& name)>& given_by_name)
{
    const bool view_given = given_by_name("--view");
    std::vector<std::string> names;
    for (const std::string_view name : carried_option_names) {
        const bool theta_or_phi = name == "--theta" || name == "--phi";
        if (given_by_name(std::string(name)) || (theta_or_phi && view_given))
            names.emplace_back(name);
    }
    return names;
}

Expected<CommonOptions> options_of_script(const ScriptOptions& line, const std::string& file_name)
{
    CommonOptions from_script;
    if (line.words.empty())
        return from_script;
    if (const std::optional<std::string> problem = misnamed_option(line.words))
        return Diagnostic{file_name, line.line_number, "OPTIONS " + *problem};
    std::vector<double> slopes;
    CLI::App app{"", "OPTIONS"};
    app.set_help_flag();
    add_carried_options(app, from_script, slopes);
    try {
        app.parse(line.words, false);
    } catch (const CLI::ParseError& error) {
        return Diagnostic{file_name, line.line_number, "OPTIONS: " + refusal_text(error, app)};
    }
    if (slopes.size() == 2)
        from_script.path.slopes = {slopes[0], slopes[1]};
    from_script.given.carried =
        given_carried_options([&app](const std::string& name) { return app.get_option(name)->count() > 0; });
    return from_script;
}

void merge_script_options(const CommonOptions& script, CommonOptions& options)
{
    for (const CarriedOption& option : carried_options) {
        if (!given(script.given.carried, option.name) || given(options.given.carried, option.name))
            continue;
        option.take(options, script);
        options.given.carried.emplace_back(option.name);
    }
}

Expected<void> take_script_options(const ScriptOptions& line, const std::string& file_name, CommonOptions& options)
{
    const Expected<CommonOptions> script = options_of_script(line, file_name);
    if (!script)
        return script.error();
    merge_script_options(*script, options);
    return ok;
}

std::string carried_options_words(const CommonOptions& options)
{
    std::string words;
    for (const CarriedOption& option : carried_options)
        if (given(options.given.carried, option.name))
            words += (words.empty() ? "" : " ") + std::string(option.name) + " " + option.value(options);
    return words;
}

std::optional<std::string> changed_task_option(const CommonOptions& task, const CommonOptions& options)
{
    for (const CarriedOption& option : carried_options) {
        const bool sets_task = std::ranges::find(task_option_names, option.name) != task_option_names.end();
        if (sets_task && option.value(task) != option.value(options))
            return std::string(option.name) + " " + option.value(options);
    }
    return std::nullopt;
}

} // namespace apcs
