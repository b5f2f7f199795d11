#include "apcs/session/session.h"

#include "apcs/formats/numbered_files.h"
#include "apcs/base/overloaded.h"
#include "apcs/raster/screen_layout.h"
#include "session_pictures.h"
#include "apcs/screens/curve_raster.h"
#include "apcs/screens/words.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace apcs {

namespace {

std::string trimmed(const std::string& line)
{
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    const auto last = line.find_last_not_of(" \t");
    return line.substr(first, last - first + 1);
}

// From this many control points on, the terminal's session makes a path's evaluation arrays while
// its slopes prompt waits (10^6 points: 112 MB, 0.1-0.3 s on a virtual machine), 24 MB of segments
// a work() step so that a key typed meanwhile waits for no more. A shorter path's take a few ms at
// the opening, and never set the session to work at the prompt.
constexpr std::size_t points_worth_a_room = std::size_t{1} << 16;
constexpr std::size_t room_segments_a_step = std::size_t{1} << 18;

// A typed answer is a file name or a few numbers: longer input is not kept.
constexpr std::size_t max_answer_bytes = 200;

std::string without_last_character(const std::string& input)
{
    std::u32string characters = decode_utf8(input);
    if (!characters.empty())
        characters.pop_back();
    std::string shorter;
    for (const char32_t character : characters)
        append_utf8(shorter, character);
    return shorter;
}

} // namespace

Session::Session(SessionSettings settings, SessionFiles& files)
    : m_settings(std::move(settings))
    , m_files(files)
    , m_step(step::Key1Prompt{})
{
    ask({});
}

StepContext Session::context()
{
    return {m_settings, m_files, m_model, m_console, m_notice};
}

bool Session::animating() const
{
    const auto* playing = std::get_if<step::Playing>(&m_step);
    return playing != nullptr && playing->player.playing();
}

bool Session::showing_frames() const
{
    const auto* playing = std::get_if<step::Playing>(&m_step);
    return playing != nullptr && AnimationPlayer::chart().encloses(AnimationPlayer::State::showing, playing->player.leaf());
}

bool Session::takes_typed_text() const
{
    const KeyContext context = step_key_context();
    return context == KeyContext::text_line || context == KeyContext::value_field;
}

bool Session::keeps_step(const KeyEvent& event) const
{
    const KeyContext keys = key_context();
    const std::optional<Command> command = command_for(keys, event);
    return !command || stays_in_step(keys, *command);
}

void Session::handle(const KeyEvent& event)
{
    const ChangeCounts counted = counted_changes();
    const std::string notice = m_notice;
    take_key(event);
    if (counted_changes() != counted || m_notice != notice)
        ++m_revision;
}

Session::ChangeCounts Session::counted_changes() const
{
    const auto* shaping = std::get_if<step::Shaping>(&m_step);
    return {m_console.revision(), m_overlays.revision(), m_step_changes,
            shaping != nullptr ? shaping->editor.revision() : 0};
}

bool Session::showing_help() const { return m_overlays.help() != nullptr; }

void Session::say_goal(std::string feedback, std::string briefly)
{
    if (feedback == m_goal_feedback && briefly == m_goal_briefly)
        return;
    m_goal_feedback = std::move(feedback);
    m_goal_briefly = std::move(briefly);
    ++m_revision;
}

void Session::mark_goal(std::optional<Vec3> point)
{
    if (point == m_goal_point)
        return;
    m_goal_point = point;
    ++m_revision;
}

void Session::take_key(const KeyEvent& event)
{
    const std::optional<Command> command = command_for(key_context(), event);
    if (!command)
        return;
    m_notice.clear();
    m_step_result = {};
    chart().fire(*this, *command, [](const Session& session) { return session.leaf(); });
    follow(std::exchange(m_step_result, {}));
}

// A command the path screen or the animation takes by its own chart, through its step.
void Session::update_step(const Command& command)
{
    StepContext step_context = context();
    if (auto* shaping = std::get_if<step::Shaping>(&m_step))
        m_step_result = shaping->update(step_context, command);
    else if (auto* playing = std::get_if<step::Playing>(&m_step)) {
        // Each command the player's chart takes shows another frame or says paused.
        m_step_result = playing->update(step_context, command);
        ++m_step_changes;
    }
}

void Session::open_help() { m_overlays.open_help(step_key_context(), empty_answer()); }

void Session::type_into_line(char32_t character)
{
    std::string input = m_console.input();
    // A zero-width or control character would change the answer where nobody can see it.
    if (cell_width(character) > 0 && append_utf8_within(input, character, max_answer_bytes))
        m_console.set_input(input);
}

