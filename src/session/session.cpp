#include "apcs/session/session.h"

#include "apcs/animation/surface_fit.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/text_fields.h"
#include "apcs/raster/painter.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/screen_layout.h"
#include "apcs/session/session_text.h"
#include "session_keys.h"

using namespace apcs::session_keys;

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace apcs {

namespace text = session_text;

const char* phase_name(SessionPhase phase)
{
    switch (phase) {
    case SessionPhase::ask_key1: return "step 1: KEY1 file";
    case SessionPhase::ask_key2: return "step 1: KEY2 file";
    case SessionPhase::ask_view: return "step 2: view and delay";
    case SessionPhase::ask_path_file: return "step 3: path file";
    case SessionPhase::ask_slopes: return "step 3: end slopes";
    case SessionPhase::choose_control: return "step 3: global or local control";
    case SessionPhase::pick_region_first: return "step 3: first control point of the region";
    case SessionPhase::pick_region_last: return "step 3: last control point of the region";
    case SessionPhase::staff: return "step 4: four-line staff";
    case SessionPhase::ask_again: return "step 5: adjust again";
    case SessionPhase::ask_next_path: return "step 5: next path";
    case SessionPhase::ask_stop: return "step 6: stop the work";
    case SessionPhase::ask_draw: return "step 6: surface fitting done";
    case SessionPhase::animating: return "step 6: animation";
    case SessionPhase::animation_done: return "step 6: animation done";
    case SessionPhase::overlay: return "step 6: all frames";
    case SessionPhase::finished: return "end";
    }
    return "";
}

namespace {

std::string trimmed(const std::string& line)
{
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    const auto last = line.find_last_not_of(" \t");
    return line.substr(first, last - first + 1);
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

Session::Session(SessionSettings settings, SessionFiles& files)
    : m_settings(settings)
    , m_files(files)
{
    m_console.print_line(std::string(text::ask_key1));
}

void Session::say(const std::string& line) { m_console.print_line(line); }

std::optional<Diagnostic> Session::write_file(const std::string& name, const std::string& content)
{
    // Key files are never written: compared the way DOS names compare, ignoring case.
    const std::string plain = std::filesystem::path(name).lexically_normal().string();
    for (const std::string& key : m_key_names)
        if (!key.empty() && equals_ignoring_case(plain, std::filesystem::path(key).lexically_normal().string()))
            return Diagnostic{name, 0, "is a key file; key files are never written"};
    return m_files.write(name, content);
}

void Session::record_written(const std::string& name)
{
    if (std::find(m_written.begin(), m_written.end(), name) == m_written.end())
        m_written.push_back(name);
}

void Session::handle(const KeyEvent& event)
{
    switch (m_phase) {
    case SessionPhase::ask_key1:
    case SessionPhase::ask_key2:
    case SessionPhase::ask_view:
    case SessionPhase::ask_path_file:
    case SessionPhase::ask_slopes: {
        std::string input = m_console.input();
        if (event.key == Key::enter) {
            // An empty answer takes the thesis' example, and the console shows it as typed.
            const std::string answer = trimmed(input).empty() ? default_answer() : trimmed(input);
            m_console.set_input(answer);
            m_console.commit_input();
            submit_line(answer);
            return;
        }
        if (event.key == Key::backspace) {
            const std::u32string decoded = decode_utf8(input);
            std::string shorter;
            for (std::size_t i = 0; i + 1 < decoded.size(); ++i)
                append_utf8(shorter, decoded[i]);
            m_console.set_input(shorter);
        } else if (event.key == Key::escape) {
            m_console.set_input("");
        } else if (event.key == Key::space) {
            m_console.set_input(input + " ");
        } else if (event.key == Key::character && event.character >= 0x20 && input.size() < 200) {
            append_utf8(input, event.character);
            m_console.set_input(input);
        }
        return;
    }
    case SessionPhase::ask_next_path:
        if (is_yes(event)) {
            say("Y");
            m_path = 1;
            start_path_prompt();
        }
        return;
    case SessionPhase::ask_stop:
        if (event.key == Key::enter)
            run_surface_fitting();
        return;
    case SessionPhase::ask_draw:
        start_animation();
        return;
    case SessionPhase::animating:
        if (event.key == Key::escape) {
            m_phase = SessionPhase::animation_done;
            m_paused = false;
        } else if (event.key == Key::space) {
            m_paused = !m_paused;
        } else if (is_character(event, U'R', U'r')) {
            m_frame = 0;
            m_paused = false;
        }
        return;
    case SessionPhase::animation_done:
        m_phase = SessionPhase::overlay;
        m_files.log("showed all " + std::to_string(m_frames.frame_count()) + " frames overlaid");
        return;
    case SessionPhase::overlay: {
        m_phase = SessionPhase::finished;
        say("");
        say("APCS is done. Files written:");
        for (const std::string& name : m_written)
            say("  " + name);
        m_files.log("end of session");
        return;
    }
    case SessionPhase::finished:
        return;
    default:
        handle_graphics_key(event);
        return;
    }
}

void Session::tick()
{
    if (!animating())
        return;
    if (m_frame + 1 < m_frames.frame_count())
        ++m_frame;
    else
        m_phase = SessionPhase::animation_done;
}

std::string Session::default_answer() const
{
    switch (m_phase) {
    case SessionPhase::ask_key1:
        return "key1.dat";
    case SessionPhase::ask_key2:
        return "key2.dat";
    case SessionPhase::ask_view:
        return "30 40 200";
    case SessionPhase::ask_path_file:
        return path_file_name(m_path == 0 ? 1 : m_point_count);
    case SessionPhase::ask_slopes:
        return m_first_slope ? "1" : "1 1";
    default:
        return {};
    }
}

void Session::submit_line(const std::string& line)
{
    switch (m_phase) {
    case SessionPhase::ask_key1:
        return submit_key_file(line, 0);
    case SessionPhase::ask_key2:
        return submit_key_file(line, 1);
    case SessionPhase::ask_view:
        return submit_view(line);
    case SessionPhase::ask_path_file:
        return submit_path_file(line);
    case SessionPhase::ask_slopes:
        return submit_slopes(line);
    default:
        return;
    }
}

void Session::submit_key_file(const std::string& name, int which)
{
    const Expected<DatFile> file = m_files.read_dat(name, 2);
    if (!file) {
        say(file.error().to_string());
        say(std::string(which == 0 ? text::ask_key1 : text::ask_key2));
        return;
    }
    m_key_names[static_cast<std::size_t>(which)] = name;
    m_key_frames[static_cast<std::size_t>(which)] = graphic_from(*file);
    m_files.log("KEY" + std::to_string(which + 1) + " " + name + ": " + std::to_string(file->point_count()) +
                " points in " + std::to_string(file->parts.size()) + " parts");
    if (which == 0) {
        m_phase = SessionPhase::ask_key2;
        say(std::string(text::ask_key2));
        return;
    }
    finish_keys();
}

void Session::finish_keys()
{
    m_keys = equalise_key_frames(m_key_frames[0], m_key_frames[1]);
    m_point_count = m_keys.key1.point_count();
    for (const NamedText& file : split_path_files(m_keys.key1, m_keys.key2)) {
        if (auto problem = write_file(file.name, file.content)) {
            say(problem->to_string());
            say(std::string(text::ask_key2));
            return;
        }
        record_written(file.name);
    }
    m_files.log("added points: both keys have " + std::to_string(m_point_count) + " points in " +
                std::to_string(m_keys.key1.parts.size()) + " parts; wrote ani1.dat … " + path_file_name(m_point_count));
    const std::string last = path_file_name(m_point_count);
    say(std::string(text::adding_points_done));
    say(std::string(text::must_input_two_files));
    say("ani1.dat and " + last + ".");
    say("ani1.dat" + std::string(text::contained_first));
    say(last + std::string(text::contained_last));
    say(std::string(text::ask_view));
    say(std::string(text::ask_view_values));
    m_phase = SessionPhase::ask_view;
}

void Session::submit_view(const std::string& line)
{
    const std::optional<std::vector<double>> numbers = numbers_in(line);
    if (!numbers || numbers->size() != 3 || (*numbers)[2] < 0 || (*numbers)[2] > 60000 ||
        std::abs((*numbers)[0]) > 1e6 || std::abs((*numbers)[1]) > 1e6) {
        say("Expected three numbers: THETA PHI (degrees) and the delay (0 to 60000 ms), e.g. 30 40 200");
        say(std::string(text::ask_view_values));
        return;
    }
    m_view_angles = {(*numbers)[0], (*numbers)[1]};
    m_delay_ms = static_cast<int>(std::lround((*numbers)[2]));
    m_files.log("view: theta " + shortest_number(m_view_angles.theta_degrees) + ", phi " +
                shortest_number(m_view_angles.phi_degrees) + ", delay " + std::to_string(m_delay_ms) + " ms");
    m_path = 0;
    start_path_prompt();
}

void Session::start_path_prompt()
{
    say(std::string(text::ask_path_file));
    say(std::string(text::ask_path_file_purpose));
    m_phase = SessionPhase::ask_path_file;
}

void Session::submit_path_file(const std::string& name)
{
    // The path file is rewritten after adjusting: it must lie in the session's folder.
    const std::filesystem::path typed(name);
    const bool escapes = typed.is_absolute() ||
                         std::any_of(typed.begin(), typed.end(), [](const std::filesystem::path& part) { return part == ".."; });
    if (escapes) {
        say(name + ": expected a file in the session's folder (no leading '/', no '..'), since APCS rewrites it");
        start_path_prompt();
        return;
    }
    const Expected<DatFile> file = m_files.read_dat(name, 2);
    // The graphic point this path belongs to: the very first or the very last of each key.
    const auto end_point = [&](const Graphic& key) { return m_path == 0 ? key.first_point() : key.last_point(); };
    std::optional<Diagnostic> problem;
    if (!file)
        problem = file.error();
    else
        problem = check_path_ends(*file, name, m_path == 0 ? "first" : "last", end_point(m_keys.key1),
                                  end_point(m_keys.key2));
    if (problem) {
        say(problem->to_string());
        start_path_prompt();
        return;
    }
    // A closed graphic's second path starts from the first path's values, as the thesis says.
    const bool closed_second = m_path == 1 && m_keys.key1.is_closed() && !m_points[0].empty();
    const StaffValues defaults = closed_second ? m_points[0].front().staff : StaffValues{};
    m_path_names[static_cast<std::size_t>(m_path)] = name;
    m_points[static_cast<std::size_t>(m_path)] = control_points_from(*file, defaults);
    m_files.log("path " + name + ": " + std::to_string(file->point_count()) + " control points");
    say("");
    say(std::string(text::slope_range));
    say(std::string(text::ask_slopes));
    m_first_slope.reset();
    m_phase = SessionPhase::ask_slopes;
}

void Session::submit_slopes(const std::string& line)
{
    const std::optional<std::vector<double>> numbers = numbers_in(line);
    const bool fits = numbers && !numbers->empty() && numbers->size() <= (m_first_slope ? 1u : 2u) &&
                      std::all_of(numbers->begin(), numbers->end(), [](double s) { return s >= 0.0 && s <= 1.0; });
    if (!fits) {
        say("Expected two slopes from 0 to 1, e.g. 1 1");
        say(std::string(text::ask_slopes));
        m_first_slope.reset();
        return;
    }
    if (!m_first_slope && numbers->size() == 1) {
        m_first_slope = numbers->front();
        return;
    }
    const double start = m_first_slope ? *m_first_slope : (*numbers)[0];
    const double end = numbers->back();
    m_slopes[static_cast<std::size_t>(m_path)] = {start, end};
    m_files.log("slopes DS[0] " + shortest_number(start) + ", DD[N] " + shortest_number(end));
    enter_graphics();
}

EvaluatedPath Session::evaluated(int path) const
{
    const auto index = static_cast<std::size_t>(path);
    return evaluate_path(m_points[index], {m_slopes[index], m_settings.samples_per_segment, m_settings.inbetween_count,
                                           m_settings.spacing});
}

void Session::reevaluate() { m_evaluated = evaluated(m_path); }

void Session::enter_graphics()
{
    reevaluate();
    // The view is fixed for the whole adjusting of a path so that each key's effect is seen
    // against a still picture; it is fitted to the path and both key frames.
    std::vector<Vec3> scene;
    for (const ControlPoint& point : m_points[static_cast<std::size_t>(m_path)])
        scene.push_back(point.position);
    scene.insert(scene.end(), m_evaluated.curve.points.begin(), m_evaluated.curve.points.end());
    for (const Graphic* key : {&m_keys.key1, &m_keys.key2}) {
        const std::vector<Vec3> points = key->all_points();
        scene.insert(scene.end(), points.begin(), points.end());
    }
    m_view = ViewTransform::fit(m_view_angles, scene, layout::drawing_area);
    m_phase = SessionPhase::choose_control;
    m_graphics_message.clear();
}

void Session::run_surface_fitting()
{
    say(std::string(text::fitting));
    m_frames = fit_key_frames(m_keys, evaluated(0), evaluated(1));
    const std::size_t count = inbetween_count(m_frames);
    for (std::size_t number = 1; number <= count; ++number) {
        const NamedText file = inbetween_file(m_frames, m_keys.key1, number);
        if (auto problem = write_file(file.name, file.content)) {
            say(problem->to_string());
            say(std::string(text::ask_stop));
            return;
        }
        record_written(file.name);
    }
    m_files.log("surface fitting: " + std::to_string(count) + " in-betweens of " + std::to_string(m_point_count) +
                " points written");
    say(std::string(text::fitting_done));
    say(std::string(text::ask_draw));
    m_phase = SessionPhase::ask_draw;
}

void Session::start_animation()
{
    std::vector<Vec3> scene;
    for (std::size_t k = 0; k < m_frames.frame_count(); ++k)
        scene.insert(scene.end(), m_frames.frame(k).begin(), m_frames.frame(k).end());
    m_animation_view = ViewTransform::fit(m_view_angles, scene, layout::drawing_area);
    m_frame = 0;
    m_paused = false;
    m_phase = m_frames.frame_count() == 0 ? SessionPhase::animation_done : SessionPhase::animating;
    m_files.log("animation: " + std::to_string(m_frames.frame_count()) + " frames, " + std::to_string(m_delay_ms) +
                " ms each");
}

} // namespace apcs
