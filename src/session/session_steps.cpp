// The text steps of the session, in the order of thesis Ch. 4.2 and named after the functions of
// animate.c (SPEC §9): the prompt table, then what each answer does.
#include "apcs/session/session.h"

#include "apcs/animation/input_limits.h"
#include "apcs/animation/surface_fit.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/session/session_budget.h"
#include "apcs/session/session_text.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace apcs {

namespace text = session_text;

namespace {

std::vector<std::string> lines_of(std::initializer_list<std::string_view> lines)
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

} // namespace

const Session::Prompt& Session::prompt_for(SessionPhase phase)
{
    using S = Session;
    static const Prompt prompts[] = {
        {SessionPhase::ask_key1, KeyContext::text_line, [](const S&) { return lines_of({text::ask_key1}); },
         [](const S&) { return lines_of({text::ask_key1}); }, [](const S&) { return std::string("key1.dat"); },
         &S::read_key1},
        {SessionPhase::ask_key2, KeyContext::text_line, [](const S&) { return lines_of({text::ask_key2}); },
         [](const S&) { return lines_of({text::ask_key2}); }, [](const S&) { return std::string("key2.dat"); },
         &S::read_key2},
        // The split shows its progress on the message line, not in the console's lines.
        {SessionPhase::splitting, KeyContext::splitting, [](const S&) { return std::vector<std::string>{}; },
         [](const S&) { return std::vector<std::string>{}; }, nullptr, &S::stop_split},
        {SessionPhase::ask_view, KeyContext::text_line, [](const S& s) { return s.view_prompt(); },
         [](const S&) { return lines_of({text::ask_view_values}); }, [](const S& s) { return s.view_default(); },
         &S::define_view_parameters},
        {SessionPhase::ask_path_file, KeyContext::text_line,
         [](const S&) { return lines_of({text::ask_path_file, text::ask_path_file_purpose}); },
         [](const S&) { return lines_of({text::ask_path_file, text::ask_path_file_purpose}); },
         [](const S& s) { return s.path_file_default(); }, &S::read_data_file},
        {SessionPhase::ask_slopes, KeyContext::text_line,
         [](const S&) { return lines_of({"", text::slope_range, text::ask_slopes}); },
         [](const S&) { return lines_of({text::ask_slopes}); }, [](const S& s) { return s.slopes_default(); },
         &S::predefine_ends_slope},
        {SessionPhase::ask_next_path, KeyContext::yes_to_go_on, [](const S&) { return lines_of({text::ask_next_path}); },
         [](const S&) { return lines_of({text::ask_next_path}); }, nullptr, &S::adjust_next_path},
        {SessionPhase::ask_stop, KeyContext::enter_to_go_on, [](const S&) { return lines_of({text::ask_stop}); },
         [](const S&) { return lines_of({text::ask_stop}); }, nullptr, &S::surface_fitting},
        {SessionPhase::ask_draw, KeyContext::any_key,
         [](const S&) { return lines_of({text::fitting_done, text::ask_draw}); },
         [](const S&) { return lines_of({text::ask_draw}); }, nullptr, &S::showing_animation},
        {SessionPhase::finished, KeyContext::finished, [](const S& s) { return s.done_lines(); },
         [](const S&) { return std::vector<std::string>{}; }, nullptr, nullptr},
    };
    const auto found = std::find_if(std::begin(prompts), std::end(prompts),
                                    [phase](const Prompt& prompt) { return prompt.phase == phase; });
    assert(found != std::end(prompts));
    return *found;
}

// Step 1 (fig. 4.2.1): the key frames.

void Session::read_key1(const std::string& name)
{
    if (read_key_file(name, 0))
        go_to(SessionPhase::ask_key2);
}

void Session::read_key2(const std::string& name)
{
    if (!read_key_file(name, 1))
        return;
    const std::size_t key_points = std::max(m_key_frames[0].point_count(), m_key_frames[1].point_count());
    if (const std::optional<std::string> refused = frames_refusal(key_points, m_settings))
        return ask_again(SessionPhase::ask_key2, *refused);
    add_points_and_split();
}

bool Session::read_key_file(const std::string& name, int which)
{
    const SessionPhase phase = which == 0 ? SessionPhase::ask_key1 : SessionPhase::ask_key2;
    const Expected<DatFile> file = m_files.read_dat(name, 2);
    if (!file) {
        ask_again(phase, file.error().to_string());
        return false;
    }
    m_files.protect_key_file(name);
    m_key_names[static_cast<std::size_t>(which)] = name;
    m_key_frames[static_cast<std::size_t>(which)] = graphic_from(*file);
    m_files.log("KEY" + std::to_string(which + 1) + " " + name + ": " + std::to_string(file->point_count()) +
                " points in " + std::to_string(file->parts.size()) + " parts");
    return true;
}

