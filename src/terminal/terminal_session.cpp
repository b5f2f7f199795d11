#include "apcs/terminal/terminal_session.h"

#include "apcs/session/replay_caption.h"
#include "apcs/terminal/terminal.h"
#include "apcs/terminal/terminal_pixels.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace apcs {

namespace {

// What a replay lays over the session's screen: its caption, and during a paced replay the key
// just played.
struct ReplayShown {
    std::string_view caption;
    std::string_view played_key;
};

CellGrid grid_for(const SessionScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache,
                  ReplayShown replay)
{
    if (!fit_cell_area(size.columns, size.rows))
        return too_small_grid(size);
    return with_played_key(screen.graphics ? graphics_grid(screen.picture, size, glyphs, cache) : screen.text,
                           replay.played_key);
}

// The program's screen on the terminal: characters through curses and, where --pixels shows the
// drawing area as a picture, the picture over the rows curses leaves blank. A replay's caption, else
// why pictures are off (until a key is typed), goes on the caption row (with_caption).
void show_screen(Terminal& terminal, TerminalPixels& pixels, const InteractiveProgram& program, GlyphSet glyphs,
                 AsciiGlyphCache& cache, ReplayShown replay)
{
    if (replay.caption.empty())
        replay.caption = pixels.notice();
    const SessionScreen screen = with_caption(program.screen(), replay.caption);
    const TerminalSize size = terminal.size();
    const std::optional<PictureFrame> frame = screen.graphics ? pixels.frame_for(size) : std::nullopt;
    pixels.before_show(frame);
    CellGrid grid = grid_for(screen, size, glyphs, cache, replay);
    if (frame)
        grid = without_rows(std::move(grid), frame->blank_rows);
    const bool repainted = terminal.show(grid);
    if (frame)
        pixels.show(screen.picture, *frame, repainted);
}

// The session's work (the split) for about a frame's time, then back to the keys: Esc or Ctrl-C
// is read within that time, however many files are left.
void work_a_while(InteractiveProgram& session)
{
    constexpr auto slice = std::chrono::milliseconds(30);
    const auto start = std::chrono::steady_clock::now();
    do
        session.work();
    while (session.busy() && std::chrono::steady_clock::now() - start < slice);
}

// A script played into the terminal session: how far, and at what pace.
class Replay {
public:
    Replay(const KeyScript& script, ReplayPace pace) : m_script(script), m_pace(pace) {}

    bool playing() const { return m_played < m_script.events.size(); }
    // Inside a step of several keys (a TEXT line), whose other keys play at once.
    bool mid_step() const { return m_played < m_step_end; }
    ReplayPace::Kind pace() const { return m_pace.kind; }
    int pace_ms() const { return m_pace.milliseconds; }
    // Played a step per Space, a Space typed while the animation plays is the replay's next step,
    // held until the animation ends (not the animation's pause key, which would stop the lesson).
    bool holds_space(const InteractiveProgram& program, const KeyEvent& key) const
    {
        return key.key == Key::space && m_pace.kind == ReplayPace::Kind::on_space && playing() && !m_stopped &&
               program.animating();
    }
    void hold_step() { m_step_held = true; }
    // A goal is the student's: a Space held before it is not its answer.
    void drop_held_step() { m_step_held = false; }
    bool take_held_step() { return std::exchange(m_step_held, false); }
    KeyEvent next()
    {
        if (!mid_step()) {
            m_step_end = m_played + step_length(m_script, m_played);
            m_step_label = step_label(m_script, m_played);
        }
        return m_script.events[m_played++];
    }
    // The captions reached and not yet told, to `hooks`, over `program`'s screen: when it is
    // neither splitting nor animating, as a headless replay reaches them. After Esc ended the
    // replay (stop), none is.
    void tell_captions(const InteractiveProgram& program, const ReplayHooks& hooks)
    {
        if (!hooks.caption_reached || m_stopped || program.busy() || program.animating())
            return;
        for (; m_told < m_script.captions.size() && m_script.captions[m_told].before_event <= m_played; ++m_told)
            hooks.caption_reached(m_told, with_caption(program.screen(), m_script.captions[m_told].text));
    }
    // At a goal that does not hold yet: what the caption row says ("GOAL: tension +0.10, want …"),
    // while the student's keys go to the program. A goal that holds is passed, its answer's keys
    // skipped. nullopt when the replay is not at a goal, or the program is splitting or animating.
    std::optional<std::string> goal_waiting(const InteractiveProgram& program, const ReplayHooks& hooks)
    {
        m_goal_said.clear();
        if (!hooks.goal_progress || m_stopped || mid_step() || program.busy() || program.animating())
            return std::nullopt;
        const std::vector<ScriptGoal>& goals = m_script.goals;
        for (; m_goal < goals.size() && goals[m_goal].before_event <= m_played; ++m_goal) {
            if (goals[m_goal].before_event < m_played)
                continue;
            const GoalProgress progress = hooks.goal_progress(m_goal);
            if (!progress.reached) {
                m_goal_said = "GOAL: " + progress.said;
                return m_goal_said;
            }
            m_played = m_step_end = goals[m_goal].answer_end;
        }
        return std::nullopt;
    }
    // Esc during a paced replay: the keyboard takes over.
    void stop()
    {
        m_played = m_step_end = m_script.events.size();
        m_stopped = true;
    }
    void key_typed() { m_typed_after = !playing(); }
    // The caption reached and, when paced, the step just played, until a key is typed after the
    // replay.
    ReplayShown shown() const
    {
        if (m_typed_after)
            return {};
        if (!m_goal_said.empty())
            return {m_goal_said, {}};
        const ScriptCaption* caption = caption_at(m_script, m_played);
        return {caption == nullptr ? std::string_view{} : std::string_view(caption->text),
                m_pace.kind == ReplayPace::Kind::at_once ? std::string_view{} : std::string_view(m_step_label)};
    }

private:
    const KeyScript& m_script;
    ReplayPace m_pace;
    std::size_t m_played = 0;
    std::size_t m_step_end = 0;
    std::string m_step_label;
    bool m_typed_after = false;
    std::size_t m_told = 0;
    bool m_stopped = false;
    std::size_t m_goal = 0;
    std::string m_goal_said;
    bool m_step_held = false;
};

// The next input of a replay that waits to play a key: the script's key at its pace (`scripted`
// set; the rest of a TEXT line at once), or what the terminal reported meanwhile. A key typed during a paced replay is dropped
// (Esc ends the replay); nullopt means there is nothing to act on this time round.
std::optional<TerminalInput> replay_input(Terminal& terminal, Replay& replay, KeyEvent& key)
{
    if (replay.pace() == ReplayPace::Kind::at_once || replay.mid_step() || replay.take_held_step()) {
        key = replay.next();
        return TerminalInput::key;
    }
    const bool timed = replay.pace() == ReplayPace::Kind::every;
    const TerminalInput input = terminal.read_key(timed ? replay.pace_ms() : -1, key);
    if (input == TerminalInput::timeout && timed) {
        key = replay.next();
        return TerminalInput::key;
    }
    if (input != TerminalInput::key)
        return input;
    if (key.key == Key::escape)
        replay.stop();
    else if (!timed && key.key == Key::space) {
        key = replay.next();
        return TerminalInput::key;
    }
    return std::nullopt;
}

} // namespace

