#include "apcs/session/session.h"

#include "apcs/screens/words.h"

#include "step_leaves.h"

// The session's chart: every command the key map lets through in each leaf is a row here, a
// written ignore, or handed to the path editor's or the player's chart (tests/input/charts.test.cpp
// walks them all; the charts print themselves to tests/golden/session_chart.txt).
namespace apcs {

namespace {

using State = Session::State;
// The rows' lambdas take (S&, C), their guards (const S&, C).
using S = Session;
using C = const Command&;

// `ask` of the chart below the step, the path editor's or the player's; none at a step without one.
template <typename Ask>
auto ask_chart_below(const Step& step, Ask ask) -> std::optional<decltype(ask(std::declval<const PathEditor&>()))>
{
    if (const auto* shaping = std::get_if<step::Shaping>(&step))
        return ask(shaping->editor);
    if (const auto* playing = std::get_if<step::Playing>(&step))
        return ask(playing->player);
    return std::nullopt;
}

} // namespace

const Session::SessionChart& Session::chart() { return SessionChart::once<&make_chart>(); }

Session::State Session::step_leaf() const { return session_leaves::of_step[m_step.index()]; }

Session::State Session::leaf() const
{
    if (m_overlays.help() != nullptr)
        return State::help;
    if (m_overlays.quit_question() != nullptr)
        return State::quit_question;
    return step_leaf();
}

std::string_view Session::leaf_name() const
{
    const auto below = ask_chart_below(m_step, [](const auto& room) { return room.chart().info(room.leaf()).name; });
    return below && leaf() == step_leaf() ? *below : chart().info(leaf()).name;
}

std::string_view Session::step_title() const
{
    return ask_chart_below(m_step, [](const auto& room) { return room.title(); }).value_or(chart().title(step_leaf()));
}

KeyContext Session::step_key_context() const
{
    const auto below = ask_chart_below(m_step, [](const auto& room) { return room.key_context(); });
    return below ? *below : *chart().keys(step_leaf());
}

KeyContext Session::key_context() const
{
    const State now = leaf();
    return now == State::help || now == State::quit_question ? *chart().keys(now) : step_key_context();
}

Session::SessionChart Session::make_chart()
{
    std::vector<SessionChart::StateInfo> states = {
        {State::session, "session", std::nullopt},
        {State::overlays, "overlays", State::session},
        {State::help, "help", State::overlays, KeyContext::help_screen},
        {State::quit_question, "quit_question", State::overlays, KeyContext::quit_question},
        {State::steps, "steps", State::session},
        {State::console, "console", State::steps},
        {State::text_line, "text_line", State::console, KeyContext::text_line},
        {State::ask_key1, "ask_key1", State::text_line, {}, "step 1: KEY1 file"},
        {State::ask_key2, "ask_key2", State::text_line, {}, "step 1: KEY2 file"},
        {State::splitting, "splitting", State::console, KeyContext::splitting, "step 1: splitting into path files"},
        {State::ask_view, "ask_view", State::text_line, {}, "step 2: view and delay"},
        {State::ask_path_file, "ask_path_file", State::text_line, {}, "step 3: path file"},
        {State::ask_slopes, "ask_slopes", State::text_line, {}, "step 3: end slopes"},
        {State::question, "question", State::console},
        {State::ask_next_path, "ask_next_path", State::question, KeyContext::yes_to_go_on, "step 5: next path"},
        {State::ask_stop, "ask_stop", State::question, KeyContext::enter_to_go_on, "step 6: stop the work"},
        {State::ask_draw, "ask_draw", State::question, KeyContext::any_key, "step 6: surface fitting done"},
        // Their keys and titles are their charts' leaves'.
        {State::path_screen, "path_screen", State::steps},
        {State::player, "player", State::steps},
        {State::finished, "finished", State::steps, KeyContext::finished, "end"},
    };
    std::vector<SessionChart::Row> rows = any_step_rows();
    std::vector<SessionChart::Row> more = console_rows();
    rows.insert(rows.end(), more.begin(), more.end());
    return SessionChart(std::move(states), std::move(rows));
}

// The overlays, and the keys the session takes at any step.
std::vector<Session::SessionChart::Row> Session::any_step_rows()
{
    return {
        // Laid over the step: any key closes the help; Y to the question quits.
        {State::help, on<command::Continue>, {}, nullptr, "the help closed", [](S& s, C) { s.m_overlays.close(); },
         State::steps},
        {State::quit_question, on<command::Yes>, {}, nullptr, "quit: the files written listed, logged",
         [](S& s, C) { s.quit(); }, State::finished},
        {State::quit_question, on<command::No>, {}, nullptr, "back to the step as it was",
         [](S& s, C) { s.m_overlays.close(); }, State::steps},
        // Any step: help, a picture, quitting.
        {State::steps, on<command::ShowHelp>, {}, nullptr, "the help of the step's keys laid over it",
         [](S& s, C) { s.open_help(); }, State::help},
        {State::steps, on<command::SavePicture>, {}, nullptr,
         "the screen written to the first free apcs001.png ... apcs999.png (graphics mode only: said)",
         [](S& s, C) { s.save_picture(); }},
        {State::steps, on<command::Quit>, {}, nullptr, "quit: the files written listed, logged",
         [](S& s, C) { s.quit(); }, State::finished},
    };
}

// A prompt's line, the split and the questions, and the screens with charts of their own.
std::vector<Session::SessionChart::Row> Session::console_rows()
{
    return {
        {State::text_line, on<command::TypeCharacter>, {}, nullptr,
         "typed into the answer (not a control or zero-width character, 200 bytes at most)",
         [](S& s, C c) { s.type_into_line(std::get<command::TypeCharacter>(c).character); }},
        {State::text_line, on<command::EraseCharacter>, {}, nullptr, "the answer's last character erased",
         [](S& s, C) { s.erase_last_typed(); }},
        {State::text_line, on<command::ClearLine>, "the line empty", [](const S& s, C) { return s.m_console.input().empty(); },
         "asked: Quit APCS ? (Y/N)", [](S& s, C) { s.m_overlays.ask_quit(words::quit_apcs_question); },
         State::quit_question},
        {State::text_line, on<command::ClearLine>, {}, nullptr, "the line cleared",
         [](S& s, C) { s.m_console.set_input(""); }},
        {State::text_line, on<command::SubmitLine>, "the answer ? alone",
         [](const S& s, C) { return s.typed_answer() == "?"; }, "the line emptied, the help laid over the step",
         [](S& s, C) {
             s.m_console.set_input("");
             s.open_help();
         },
         State::help},
        {State::text_line, on<command::SubmitLine>, {}, nullptr,
         "the answer (an empty line: the prompt's, shown) to the step: the steps' graph", [](S& s, C) { s.submit_line(); },
         State::steps},
        // The split and the questions.
        {State::splitting, on<command::Back>, {}, nullptr, "the split stopped (files written stay): the steps' graph",
         [](S& s, C) { s.answer_question(); }, State::steps},
        {State::question, on<command::Yes>, {}, nullptr, "answered: the steps' graph", [](S& s, C) { s.answer_question(); },
         State::steps},
        {State::question, on<command::Continue>, {}, nullptr, "answered: the steps' graph",
         [](S& s, C) { s.answer_question(); }, State::steps},
        // The screens with charts of their own; only a path being shaped is not yet saved.
        {State::path_screen, on<command::Quit>, {}, nullptr, "asked: Quit without saving this path ? (Y/N)",
         [](S& s, C) { s.m_overlays.ask_quit(words::quit_question); }, State::quit_question},
        {State::path_screen, any_other_event, {}, nullptr,
         "to the path editor's chart (an accepted path: the steps' graph)", [](S& s, C c) { s.update_step(c); },
         State::steps},
        {State::player, any_other_event, {}, nullptr, "to the animation player's chart (its end: the steps' graph)",
         [](S& s, C c) { s.update_step(c); }, State::steps},
    };

}

} // namespace apcs