void Session::erase_last_typed() { m_console.set_input(without_last_character(m_console.input())); }

std::string Session::typed_answer() const { return trimmed(m_console.input()); }

// Enter on a typed line: the answer, an empty line taking the prompt's (the console shows it as
// typed), to the step, which says how it ended.
void Session::submit_line()
{
    StepContext step_context = context();
    const std::string typed = typed_answer();
    m_step_result = std::visit(
        [&](auto& prompt) -> StepResult {
            if constexpr (requires { prompt.default_answer(step_context); }) {
                const std::string answer = typed.empty() ? prompt.default_answer(step_context) : typed;
                m_console.set_input(answer);
                m_console.commit_input();
                return prompt.submit(step_context, answer);
            } else {
                return {};
            }
        },
        m_step);
}

// Y, Enter or any key, as the question asks: the key map lets only those through.
void Session::answer_question()
{
    StepContext step_context = context();
    m_step_result = std::visit(
        [&](auto& question) -> StepResult {
            if constexpr (requires { question.submit(step_context, std::string()); } &&
                          !requires { question.default_answer(step_context); })
                return question.submit(step_context, {});
            else
                return {};
        },
        m_step);
}

// The answer an empty line takes at the step's text prompt (its help names it); empty elsewhere.
std::string Session::empty_answer()
{
    const StepContext step_context = context();
    return std::visit(
        [&](const auto& step) -> std::string {
            if constexpr (requires { step.default_answer(step_context); })
                return step.default_answer(step_context);
            else
                return {};
        },
        m_step);
}

void Session::follow(StepResult result)
{
    while (result.outcome != StepOutcome::stay) {
        const bool followed = graph().fire(*this, result, [](const Session& session) { return session.step_leaf(); });
        assert(followed && "a step ended in a way the steps' graph does not know");
        StepContext step_context = context();
        if (!followed) {
            // Never drop a refusal unread.
            m_files.log("no step follows " + std::string(step_title()) + " on " +
                        std::string(StepGraph::event_name(ChartEvents<StepResult>::index(result))));
            if (!result.problem.empty())
                step_context.say(result.problem);
            return;
        }
        ++m_step_changes;
        const std::string problem = std::move(result.problem);
        result = std::visit(
            [&](auto& step) -> StepResult {
                if constexpr (requires { step.start(step_context); })
                    return step.start(step_context);
                else
                    return {};
            },
            m_step);
        if (result.outcome == StepOutcome::stay)
            ask(problem);
    }
}

// The prompt of the step begun: its lines, or after `problem` (a refusal) the lines that ask again.
void Session::ask(const std::string& problem)
{
    StepContext step_context = context();
    if (!problem.empty())
        step_context.say(problem);
    const step::Lines lines = std::visit(
        [&](const auto& step) { return problem.empty() ? step.lines(step_context) : step.again(step_context); }, m_step);
    for (const std::string& line : lines)
        step_context.say(line);
}

void Session::tick()
{
    ++m_revision;
    if (auto* playing = std::get_if<step::Playing>(&m_step))
        playing->player.tick();
}

bool Session::busy() const { return working() || preparing(); }

bool Session::working() const
{
    const auto* shaping = std::get_if<step::Shaping>(&m_step);
    return std::holds_alternative<step::Splitting>(m_step) || (shaping != nullptr && shaping->editor.refining());
}

const SessionPath* Session::path_wanting_room() const
{
    const auto* slopes = std::get_if<step::SlopesPrompt>(&m_step);
    if (slopes == nullptr || m_settings.refinement != Refinement::in_steps)
        return nullptr;
    const SessionPath& path = m_model.paths[static_cast<std::size_t>(slopes->path)];
    const std::size_t points = path.points.size();
    return points >= points_worth_a_room && !has_room(path.evaluation_room, points) ? &path : nullptr;
}

SessionPath* Session::path_wanting_room()
{
    return const_cast<SessionPath*>(std::as_const(*this).path_wanting_room());
}

void Session::work()
{
    ++m_revision;
    if (SessionPath* path = path_wanting_room()) {
        make_room(path->evaluation_room, path->points.size(), room_segments_a_step);
        return;
    }
    if (auto* shaping = std::get_if<step::Shaping>(&m_step))
        return shaping->editor.refine_step();
    auto* splitting = std::get_if<step::Splitting>(&m_step);
    if (splitting == nullptr)
        return;
    StepContext step_context = context();
    follow(splitting->work(step_context));
}