CellGrid too_small_grid(TerminalSize size)
{
    CellGrid grid(size.columns, size.rows);
    // The least fit_cell_area accepts: the character screen of graphics mode.
    const std::string message = "The terminal must be at least " + std::to_string(text_screen_columns) + "x" +
                                std::to_string(text_screen_rows) + " (it is " + std::to_string(size.columns) + "x" +
                                std::to_string(size.rows) + ")";
    const std::string keys = "Keys are ignored until it is larger; Ctrl-C quits";
    const int column = std::max(0, (size.columns - static_cast<int>(message.size())) / 2);
    grid.put_text(column, size.rows / 2, message);
    grid.put_text(std::max(0, (size.columns - static_cast<int>(keys.size())) / 2), size.rows / 2 + 1, keys);
    return grid;
}

CellGrid graphics_grid(const GraphicsScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache)
{
    const std::optional<CellArea> area = fit_cell_area(size.columns, size.rows);
    return area ? render_cells(screen, *area, glyphs, cache) : too_small_grid(size);
}

Expected<ExitStatus> run_terminal_session(InteractiveProgram& session, const KeyScript& script, ReplayPace pace,
                                          GlyphSet glyphs, ColourChoice colour, PixelChoice pixel_choice,
                                          std::vector<KeyEvent>& recorded, const ReplayHooks& hooks)
{
    Expected<std::unique_ptr<Terminal>> opened = Terminal::open(colour);
    if (!opened)
        return opened.error();
    const std::unique_ptr<Terminal> terminal = std::move(*opened);
    TerminalPixels pixels(*terminal, terminal->detect_pixels(pixel_choice));
    Replay replay(script, pace);
    AsciiGlyphCache cache;
    while (!session.finished()) {
        replay.tell_captions(session, hooks);
        // At a goal the keyboard is the student's (Esc included) until it holds.
        const bool at_goal = replay.goal_waiting(session, hooks).has_value();
        if (at_goal)
            replay.drop_held_step();
        show_screen(*terminal, pixels, session, glyphs, cache, replay.shown());
        KeyEvent key;
        std::optional<TerminalInput> input;
        // A scripted key waits for the split, as a typed one would (Esc would stop it).
        const bool scripted = !at_goal && replay.playing() && !session.animating() && !session.busy();
        if (scripted)
            input = replay_input(*terminal, replay, key);
        else
            input = terminal->read_key(session.busy() ? 0 : session.animating() ? session.delay_ms() : -1, key);
        if (input == TerminalInput::key && !at_goal && replay.holds_space(session, key)) {
            replay.hold_step();
            continue;
        }
        if (!input)
            continue;
        switch (*input) {
        case TerminalInput::stop:
            return ExitStatus::stopped;
        case TerminalInput::resize:
            terminal->invalidate();
            break;
        case TerminalInput::timeout:
            if (session.busy())
                work_a_while(session);
            else
                session.tick();
            break;
        case TerminalInput::key:
            // Ctrl-L repaints the whole terminal; the session sees the key too.
            if (key.key == Key::redraw)
                terminal->redraw();
            // Keys typed at the too-small screen would act on a session nobody can see.
            if (!fit_cell_area(terminal->size().columns, terminal->size().rows))
                break;
            if (!scripted && !at_goal) {
                replay.key_typed();
                pixels.clear_notice();
            }
            recorded.push_back(key);
            session.handle(key);
            break;
        }
    }
    return ExitStatus::success;
}

} // namespace apcs
