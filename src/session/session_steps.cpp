// The text steps of the session, in the order of thesis Ch. 4.2 and named after the functions of
// animate.c (SPEC §9): what each prompt prints and what its answer does.
#include "apcs/session/session_steps.h"

#include "apcs/animation/input_limits.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/sif_path.h"
#include "session_budget.h"
#include "apcs/screens/words.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

namespace apcs::step {

namespace text = words;

namespace {

Lines lines_of(std::initializer_list<std::string_view> lines)
{
    return {lines.begin(), lines.end()};
}

// Numbers separated by blanks or commas (the thesis writes "THETA ,PHI"); nullopt if any field
// is not a finite number.
std::optional<std::vector<double>> numbers_in(const std::string& line)
{
    std::string spaced = line;
    std::replace(spaced.begin(), spaced.end(), ',', ' ');
    std::istringstream fields(spaced);
    std::vector<double> numbers;
    std::string field;
    while (fields >> field) {
        const std::optional<double> value = parse_number(field);
        if (!value || !std::isfinite(*value))
            return std::nullopt;
        numbers.push_back(*value);
    }
    return numbers;
}

// KEY1 (which 0) or KEY2 (1) read into the model, or why not.
Expected<void> read_key_file(StepContext& context, const std::string& name, std::size_t which)
{
    const Expected<DatFile> file = context.files.read_dat(name, 2);
    if (!file)
        return file.error();
    context.files.protect_key_file(name);
    context.model.key_names[which] = name;
    context.model.key_frames[which] = graphic_from(*file);
    context.files.log("KEY" + std::to_string(which + 1) + " " + name + ": " + std::to_string(file->point_count()) +
                      " points in " + std::to_string(file->parts.size()) + " parts");
    return ok;
}

} // namespace

// Step 1 (fig. 4.2.1): the key frames.

Lines Key1Prompt::lines(const StepContext&) const { return lines_of({text::ask_key1}); }

StepResult Key1Prompt::submit(StepContext& context, const std::string& answer)
{
    if (const Expected<void> read = read_key_file(context, answer, 0); !read)
        return StepResult::refused(read.error().to_string());
    return {StepOutcome::answered};
}

Lines Key2Prompt::lines(const StepContext&) const { return lines_of({text::ask_key2}); }

StepResult Key2Prompt::submit(StepContext& context, const std::string& answer)
{
    if (const Expected<void> read = read_key_file(context, answer, 1); !read)
        return StepResult::refused(read.error().to_string());
    const auto& keys = context.model.key_frames;
    const std::size_t key_points = std::max(keys[0].point_count(), keys[1].point_count());
    if (const Expected<void> fits = check_frames_fit(key_points, context.settings); !fits)
        return StepResult::refused(fits.error().message);
    return {StepOutcome::answered};
}

// Step 2 (fig. 4.2.2).

Lines ViewPrompt::lines(const StepContext& context) const
{
    const std::string last = path_file_name(context.model.point_count);
    return {std::string(text::adding_points_done),
            std::string(text::must_input_two_files),
            "ani1.dat and " + last + ".",
            "ani1.dat" + std::string(text::contained_first),
            last + std::string(text::contained_last),
            std::string(text::ask_view),
            std::string(text::ask_view_values)};
}

Lines ViewPrompt::again(const StepContext&) const { return lines_of({text::ask_view_values}); }

// The thesis' example, 30 40 200, or what the command line gave (--theta, --phi, --delay).
std::string ViewPrompt::default_answer(const StepContext& context) const
{
    const SessionSettings& settings = context.settings;
    return shortest_number(settings.theta_degrees.value_or(30.0)) + " " +
           shortest_number(settings.phi_degrees.value_or(40.0)) + " " + std::to_string(settings.delay_ms.value_or(200));
}

// THETA, PHI and the delay; the view itself is fitted when graphics begin.
StepResult ViewPrompt::submit(StepContext& context, const std::string& answer)
{
    const std::optional<std::vector<double>> numbers = numbers_in(answer);
    if (!numbers || numbers->size() != 3 || !limits::view_degrees.contains((*numbers)[0]) ||
        !limits::view_degrees.contains((*numbers)[1]) || !limits::delay_ms.contains((*numbers)[2]))
        return StepResult::refused(
            "Expected three numbers: THETA PHI (degrees) and the delay (0 to 60000 ms), e.g. 30 40 200");
    SessionModel& model = context.model;
    model.view_angles = {(*numbers)[0], (*numbers)[1]};
    model.delay_ms = static_cast<int>(std::lround((*numbers)[2]));
    const SessionSettings& settings = context.settings;
    std::string overridden;
    if (settings.delay_overrides_answer && settings.delay_ms) {
        overridden = " (--delay; the answer gave " + std::to_string(model.delay_ms) + ")";
        model.delay_ms = *settings.delay_ms;
    }
    context.files.log("view: theta " + shortest_number(model.view_angles.theta_degrees) + ", phi " +
                      shortest_number(model.view_angles.phi_degrees) + ", delay " + std::to_string(model.delay_ms) +
                      " ms" + overridden);
    return {StepOutcome::answered};
}

// Step 3 (fig. 4.2.3): the path file and its end slopes.

Lines PathPrompt::lines(const StepContext&) const { return lines_of({text::ask_path_file, text::ask_path_file_purpose}); }

std::string PathPrompt::default_answer(const StepContext& context) const
{
    return path_file_name(path == 0 ? 1 : context.model.point_count);
}

namespace {

// A Synfig document's path (SPEC §7.5), read into the plane the answered view looks at. It is only
// read: there is no text to rewrite, and its warnings go to the log.
Expected<DatText> read_synfig_path(StepContext& context, const std::string& name)
{
    Expected<std::string> text = context.files.read_text(name);
    if (!text)
        return text.error();
    const ViewAngles& view = context.model.view_angles;
    Expected<SifPath> read =
        parse_sif_path(*text, name, {"origin", sif_plane_of(view.theta_degrees, view.phi_degrees)});
    if (!read)
        return read.error();
    for (const std::string& warning : read->warnings)
        context.files.log("warning: " + warning);
    return DatText{std::move(read->file), std::string()};
}

} // namespace

StepResult PathPrompt::submit(StepContext& context, const std::string& name)
{
    const bool synfig = is_sif_name(name);
    // The path file is rewritten after adjusting: it must lie in the session's folder. A Synfig
    // document is only read; its adjusted path goes to aniK.dat.
    if (!synfig && !context.files.lies_in_folder(name))
        return StepResult::refused(name + ": expected a file in the session's folder (no leading '/', no '..', no "
                                          "link out of it), since APCS rewrites it");
    Expected<DatText> read = synfig ? read_synfig_path(context, name) : context.files.read_dat_text(name, 2);
    if (!read)
        return StepResult::refused(read.error().to_string());
    SessionModel& model = context.model;
    // A closed graphic's second path starts from the first path's values, as the thesis says.
    const ControlPoints& first_points = model.paths[0].points;
    const bool closed_second = path == 1 && model.keys.key1.is_closed() && !first_points.empty();
    const StaffValues defaults = closed_second ? first_points.front().staff : context.settings.staff;
    Expected<ControlPoints> points =
        point_path_from(read->file, name, path == 0 ? PathEnd::first : PathEnd::last, model.keys, defaults);
    if (!points)
        return StepResult::refused(points.error().to_string());
    if (const Expected<void> fits = check_path_fits(points->size(), context.settings); !fits)
        return StepResult::refused(name + ": " + fits.error().message);
    SessionPath& shaped = model.paths[static_cast<std::size_t>(path)];
    // Accepting rewrites the file that was read, whatever case the name was typed in; a Synfig
    // document's path is written as the prompt's own file, aniK.dat.
    shaped.name = synfig ? default_answer(context) : context.files.name_read(name);
    shaped.text = std::move(read->text);
    shaped.points = std::move(*points);
    shaped.file_slopes = read->file.slopes;
    context.files.log("path " + name + ": " + std::to_string(read->file.point_count()) + " control points");
    return {StepOutcome::answered};
}

Lines SlopesPrompt::lines(const StepContext&) const { return lines_of({"", text::slope_range, text::ask_slopes}); }

Lines SlopesPrompt::again(const StepContext&) const { return lines_of({text::ask_slopes}); }

std::string SlopesPrompt::default_answer(const StepContext& context) const
{
    // SPEC §2.1: an explicit --slopes, else the path file's SLOPES, else 1 1.
    const EndSlopes slopes = context.settings.slopes.value_or(
        context.model.paths[static_cast<std::size_t>(path)].file_slopes.value_or(EndSlopes{}));
    return first ? shortest_number(slopes.end) : shortest_number(slopes.start) + " " + shortest_number(slopes.end);
}

StepResult SlopesPrompt::submit(StepContext& context, const std::string& answer)
{
    const std::optional<std::vector<double>> numbers = numbers_in(answer);
    const bool fits = numbers && !numbers->empty() && numbers->size() <= (first ? 1u : 2u) &&
                      std::all_of(numbers->begin(), numbers->end(), [](double s) { return limits::end_slope.contains(s); });
    if (!fits)
        return StepResult::refused("Expected two slopes from 0 to 1, e.g. 1 1");
    if (!first && numbers->size() == 1) {
        first = numbers->front();
        return {};
    }
    const double start = first ? *first : (*numbers)[0];
    const double end = numbers->back();
    context.model.paths[static_cast<std::size_t>(path)].slopes = {start, end};
    context.files.log("slopes DS[0] " + shortest_number(start) + ", DD[N] " + shortest_number(end));
    return {StepOutcome::answered};
}

// Step 5.

Lines AskNext::lines(const StepContext&) const { return lines_of({text::ask_next_path}); }

StepResult AskNext::submit(StepContext& context, const std::string&)
{
    context.say("Y");
    return {StepOutcome::answered};
}

// The end.

Lines Finished::lines(const StepContext& context) const
{
    Lines lines{"", "APCS is done. Files written:"};
    for (const std::string& name : context.model.written.names())
        lines.push_back("  " + name);
    return lines;
}

StepResult Finished::start(StepContext& context)
{
    context.files.log("end of session");
    return {};
}

} // namespace apcs::step
