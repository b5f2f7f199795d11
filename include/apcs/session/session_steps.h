#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/playback/animation_player.h"
#include "apcs/input/key_map.h"
#include "apcs/editor/path_editor.h"
#include "apcs/session/session_model.h"
#include "apcs/input/chart.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

// The steps of the 1989 session (thesis Ch. 4.2, SPEC §3), each a state that owns what it alone
// uses; what later steps read goes into the SessionModel. A step acts on its commands and says
// how it ended (StepResult); the session's steps' graph (session_graph.cpp) says which step
// follows, and each step's `after` says how it is made from the step before it.
//
// A text prompt gives: lines() printed when it begins, again() after a refusal, default_answer()
// for an empty line, submit() for the answer. A question (Y, Enter, any key) gives submit() too,
// with an empty answer. start(), where a step has it, runs as the step begins and may end it
// at once.
namespace apcs {

enum class StepOutcome { stay, answered, refused, stopped, done, first_path_accepted, last_path_accepted };

struct StepResult {
    StepResult(StepOutcome how = StepOutcome::stay, std::string why = {}) : outcome(how), problem(std::move(why)) {}

    StepOutcome outcome;
    // Printed before the next step's prompt (a refusal's reason, what a stop left).
    std::string problem;

    static StepResult refused(std::string why) { return {StepOutcome::refused, std::move(why)}; }
};

// The steps' graph (session_graph.cpp) is a chart whose events are how a step ended.
template <>
struct ChartEvents<StepResult> {
    static std::size_t index(const StepResult& result) { return static_cast<std::size_t>(result.outcome); }
    static std::string_view name(std::size_t index);
};

namespace step {

struct AskNext;

using Lines = std::vector<std::string>;

// Step 1 (fig. 4.2.1): the key frames.
struct Key1Prompt {
    Lines lines(const StepContext&) const;
    Lines again(const StepContext& context) const { return lines(context); }
    std::string default_answer(const StepContext&) const { return "key1.dat"; }
    StepResult submit(StepContext& context, const std::string& answer);

    static Key1Prompt after(const Key1Prompt&, StepContext&) { return {}; }
};

struct Key2Prompt {
    Lines lines(const StepContext&) const;
    Lines again(const StepContext& context) const { return lines(context); }
    std::string default_answer(const StepContext&) const { return "key2.dat"; }
    StepResult submit(StepContext& context, const std::string& answer);

    template <typename Before>
    static Key2Prompt after(const Before&, StepContext&) { return {}; }
};

// addpoint.c and split.c (SPEC §5.1, §5.2): equal point counts, then one path file per point,
// written a batch per work() so that keys are read between batches; Esc stops it.
struct Splitting {
    std::vector<Vec3> key1;
    std::vector<Vec3> key2;
    std::size_t written = 0;

    Lines lines(const StepContext&) const { return {}; }
    Lines again(const StepContext&) const { return {}; }
    StepResult start(StepContext& context);
    StepResult work(StepContext& context);
    // Esc: the files written stay (each whole), and KEY2 is asked again.
    StepResult submit(StepContext& context, const std::string& answer);
    // The message line while it writes.
    std::string progress() const;
    // Ends the batch of writes: the one disk barrier for all its files.
    Expected<void> close(StepContext& context);

    static Splitting after(const Key2Prompt&, StepContext& context);

private:
    std::size_t total() const { return std::min(key1.size(), key2.size()); }
    StepResult finish(StepContext& context);
};

// Step 2 (fig. 4.2.2), Define_View_Parameters.
struct ViewPrompt {
    Lines lines(const StepContext& context) const;
    Lines again(const StepContext& context) const;
    std::string default_answer(const StepContext& context) const;
    StepResult submit(StepContext& context, const std::string& answer);

    template <typename Before>
    static ViewPrompt after(const Before&, StepContext&) { return {}; }
};

// Step 3 (fig. 4.2.3), Read_data_file: the path file of graphic point `path` (0 first, 1 last).
struct PathPrompt {
    int path = 0;