ProgramScreen Session::screen() const
{
    if (const overlay::HelpScreen* help = m_overlays.help())
        return {false, key_help_screen(step_title(), help->keys, help->empty_answer), {}};
    return std::visit(Overloaded{[&](const step::Shaping& shaping) { return graphics_screen(shaping.editor.view(m_goal_point, {m_goal_feedback, m_goal_briefly})); },
                                 [&](const step::Playing& playing) { return graphics_screen(playing.player.view()); },
                                 [&](const auto& text_step) {
                                     ProgramScreen shown{false, console_screen(), {}};
                                     std::string message = m_notice;
                                     if constexpr (std::is_same_v<std::decay_t<decltype(text_step)>, step::Splitting>)
                                         message = text_step.progress();
                                     if (message.empty())
                                         message = m_goal_feedback;
                                     if (!message.empty())
                                         shown.text.put_text(0, TextConsole::rows - 1, message);
                                     return shown;
                                 }},
                      m_step);
}

// The text console; the quit question, when asked at a prompt (where the line is empty), stands
// where the answer is typed, the cursor after it.
CellGrid Session::console_screen() const
{
    const overlay::QuitQuestion* asking = m_overlays.quit_question();
    if (asking == nullptr)
        return m_console.render(!finished());
    TextConsole question = m_console;
    question.set_input(std::string(asking->question));
    return question.render();
}

// The message line, by priority (SPEC §7.3): an open question, then what the last key did.
ProgramScreen Session::graphics_screen(GraphicsScreen picture) const
{
    const overlay::QuitQuestion* asking = m_overlays.quit_question();
    const std::string message = asking != nullptr ? std::string(asking->question) : m_notice;
    if (!message.empty()) {
        std::erase_if(picture.text, [](const TextLine& line) { return line.row == layout::message_row; });
        picture.text.push_back({1, layout::message_row, message});
    }
    return {true, {}, std::move(picture)};
}

void Session::save_picture()
{
    // The picture written is the final one, never a first picture still refined.
    if (auto* shaping = std::get_if<step::Shaping>(&m_step))
        shaping->editor.refine();
    ProgramScreen shown = screen();
    if (!shown.graphics) {
        m_notice = "P writes a picture in graphics mode only";
        return;
    }
    // A picture of the overlay draws every frame, not the terminal's first, middle and last.
    if (const auto* playing = std::get_if<step::Playing>(&m_step))
        shown.picture = playing->player.picture();
    for (int number = 1; number <= most_pictures; ++number) {
        const std::string name = picture_file_name(number);
        if (!m_files.exists(name)) {
            StepContext step_context = context();
            return write_picture(step_context, name, shown.picture, PngShape::monitor, "picture " + name);
        }
    }
    m_notice = "apcs001.png … apcs999.png all exist; move some away";
}

void Session::quit()
{
    m_files.log("quit at " + std::string(step_title()));
    m_overlays.close();
    StepContext step_context = context();
    if (auto* splitting = std::get_if<step::Splitting>(&m_step))
        static_cast<void>(splitting->close(step_context));
    m_step.emplace<step::Finished>();
    ++m_step_changes;
    static_cast<void>(std::get<step::Finished>(m_step).start(step_context));
    ask({});
}

const PathEditor* Session::path_editor() const
{
    const auto* shaping = std::get_if<step::Shaping>(&m_step);
    return shaping == nullptr ? nullptr : &shaping->editor;
}

namespace {

std::size_t largest_path(const SessionModel& model, const PathEditor* editor)
{
    std::size_t largest = 0;
    for (const SessionPath& path : model.paths)
        largest = std::max(largest, path.points.size());
    if (editor != nullptr)
        largest = std::max(largest, editor->points().size());
    return largest;
}

} // namespace

std::uint64_t Session::key_work() const { return 1 + std::uint64_t{largest_path(m_model, path_editor())}; }

std::uint64_t Session::key_work(const KeyEvent& event) const
{
    if (key_context() != KeyContext::waypoints || !keeps_step(event))
        return key_work();
    const std::size_t largest = largest_path(m_model, path_editor());
    return 1 + 2 * std::uint64_t{CurveRaster::block_segments(largest)} + largest / 64;
}

std::optional<int> Session::shaped_path() const
{
    const auto* shaping = std::get_if<step::Shaping>(&m_step);
    return shaping == nullptr ? std::nullopt : std::optional<int>(shaping->path);
}

} // namespace apcs
