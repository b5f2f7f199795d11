#include "apcs/cli/session_command.h"

#include "apcs/base/utf8.h"
#include "handout_writer.h"
#include "memory_limit.h"
#include "report.h"
#include "session_parts.h"
#include "apcs/cli/script_options.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/input_check.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/input/play_to_idle.h"
#include "apcs/lesson/handout.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/session/rewindable_files.h"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <memory>
#include <limits>
#include <optional>
#include <ostream>
#include <string_view>
#include <unistd.h>

namespace apcs {

SessionSettings session_settings(const CommonOptions& options)
{
    SessionSettings settings;
    settings.samples_per_segment = options.path.samples_per_segment;
    settings.inbetween_count = options.path.inbetween_count;
    settings.spacing = options.path.spacing;
    settings.surface = options.surface;
    settings.step = options.step;
    if (options.given.theta)
        settings.theta_degrees = options.view.theta_degrees;
    if (options.given.phi)
        settings.phi_degrees = options.view.phi_degrees;
    if (options.given.delay)
        settings.delay_ms = options.delay_ms;
    settings.delay_overrides_answer = options.given.delay && options.keys.has_value();
    if (options.given.slopes)
        settings.slopes = options.path.slopes;
    settings.staff = options.staff;
    // The session writes in its folder; a name typed relative to where apcs started stays so.
    const auto as_started = [&options](const std::filesystem::path& name) {
        return (options.workdir.empty() || name.is_absolute() ? name : std::filesystem::absolute(name)).string();
    };
    if (options.png)
        settings.overlay_png = as_started(*options.png);
    if (options.png_raw)
        settings.overlay_png_raw = as_started(*options.png_raw);
    if (options.svg)
        settings.overlay_svg = as_started(*options.svg);
    return settings;
}

std::size_t run_headless_session(ReplayDriver& replay, const Session& session, GlyphSet glyphs, std::ostream& out)
{
    // A step's screen is printed when the next one has another title (the transcript's steps): the
    // screen after the last key the step took. It is drawn only before a key that may end the step
    // (a path of 16,000 waypoints inserted, 10^6 staff keys: a screen a key would be most of the
    // replay's time).
    std::string shown = screen_text(session.screen(), glyphs);
    std::size_t drawn = 1;
    bool shown_is_current = true;
    std::string_view shown_title = session.step_title();
    const auto draw_current = [&] {
        if (!shown_is_current) {
            shown = screen_text(session.screen(), glyphs);
            ++drawn;
        }
        shown_is_current = true;
    };
    const auto print_shown = [&] { out << "--- " << shown_title << '\n' << shown; };
    // Nobody can press Esc: each split runs to its end, and the animation's last frame ends its
    // step.
    IdleDrive drive;
    drive.before_step = [&] {
        // While the session works (a split), its screens are not a step's last: the last was drawn
        // before the key that set it to work.
        if (!session.busy() && !replay.next_work_keeps_step())
            draw_current();
    };
    drive.after_step = [&] {
        if (session.busy())
            return;
        if (session.step_title() != shown_title) {
            assert(shown_is_current && "a key vouched to keep its step ended it");
            print_shown();
        }
        shown_is_current = false;
        shown_title = session.step_title();
    };
    play_to_idle(replay, drive);
    draw_current();
    replay.finish();
    // The last step: the end, or where a script that ends mid-step stopped and why.
    print_shown();
    return drawn;
}

namespace {

// The steps of run_session_command. A step that refuses writes its reason to `err` and returns the
// exit status; nullopt lets the session go on.

std::optional<ExitStatus> refuse_work_folder(const std::filesystem::path& folder, std::ostream& err)
{
    std::error_code error;
    if (std::filesystem::is_directory(folder, error))
        return std::nullopt;
    err << escape_controls(folder.string()) << ": is not a folder; expected the folder to work in (--workdir)\n";
    return ExitStatus::bad_input;
}

// An exercise's INPUT lines checked against the work folder before anything is written: a file a
// session rewrote (an accepted path) could meet the goal with no key typed (issue 43). The run is
// refused, on a terminal too, rather than replayed on the exercise's files: the script holds their
// checksums only, not their content.
std::optional<ExitStatus> refuse_changed_inputs(const CommonOptions& options, const KeyScript& script,
                                                const std::filesystem::path& folder, std::ostream& err)
{
    if (const Expected<void> checked = check_script_inputs(script.inputs, folder, options.keys->string()); !checked)
        return report_bad_input(checked.error(), err);
    return std::nullopt;
}

// An exercise (a script with GOAL lines) sets its task (`task`: the defaults and its OPTIONS): the
// command line may not start the staff elsewhere or change what its goals measure, or apcs grade
// would grade the recording "other".
std::optional<ExitStatus> refuse_changed_task(const KeyScript& script, const CommonOptions& task,
                                              const CommonOptions& options, std::ostream& err)
{
    if (script.goals.empty())
        return std::nullopt;
    const std::optional<std::string> changed = changed_task_option(task, options);
    if (!changed)
        return std::nullopt;
    err << "apcs: " << *changed << ": " << escape_controls(options.keys->string())
        << " is an exercise (it has GOAL lines) and this changes its task: apcs grade would grade the recording "
           "'other'; expected the exercise's own (only --step, --delay, --theta and --phi may differ)\n";
    return ExitStatus::bad_usage;
}

// --keys FILE: its script into `script`, its text into `script_text`, its OPTIONS line into
// `options` (where the command line gave none of them), an exercise's inputs checked in `folder`;
// nothing without --keys.
std::optional<ExitStatus> read_key_script(CommonOptions& options, const std::filesystem::path& folder,
                                          KeyScript& script, std::string& script_text, std::ostream& err)
{
    if (!options.keys)
        return std::nullopt;
    // The terminal session reads its keys from standard input: a script cannot come from there too.
    if (*options.keys == "-" && ::isatty(STDIN_FILENO)) {
        err << "apcs: --keys -: standard input is a terminal; pipe the script in, or give --keys FILE\n";
        return ExitStatus::bad_usage;
    }
    const Expected<std::string> text = read_script_text(*options.keys, max_key_script_bytes);
    if (!text)
        return report_bad_input(text.error(), err);
    Expected<KeyScript> parsed = parse_captioned_key_script(*text, options.keys->string());
    if (!parsed)
        return report_bad_input(parsed.error(), err);
    const Expected<CommonOptions> task = options_of_script(parsed->options, options.keys->string());
    if (!task)
        return report_bad_input(task.error(), err);
    merge_script_options(*task, options);
    if (const std::optional<ExitStatus> refused = refuse_changed_task(*parsed, *task, options, err))
        return refused;
    const auto inbetweens = static_cast<std::size_t>(std::max(options.path.inbetween_count, 0));
    if (Expected<void> reachable = goals_within_inbetweens(parsed->goals, inbetweens, options.keys->string()); !reachable)
        return report_bad_input(reachable.error(), err);
    if (const std::optional<ExitStatus> refused = refuse_changed_inputs(options, *parsed, folder, err))
        return refused;
    script = std::move(*parsed);
    script_text = *text;
    return std::nullopt;
}

// A replay needs a script, and so does a handout; a paced one, a terminal; a session without a terminal, a script.
std::optional<ExitStatus> refuse_replay_without_its_needs(const CommonOptions& options, bool headless,
                                                          std::ostream& err)
{
    const bool paced = options.pace.kind != ReplayPace::Kind::at_once;
    if (paced && !options.keys) {
        err << "apcs: --pace paces a --keys replay; give --keys FILE\n";
        return ExitStatus::bad_usage;
    }
    if (options.handout && !options.keys) {
        err << "apcs: --handout writes the captions of a --keys replay; give --keys FILE\n";
        return ExitStatus::bad_usage;
    }
    if (options.paper && !options.handout) {
        err << "apcs: --paper draws the pages of a handout black on white; give --handout DIR\n";
        return ExitStatus::bad_usage;
    }
    if (headless && !options.keys) {
        err << "apcs: standard input is not a terminal; give --keys FILE to replay a session without one\n";
        return ExitStatus::terminal_problem;
    }
    if (paced && headless) {
        err << "apcs: --pace paces a replay on a terminal; without one the script plays at once (leave --pace out)\n";
        return ExitStatus::bad_usage;
    }
    return std::nullopt;
}

// What a replay keeps for after it: the keys for --record, each goal's outcome for apcs grade.
struct ReplayKept {
    KeyRecording recording;
    std::vector<GoalOutcome> goals;
    std::optional<Diagnostic> unwritten; // the session's first write that failed
    // The KEY files of every session the replay played into (ReplayDriver::key_files_read).
    std::vector<std::string> key_files;
    std::uint64_t work_done = 0; // the operations the replay cost (ReplayDriver::work_done)
};

// The settings of a session that `options` asks for, within the memory budget `limit`. On a
// terminal a key's first picture comes at once and is refined while no key waits; headless, every
// key's work is done before the next (the screens printed are final).
SessionSettings replay_settings(const CommonOptions& options, std::uint64_t limit, ReplayAudience audience)
{
    SessionSettings settings = session_settings(options);
    settings.memory_limit_bytes = limit;
    settings.refinement = audience == ReplayAudience::headless ? Refinement::at_once : Refinement::in_steps;
    return settings;
}

// Where a headless replay's transcript goes: each step's screen (in `glyphs`) and each caption
// as ";; TEXT" where it is reached, on `out`; none without `out`, and then no screen is drawn at
// all (apcs grade: drawing screens is most of a replay's time, and nobody would see them).
struct Transcript {
    std::ostream* out = nullptr;
    GlyphSet glyphs = GlyphSet::ascii;
    // Without a transcript: the operations the replay may cost (ReplayDriver::work_done); it
    // stops once its keys have cost more, the rest unplayed and no goal judged.
    std::uint64_t work_budget = std::numeric_limits<std::uint64_t>::max();
};

// The script replayed at once, its transcript as `transcript` says. Nobody watched the screen: a
// file that could not be written is the run's failure.
ExitStatus replay_headless(Session& session, const KeyScript& script, const std::string& file_name,
                           Transcript transcript, ReplayHooks hooks, ReplayKept& kept, std::ostream& err)
{
    if (transcript.out != nullptr)
        hooks.caption_reached = [out = transcript.out, &script, pages = std::move(hooks.caption_reached)](
                                    std::size_t index, const ProgramScreen& shown) {
            *out << ";; " << script.captions[index].text << '\n';
            if (pages)
                pages(index, shown);
        };
    ReplayDriver replay(session, script, file_name, ReplayPace{}, std::move(hooks), ReplayAudience::headless);
    if (transcript.out != nullptr)
        run_headless_session(replay, session, transcript.glyphs, *transcript.out);
    else {
        IdleDrive within_budget;
        within_budget.go_on = [&replay, &transcript] { return replay.work_done() <= transcript.work_budget; };
        play_to_idle(replay, within_budget);
        kept.work_done = replay.work_done();
        if (kept.work_done > transcript.work_budget)
            return ExitStatus::bad_input;
        replay.finish();
    }
    kept.recording = replay.recording();
    kept.goals = replay.goal_outcomes();
    kept.key_files = replay.key_files_read();
    if (!session.writes())
        kept.unwritten = session.writes().error();
    if (!session.finished())
        err << "apcs: the key script ended at " << session.step_title() << '\n';
    if (!replay.goals())
        return report_bad_input(replay.goals().error(), err);
    if (!session.writes()) {
        err << "apcs: " << session.writes().error().to_string() << '\n';
        return ExitStatus::bad_input;
    }
    return ExitStatus::success;
}

// The session on the terminal, the script replayed first; the files it wrote listed on `out` at
// its end.
ExitStatus run_on_terminal(Session& session, const KeyScript& script, const CommonOptions& options, GlyphSet glyphs,
                           const TerminalRunner& terminal, ReplayHooks hooks, ReplayKept& kept,
                           std::ostream& out, std::ostream& err)
{
    const ColourChoice colour = session_colour(options.colour, std::getenv("NO_COLOR"));
    const std::string script_name = options.keys ? options.keys->string() : std::string();
    ReplayDriver replay(session, script, script_name, options.pace, std::move(hooks), ReplayAudience::terminal);
    const Expected<ExitStatus> ran = terminal(replay, glyphs, colour, options.pixels);
    // A goal still open when the session ended (or a signal ended it) is judged as it stood.
    if (ran)
        replay.finish();
    kept.recording = replay.recording();
    kept.key_files = replay.key_files_read();
    if (!ran) {
        err << ran.error().to_string() << '\n';
        return ExitStatus::terminal_problem;
    }
    const ExitStatus status = *ran;
    if (status == ExitStatus::stopped) {
        err << "apcs: stopped; every file written so far is whole\n";
        return status;
    }
    // As the last screen said it, a name a line (for scripts), once the terminal is given back.
    const std::vector<std::string>& written = replay.session().written_files();
    out << (written.empty() ? "APCS is done. No file written.\n" : "APCS is done. Files written:\n");
    for (const std::string& name : written)
        out << escape_controls(name) << '\n';
    return status;
}

// --handout DIR: its folder made before the session starts; nullopt without --handout.
std::optional<ExitStatus> open_handout(const CommonOptions& options, std::optional<HandoutWriter>& handout,
                                       std::ostream& err)
{
    if (!options.handout)
        return std::nullopt;
    Expected<HandoutWriter> opened = HandoutWriter::open(*options.handout, options.paper ? PngInk::paper : PngInk::monitor);
    if (!opened)
        return report_bad_input(opened.error(), err);
    handout.emplace(std::move(*opened));
    return std::nullopt;
}

// The hooks of the replay: each caption's page of the handout, the screen at the end of its keys;
// none without a handout.
ReplayHooks replay_hooks(std::optional<HandoutWriter>& handout, const CommonOptions& options,
                         const KeyScript& script, GlyphSet glyphs, const std::filesystem::path& folder)
{
    ReplayHooks hooks;
    if (handout)
        hooks.caption_ended = [&handout, &options, &script, glyphs, folder](
                                  std::size_t index, const std::string& caption, const ProgramScreen& screen,
                                  const std::vector<std::string>& keys) {
            handout->write(static_cast<int>(index) + 1, script.captions.size(),
                           {script.captions[index].text, caption}, screen, glyphs, files_read(options, keys, folder));
        };
    return hooks;
}

// The handout's index.html written after its pages; a handout that could not be written is the
// run's failure, unless a signal stopped it.
ExitStatus handout_outcome(std::optional<HandoutWriter>& handout, const CommonOptions& options,
                           const std::vector<std::string>& key_files, const std::filesystem::path& folder,
                           ExitStatus status, std::ostream& err)
{
    if (!handout)
        return status;
    const std::string title = *options.keys == "-" ? std::string("standard input") : options.keys->filename().string();
    handout->finish(title, files_read(options, key_files, folder));
    if (handout->outcome()) {
        if (const std::optional<std::string> note = earlier_inbetweens_note(handout->earlier_pages()))
            err << "apcs: " << *note << '\n';
        return status;
    }
    if (status == ExitStatus::stopped)
        return status;
    err << "apcs: --handout: " << handout->outcome().error().to_string() << '\n';
    return ExitStatus::bad_input;
}

// What a session needs before it starts.
struct SessionStart {
    std::filesystem::path folder;
    std::uint64_t limit = 0; // the memory budget
    KeyScript script;
    std::string script_text;
    bool headless = false;
    GlyphSet glyphs = GlyphSet::ascii;
    std::optional<HandoutWriter> handout;
};

// The session's needs checked in order into `start`: its folder, its memory budget, the --keys
// script (its OPTIONS taken into `options`), a terminal or a script, glyphs it can show, the
// recording's target and the handout's folder. The first refusal's exit status, its reason on `err`.
std::optional<ExitStatus> check_session_start(CommonOptions& options, const TerminalRunner& terminal,
                                              SessionStart& start, std::ostream& err)
{
    start.folder = options.workdir.empty() ? std::filesystem::path(".") : options.workdir;
    if (const std::optional<ExitStatus> refused = refuse_work_folder(start.folder, err))
        return refused;
    const Expected<std::uint64_t> limit = memory_limit(options);
    if (!limit) {
        err << limit.error().to_string() << '\n';
        return ExitStatus::bad_usage;
    }
    start.limit = *limit;
    if (const std::optional<ExitStatus> refused =
            read_key_script(options, start.folder, start.script, start.script_text, err))
        return refused;
    start.headless = !::isatty(STDIN_FILENO) || !terminal;
    if (const std::optional<ExitStatus> refused = refuse_replay_without_its_needs(options, start.headless, err))
        return refused;
    const Expected<GlyphSet> glyphs = session_glyphs(options.glyphs, start.headless);
    if (!glyphs) {
        err << glyphs.error().to_string() << '\n';
        return ExitStatus::bad_usage;
    }
    start.glyphs = *glyphs;
    if (const std::optional<ExitStatus> refused =
            refuse_record_target(options, start.script_text, start.folder, start.headless, err))
        return refused;
    return open_handout(options, start.handout, err);
}

} // namespace

ExitStatus run_session_command(const CommonOptions& command_line, const TerminalRunner& terminal, std::ostream& out,
                               std::ostream& err)
{
    CommonOptions options = command_line; // and the --keys script's OPTIONS
    SessionStart start;
    if (const std::optional<ExitStatus> refused = check_session_start(options, terminal, start, err))
        return *refused;
    const std::filesystem::path& folder = start.folder;
    FolderFiles folder_files(folder);
    // PgUp and Home replay from the files as they were at the start: a paced replay on a terminal
    // keeps each file as first read (headless, nobody goes back: no copy is kept).
    RewindableFiles rewindable(folder_files);
    const bool can_go_back = !start.headless && options.pace.kind != ReplayPace::Kind::at_once;
    SessionFiles& files = can_go_back ? static_cast<SessionFiles&>(rewindable) : folder_files;
    // An answer typed at a prompt that names the recording is refused there, as a key file is.
    if (options.record && *options.record != "-")
        files.protect_key_file(std::filesystem::absolute(*options.record).string());
    files.log("session started");
    const SessionSettings settings =
        replay_settings(options, start.limit, start.headless ? ReplayAudience::headless : ReplayAudience::terminal);
    Session session(settings, files);
    ReplayKept kept;
    // With --record -, standard output holds the keystrokes, not the headless screens.
    std::ostream no_screens(nullptr);
    std::ostream& screens = options.record == std::filesystem::path("-") ? no_screens : out;
    ReplayHooks hooks = replay_hooks(start.handout, options, start.script, start.glyphs, folder);
    hooks.log = [&files](const std::string& line) { files.log(line); };
    if (can_go_back) {
        hooks.session_as_started = [&rewindable, &settings] {
            rewindable.rewind();
            return std::make_unique<Session>(settings, rewindable);
        };
        hooks.caught_up = [&rewindable] { rewindable.caught_up(); };
    }
    const ExitStatus replayed =
        start.headless
            ? replay_headless(session, start.script, options.keys->string(), {&screens, start.glyphs}, hooks, kept, err)
            : run_on_terminal(session, start.script, options, start.glyphs, terminal, hooks, kept, out, err);
    const ExitStatus status = handout_outcome(start.handout, options, kept.key_files, folder, replayed, err);
    if (status == ExitStatus::terminal_problem)
        return status;
    // A recording that fails is reported; a session stopped by a signal still ends as stopped.
    if (const std::optional<ExitStatus> refused =
            record_keys(options, files_read(options, kept.key_files, folder), kept.recording, out, err))
        return status == ExitStatus::stopped ? status : *refused;
    // A student at a terminal sees where the keys went, the file to hand in.
    if (!start.headless && options.record && *options.record != "-")
        out << "Keystrokes recorded in " << escape_controls(options.record->string()) << '\n';
    return status;
}

HeadlessReplay replay_in_folder(const KeyScript& script, const std::string& script_name,
                                const CommonOptions& command_line, const std::filesystem::path& folder,
                                std::ostream& err, std::uint64_t work_budget)
{
    CommonOptions options = command_line;
    if (const Expected<void> taken = take_script_options(script.options, script_name, options); !taken) {
        err << taken.error().to_string() << '\n';
        return {ExitStatus::bad_input, {}, {}, 0, false};
    }
    const Expected<std::uint64_t> limit = memory_limit(options);
    if (!limit) {
        err << limit.error().to_string() << '\n';
        return {ExitStatus::bad_usage, {}, {}, 0, false};
    }
    FolderFiles files(folder);
    files.log("session started");
    SessionSettings settings = replay_settings(options, *limit, ReplayAudience::headless);
    settings.pictures_seen = false; // nobody sees this replay's screens
    Session session(settings, files);
    ReplayHooks hooks;
    hooks.log = [&files](const std::string& line) { files.log(line); };
    hooks.keeps_recording = false;
    ReplayKept kept;
    const ExitStatus status = replay_headless(session, script, script_name, Transcript{.work_budget = work_budget},
                                              std::move(hooks), kept, err);
    return {status, std::move(kept.goals), std::move(kept.unwritten), kept.work_done,
            kept.work_done > work_budget};
}

ColourChoice session_colour(ColourChoice asked, const char* no_color)
{
    const bool refused = no_color != nullptr && *no_color != '\0';
    return asked == ColourChoice::automatic && refused ? ColourChoice::never : asked;
}

} // namespace apcs