// addpoint.c and split.c: session_split.cpp.

// Step 2 (fig. 4.2.2).

std::vector<std::string> Session::view_prompt() const
{
    const std::string last = path_file_name(m_point_count);
    return {std::string(text::adding_points_done),
            std::string(text::must_input_two_files),
            "ani1.dat and " + last + ".",
            "ani1.dat" + std::string(text::contained_first),
            last + std::string(text::contained_last),
            std::string(text::ask_view),
            std::string(text::ask_view_values)};
}

// Define_View_Parameters: THETA, PHI and the delay; the view itself is fitted when graphics begin.
// The thesis' example, 30 40 200, or what the command line gave (--theta, --phi, --delay).
std::string Session::view_default() const
{
    return shortest_number(m_settings.theta_degrees.value_or(30.0)) + " " +
           shortest_number(m_settings.phi_degrees.value_or(40.0)) + " " + std::to_string(m_settings.delay_ms.value_or(200));
}

void Session::define_view_parameters(const std::string& line)
{
    const std::optional<std::vector<double>> numbers = numbers_in(line);
    if (!numbers || numbers->size() != 3 || !limits::view_degrees.contains((*numbers)[0]) ||
        !limits::view_degrees.contains((*numbers)[1]) || !limits::delay_ms.contains((*numbers)[2]))
        return ask_again(SessionPhase::ask_view,
                         "Expected three numbers: THETA PHI (degrees) and the delay (0 to 60000 ms), e.g. 30 40 200");
    m_view_angles = {(*numbers)[0], (*numbers)[1]};
    m_delay_ms = static_cast<int>(std::lround((*numbers)[2]));
    m_files.log("view: theta " + shortest_number(m_view_angles.theta_degrees) + ", phi " +
                shortest_number(m_view_angles.phi_degrees) + ", delay " + std::to_string(m_delay_ms) + " ms");
    m_path = 0;
    go_to(SessionPhase::ask_path_file);
}

// Step 3 (fig. 4.2.3): the path file and its end slopes.

std::string Session::path_file_default() const { return path_file_name(m_path == 0 ? 1 : m_point_count); }

// Read_data_file: the path file of the graphic point being adjusted.
void Session::read_data_file(const std::string& name)
{
    // The path file is rewritten after adjusting: it must lie in the session's folder.
    if (!m_files.lies_in_folder(name))
        return ask_again(SessionPhase::ask_path_file,
                         name + ": expected a file in the session's folder (no leading '/', no '..', no link "
                                "out of it), since APCS rewrites it");
    Expected<DatText> read = m_files.read_dat_text(name, 2);
    if (!read)
        return ask_again(SessionPhase::ask_path_file, read.error().to_string());
    const DatFile* file = &read->file;
    // A closed graphic's second path starts from the first path's values, as the thesis says.
    const bool closed_second = m_path == 1 && m_keys.key1.is_closed() && !m_points[0].empty();
    const StaffValues defaults = closed_second ? m_points[0].front().staff : m_settings.staff;
    Expected<ControlPoints> points =
        point_path_from(*file, name, m_path == 0 ? PathEnd::first : PathEnd::last, m_keys, defaults);
    if (!points)
        return ask_again(SessionPhase::ask_path_file, points.error().to_string());
    if (const std::optional<std::string> refused = path_refusal(points->size(), m_settings))
        return ask_again(SessionPhase::ask_path_file, name + ": " + *refused);
    // Accepting rewrites the file that was read, whatever case the name was typed in.
    m_path_names[static_cast<std::size_t>(m_path)] = m_files.name_read(name);
    m_path_texts[static_cast<std::size_t>(m_path)] = std::move(read->text);
    m_points[static_cast<std::size_t>(m_path)] = std::move(*points);
    m_files.log("path " + name + ": " + std::to_string(file->point_count()) + " control points");
    m_first_slope.reset();
    go_to(SessionPhase::ask_slopes);
}

std::string Session::slopes_default() const
{
    const EndSlopes slopes = m_settings.slopes.value_or(EndSlopes{});
    return m_first_slope ? shortest_number(slopes.end) : shortest_number(slopes.start) + " " + shortest_number(slopes.end);
}

