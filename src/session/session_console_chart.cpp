#include "apcs/session/session.h"

#include "apcs/screens/session_text.h"

// The text console's chart: every command the key map lets through at a prompt, a question or the
// split is a row here (tests/input/charts.test.cpp walks them; the chart prints itself to
// tests/golden/session_console_chart.txt).
namespace apcs {

namespace {

using State = Session::ConsoleState;

} // namespace

const Session::ConsoleChart& Session::console_chart()
{
    static const ConsoleChart chart = make_console_chart();
    return chart;
}

KeyContext Session::key_context_of(ConsoleState leaf)
{
    switch (leaf) {
    case State::splitting: return KeyContext::splitting;
    case State::yes_question: return KeyContext::yes_to_go_on;
    case State::enter_question: return KeyContext::enter_to_go_on;
    case State::any_key_question: return KeyContext::any_key;
    case State::console:
    case State::text_line:
    case State::question: break;
    }
    return KeyContext::text_line;
}

// The leaf that listens with the step's keys (a text prompt's, else a question's or the split's).
Session::ConsoleState Session::console_leaf() const
{
    const KeyContext keys = step_key_context();
    for (const State leaf : {State::splitting, State::yes_question, State::enter_question, State::any_key_question})
        if (key_context_of(leaf) == keys)
            return leaf;
    return State::text_line;
}

Session::ConsoleChart Session::make_console_chart()
{
    using S = Session;
    using C = const Command&;
    std::vector<ConsoleChart::StateInfo> states = {
        {State::console, "console", std::nullopt},
        {State::text_line, "text_line", State::console},
        {State::splitting, "splitting", State::console},
        {State::question, "question", State::console},
        {State::yes_question, "yes_question", State::question},
        {State::enter_question, "enter_question", State::question},
        {State::any_key_question, "any_key_question", State::question},
    };
    std::vector<ConsoleChart::Row> rows = {
        {State::text_line, on<command::TypeCharacter>, {}, nullptr,
         "typed into the answer (not a control or zero-width character, 200 bytes at most)",
         [](S& s, C c) { s.type_into_line(std::get<command::TypeCharacter>(c).character); }},
        {State::text_line, on<command::EraseCharacter>, {}, nullptr, "the answer's last character erased",
         [](S& s, C) { s.erase_last_typed(); }},
        {State::text_line, on<command::ClearLine>, "the line empty", [](const S& s, C) { return s.m_console.input().empty(); },
         "asked: Quit APCS ? (Y/N)", [](S& s, C) { s.m_overlays.ask_quit(session_text::quit_apcs_question); }},
        {State::text_line, on<command::ClearLine>, {}, nullptr, "the line cleared",
         [](S& s, C) { s.m_console.set_input(""); }},
        {State::text_line, on<command::SubmitLine>, "the answer ? alone",
         [](const S& s, C) { return s.typed_answer() == "?"; }, "the help opened, the line emptied",
         [](S& s, C) {
             s.m_console.set_input("");
             s.m_overlays.open_help(KeyContext::text_line, s.empty_answer());
         }},
        {State::text_line, on<command::SubmitLine>, {}, nullptr,
         "the answer (an empty line: the prompt's, shown) to the step: the graph's next step",
         [](S& s, C) { s.submit_line(); }},
        {State::splitting, on<command::Back>, {}, nullptr, "the split stopped: the KEY2 prompt (files written stay)",
         [](S& s, C) { s.answer_question(); }},
        {State::question, on<command::Yes>, {}, nullptr, "answered: the graph's next step",
         [](S& s, C) { s.answer_question(); }},
        {State::question, on<command::Continue>, {}, nullptr, "answered: the graph's next step",
         [](S& s, C) { s.answer_question(); }},
    };
    return ConsoleChart(std::move(states), std::move(rows));
}

} // namespace apcs
