#include "apcs/session/session.h"

#include "apcs/formats/numbered_files.h"
#include "apcs/raster/painter.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/raster/svg_encoder.h"
#include "apcs/session/screen_layout.h"
#include "apcs/session/session_text.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace apcs {

namespace text = session_text;

const char* phase_name(SessionPhase phase)
{
    switch (phase) {
    case SessionPhase::ask_key1: return "step 1: KEY1 file";
    case SessionPhase::ask_key2: return "step 1: KEY2 file";
    case SessionPhase::splitting: return "step 1: splitting into path files";
    case SessionPhase::ask_view: return "step 2: view and delay";
    case SessionPhase::ask_path_file: return "step 3: path file";
    case SessionPhase::ask_slopes: return "step 3: end slopes";
    case SessionPhase::choose_control: return "step 3: global or local control";
    case SessionPhase::pick_region_first: return "step 3: first control point of the region";
    case SessionPhase::pick_region_last: return "step 3: last control point of the region";
    case SessionPhase::staff: return "step 4: four-line staff";
    case SessionPhase::waypoints: return "step 3: waypoint editor";
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

// A typed answer is a file name or a few numbers: longer input is not kept.
constexpr std::size_t max_answer_bytes = 200;

} // namespace

Session::Session(SessionSettings settings, SessionFiles& files)
    : m_settings(settings)
    , m_files(files)
    , m_step(TextStep{})
{
    go_to(SessionPhase::ask_key1);
}

SessionPhase Session::phase() const
{
    return std::visit([](const auto& step) { return step.phase(); }, m_step);
}

bool Session::animating() const
{
    const auto* player = std::get_if<AnimationPlayer>(&m_step);
    return player != nullptr && player->playing();
}

KeyContext Session::key_context() const
{
    if (m_help_for)
        return KeyContext::help_screen;
    if (m_asking_quit)
        return KeyContext::quit_question;
    return step_key_context();
}

KeyContext Session::step_key_context() const
{
    if (const auto* text_step = std::get_if<TextStep>(&m_step))
        return prompt_for(text_step->current).keys;
    if (const auto* editor = std::get_if<PathEditor>(&m_step))
        return editor->key_context();
    return std::get<AnimationPlayer>(m_step).key_context();
}

void Session::handle(const KeyEvent& event)
{
    const KeyContext context = key_context();
    const std::optional<Command> command = command_for(context, event);
    if (!command)
        return;
    m_notice.clear();
    if (!handle_everywhere(context, *command))
        dispatch_to_step(*command);
}

bool Session::handle_everywhere(KeyContext context, const Command& command)
{
    if (context == KeyContext::help_screen) {
        m_help_for.reset();
        return true;
    }
    if (context == KeyContext::quit_question) {
        m_asking_quit = false;
        if (std::holds_alternative<command::Yes>(command))
            quit();
        return true;
    }
    if (std::holds_alternative<command::ShowHelp>(command)) {
        m_help_for = context;
        return true;
    }
    if (std::holds_alternative<command::SavePicture>(command)) {
        save_picture();
        return true;
    }
    if (std::holds_alternative<command::Quit>(command)) {
        // Only an unsaved path is worth a question; elsewhere every file is already written.
        if (std::holds_alternative<PathEditor>(m_step))
            m_asking_quit = true;
        else
            quit();
        return true;
    }
    return false;
}

void Session::dispatch_to_step(const Command& command)
{
    if (auto* text_step = std::get_if<TextStep>(&m_step))
        return update_text_step(text_step->current, command);
    if (auto* editor = std::get_if<PathEditor>(&m_step)) {
        if (editor->update(command) == PathEditor::Outcome::accepted)
            accept_path(*editor);
        return;
    }
    auto& player = std::get<AnimationPlayer>(m_step);
    if (player.update(command) == AnimationPlayer::Outcome::finished)
        return finish();
    if (player.phase() == SessionPhase::overlay)
        write_overlay_once();
}

void Session::update_text_step(SessionPhase phase, const Command& command)
{
    const Prompt& prompt = prompt_for(phase);
    if (prompt.keys != KeyContext::text_line) {
        // Y, Enter or any key, as the prompt asks: the key map let only those through.
        if (prompt.submit != nullptr)
            (this->*prompt.submit)({});
        return;
    }
    std::string input = m_console.input();
    if (const auto* typed = std::get_if<command::TypeCharacter>(&command)) {
        // A zero-width or control character would change the answer where nobody can see it.
        if (input.size() < max_answer_bytes && cell_width(typed->character) > 0) {
            append_utf8(input, typed->character);
            m_console.set_input(input);
        }
    } else if (std::holds_alternative<command::EraseCharacter>(command)) {
        std::u32string characters = decode_utf8(input);
        if (!characters.empty())
            characters.pop_back();
        std::string shorter;
        for (const char32_t character : characters)
            append_utf8(shorter, character);
        m_console.set_input(shorter);
    } else if (std::holds_alternative<command::ClearLine>(command)) {
        m_console.set_input("");
    } else if (std::holds_alternative<command::SubmitLine>(command)) {
        if (trimmed(input) == "?") {
            // The answer ? alone asks for the help screen (SPEC §7.3); it is no answer.
            m_console.set_input("");
            m_help_for = KeyContext::text_line;
            return;
        }
        // An empty answer takes the thesis' example, and the console shows it as typed.
        const std::string answer = trimmed(input).empty() ? prompt.default_answer(*this) : trimmed(input);
        m_console.set_input(answer);
        m_console.commit_input();
        (this->*prompt.submit)(answer);
    }
}

void Session::go_to(SessionPhase phase)
{
    m_step = TextStep{phase};
    for (const std::string& line : prompt_for(phase).lines(*this))
        say(line);
}

void Session::ask_again(SessionPhase phase, const std::string& problem)
{
    m_step = TextStep{phase};
    say(problem);
    for (const std::string& line : prompt_for(phase).again(*this))
        say(line);
}

void Session::tick()
{
    if (auto* player = std::get_if<AnimationPlayer>(&m_step))
        player->tick();
}

SessionScreen Session::screen() const
{
    SessionScreen shown;
    if (m_help_for) {
        shown.text = help_screen();
        return shown;
    }
    if (const auto* editor = std::get_if<PathEditor>(&m_step)) {
        shown.graphics = true;
        shown.picture = editor->view();
    } else if (const auto* player = std::get_if<AnimationPlayer>(&m_step)) {
        shown.graphics = true;
        shown.picture = player->view();
    } else {
        shown.text = m_console.render(!finished());
        const std::string message = m_split ? split_progress() : m_notice;
        if (!message.empty())
            shown.text.put_text(0, TextConsole::rows - 1, message);
        return shown;
    }
    // The message line, by priority (SPEC §7.3): an open question, then what the last key did.
    const std::string message = m_asking_quit ? std::string(session_text::quit_question) : m_notice;
    if (!message.empty()) {
        auto& lines = shown.picture.text;
        lines.erase(std::remove_if(lines.begin(), lines.end(), [](const TextLine& line) { return line.row == layout::message_row; }),
                    lines.end());
        lines.push_back({1, layout::message_row, message});
    }
    return shown;
}

CellGrid Session::help_screen() const
{
    return key_help_screen(phase_name(phase()), *m_help_for);
}

void Session::save_picture()
{
    const SessionScreen shown = screen();
    if (!shown.graphics) {
        m_notice = "P writes a picture in graphics mode only";
        return;
    }
    for (int number = 1; number <= most_pictures; ++number) {
        const std::string name = picture_file_name(number);
        if (!m_files.exists(name))
            return write_picture(name, shown.picture, PngShape::monitor, "picture " + name);
    }
    m_notice = "apcs001.png … apcs999.png all exist; move some away";
}

void Session::write_overlay_once()
{
    if (m_overlay_written)
        return;
    m_overlay_written = true;
    const GraphicsScreen& overlay = std::get<AnimationPlayer>(m_step).view();
    for (const auto& [name, shape] : {std::pair{m_settings.overlay_png, PngShape::monitor},
                                      std::pair{m_settings.overlay_png_raw, PngShape::raw}}) {
        if (name)
            write_picture(*name, overlay, shape, "overlay of all frames written to " + *name);
    }
    if (m_settings.overlay_svg)
        store_picture(*m_settings.overlay_svg, encode_svg(overlay),
                      "overlay of all frames written to " + *m_settings.overlay_svg);
}

void Session::write_picture(const std::string& name, const GraphicsScreen& picture, PngShape shape,
                            const std::string& log_line)
{
    const std::optional<std::string> png = encode_png(render_raster(picture), shape);
    if (!png) {
        m_notice = name + ": cannot encode the PNG image";
        return;
    }
    store_picture(name, *png, log_line);
}

void Session::store_picture(const std::string& name, const std::string& bytes, const std::string& log_line)
{
    if (auto problem = write_file(name, bytes)) {
        m_notice = problem->to_string();
        return;
    }
    record_written(name);
    m_files.log(log_line);
    m_notice = "wrote " + name;
}

void Session::quit()
{
    m_files.log("quit at " + std::string(phase_name(phase())));
    if (m_split)
        close_split();
    finish();
}

std::optional<Diagnostic> Session::write_file(const std::string& name, const std::string& content)
{
    std::optional<Diagnostic> problem = m_files.write(name, content);
    if (problem)
        m_write_problem = problem;
    return problem;
}

void Session::record_written(const std::string& name)
{
    if (m_written_names.insert(name).second)
        m_written.push_back(name);
}

} // namespace apcs