// Predefine-ENDS_slope: DS[0] and DD[N], on one line or one per line.
void Session::predefine_ends_slope(const std::string& line)
{
    const std::optional<std::vector<double>> numbers = numbers_in(line);
    const bool fits = numbers && !numbers->empty() && numbers->size() <= (m_first_slope ? 1u : 2u) &&
                      std::all_of(numbers->begin(), numbers->end(), [](double s) { return limits::end_slope.contains(s); });
    if (!fits) {
        m_first_slope.reset();
        return ask_again(SessionPhase::ask_slopes, "Expected two slopes from 0 to 1, e.g. 1 1");
    }
    if (!m_first_slope && numbers->size() == 1) {
        m_first_slope = numbers->front();
        return;
    }
    const double start = m_first_slope ? *m_first_slope : (*numbers)[0];
    const double end = numbers->back();
    m_slopes[static_cast<std::size_t>(m_path)] = {start, end};
    m_files.log("slopes DS[0] " + shortest_number(start) + ", DD[N] " + shortest_number(end));
    initial_graphics();
}

PathSettings Session::path_settings(int path) const
{
    assert(path == 0 || path == 1);
    return {m_slopes[static_cast<std::size_t>(path)], m_settings.samples_per_segment, m_settings.inbetween_count,
            m_settings.spacing};
}

// Initial_Graphics: steps 3–5 go on in graphics mode, in the PathEditor.
void Session::initial_graphics()
{
    assert(m_points[static_cast<std::size_t>(m_path)].size() >= 2);
    std::vector<std::vector<Vec3>> key_frames;
    for (const Graphic* key : {&m_keys.key1, &m_keys.key2})
        for (auto& polyline : key->polylines(key->all_points()))
            key_frames.push_back(std::move(polyline));
    const auto index = static_cast<std::size_t>(m_path);
    m_step.emplace<PathEditor>(PathEditor::Setup{m_path_names[index], m_points[index], path_settings(m_path),
                                                 m_view_angles, std::move(key_frames), m_settings.step},
                               m_files);
}

// The path file as read, with its points replaced by the editor's in seven columns and its
// comments kept.
std::string Session::rewritten_path_file(const PathEditor& editor) const
{
    const std::string& text = m_path_texts[static_cast<std::size_t>(m_path)];
    const Expected<DatFile> original = parse_dat(text, editor.path_name());
    if (!original)
        return format_dat(dat_from(editor.points()));
    return format_path_file(text, *original, editor.points(), editor.point_origins());
}

// Step 5: the path accepted is written back with its staff values.
void Session::accept_path(PathEditor& editor)
{
    const auto index = static_cast<std::size_t>(m_path);
    if (auto problem = write_file(editor.path_name(), rewritten_path_file(editor)))
        return editor.show_problem(problem->to_string());
    record_written(editor.path_name());
    m_points[index] = editor.points();
    m_files.log("accepted path " + editor.path_name() + " (rewritten with t c b a)");
    go_to(m_path == 0 ? SessionPhase::ask_next_path : SessionPhase::ask_stop);
}

void Session::adjust_next_path(const std::string&)
{
    say("Y");
    m_path = 1;
    go_to(SessionPhase::ask_path_file);
}

// Step 6 (fig. 4.2.7): s_fiting.c, then Showing_Animation.
void Session::surface_fitting(const std::string&)
{
    say(std::string(text::fitting));
    FrameSequence frames = fit_key_frames(m_keys, evaluate_path(m_points[0], path_settings(0)),
                                                evaluate_path(m_points[1], path_settings(1)));
    const Expected<std::vector<std::string>> written = m_files.write_inbetweens(frames, m_keys.key1);
    if (!written) {
        m_write_problem = written.error();
        return ask_again(SessionPhase::ask_stop, written.error().to_string());
    }
    for (const std::string& name : *written)
        record_written(name);
    m_files.log("surface fitting: " + std::to_string(written->size()) + " in-betweens of " + std::to_string(m_point_count) +
                " points written");
    if (const std::optional<std::string> note = earlier_inbetweens_note(m_files.earlier_inbetweens(written->size()))) {
        say(*note);
        m_files.log(*note);
    }
    m_fitted_frames = std::move(frames);
    go_to(SessionPhase::ask_draw);
}

void Session::showing_animation(const std::string&)
{
    m_step.emplace<AnimationPlayer>(std::move(m_fitted_frames), m_keys.key1, m_key_names, m_view_angles, m_delay_ms,
                                    m_files);
}

std::vector<std::string> Session::done_lines() const
{
    std::vector<std::string> lines{"", "APCS is done. Files written:"};
    for (const std::string& name : m_written)
        lines.push_back("  " + name);
    return lines;
}

void Session::finish()
{
    go_to(SessionPhase::finished);
    m_files.log("end of session");
}

} // namespace apcs