    Lines lines(const StepContext& context) const;
    Lines again(const StepContext& context) const { return lines(context); }
    std::string default_answer(const StepContext& context) const;
    StepResult submit(StepContext& context, const std::string& answer);

    static PathPrompt after(const ViewPrompt&, StepContext&) { return {0}; }
    static PathPrompt after(const AskNext&, StepContext&) { return {1}; }
    static PathPrompt after(const PathPrompt& refused, StepContext&) { return refused; }
};

// Predefine-ENDS_slope: DS[0] and DD[N], on one line or one per line.
struct SlopesPrompt {
    int path = 0;
    // DS[0] typed alone on its line, waiting for DD[N].
    std::optional<double> first;

    Lines lines(const StepContext& context) const;
    Lines again(const StepContext& context) const;
    std::string default_answer(const StepContext& context) const;
    StepResult submit(StepContext& context, const std::string& answer);

    static SlopesPrompt after(const PathPrompt& read, StepContext&) { return {read.path, std::nullopt}; }
    static SlopesPrompt after(const SlopesPrompt& refused, StepContext&) { return {refused.path, std::nullopt}; }
};

// Steps 3–5 in graphics mode (Initial_Graphics): the PathEditor shapes path `path`; accepting
// writes it back with its staff values.
struct Shaping {
    int path = 0;
    PathEditor editor;

    Lines lines(const StepContext&) const { return {}; }
    Lines again(const StepContext&) const { return {}; }
    StepResult update(StepContext& context, const Command& command);

    static Shaping after(const SlopesPrompt& slopes, StepContext& context);

private:
    StepResult accept(StepContext& context);
};

// Step 5: "Adjust the next path ? (Y)".
struct AskNext {
    Lines lines(const StepContext&) const;
    Lines again(const StepContext& context) const { return lines(context); }
    StepResult submit(StepContext& context, const std::string& answer);

    static AskNext after(const Shaping&, StepContext&) { return {}; }
};

// Step 6 (fig. 4.2.7): "Stop the work ? (Enter)", then s_fiting.c.
struct AskStop {
    Lines lines(const StepContext&) const;
    Lines again(const StepContext& context) const { return lines(context); }
    StepResult submit(StepContext& context, const std::string& answer);

    template <typename Before>
    static AskStop after(const Before&, StepContext&) { return {}; }
};

// Surface fitting: the in-betweens written, the frames kept until the animation shows them.
struct Fitted {
    FrameSequence frames;

    Lines lines(const StepContext&) const;
    Lines again(const StepContext& context) const { return lines(context); }
    StepResult start(StepContext& context);
    StepResult submit(StepContext& context, const std::string& answer);

    static Fitted after(const AskStop&, StepContext&) { return {}; }
};

// Showing_Animation, then all frames overlaid (written as --png, --png-raw, --svg ask).
struct Playing {
    AnimationPlayer player;
    bool overlay_written = false;

    Lines lines(const StepContext&) const { return {}; }
    Lines again(const StepContext&) const { return {}; }
    StepResult update(StepContext& context, const Command& command);

    static Playing after(Fitted& fitted, StepContext& context);

private:
    void write_overlay(StepContext& context);
};

// The end: the files written.
struct Finished {
    Lines lines(const StepContext& context) const;
    Lines again(const StepContext& context) const { return lines(context); }
    StepResult start(StepContext& context);

    template <typename Before>
    static Finished after(const Before&, StepContext&) { return {}; }
};

} // namespace step

using Step = std::variant<step::Key1Prompt, step::Key2Prompt, step::Splitting, step::ViewPrompt, step::PathPrompt,
                          step::SlopesPrompt, step::Shaping, step::AskNext, step::AskStop, step::Fitted, step::Playing,
                          step::Finished>;

} // namespace apcs
