#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/base/exit_status.h"
#include "apcs/cli/terminal_runner.h"
#include "apcs/formats/key_script.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/session/session.h"

#include <filesystem>
#include <limits>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// --color as the session uses it (SPEC §7.2.1): automatic becomes never when the environment's
// NO_COLOR (`no_color`, null when unset) is set and not empty; always and never stand as given
// (an option on the command line outranks the environment, as no-color.org asks).
ColourChoice session_colour(ColourChoice asked, const char* no_color);

// Whether a locale's codeset, as nl_langinfo(CODESET) names it, is UTF-8 ("UTF-8", "utf8", …).
bool is_utf8_codeset(std::string_view codeset);

// The glyphs of a terminal session when --glyphs is not given (SPEC §7.2): braille when the locale
// is UTF-8 and the terminal can show it, else ascii. `term` is TERM: the Linux console (linux,
// linux-*), the DEC terminals (vt100, vt220, … : "vt" and a digit) and dumb cannot; nor can an
// unnamed terminal.
GlyphSet default_glyphs(std::string_view codeset, std::string_view term);

// The glyphs a terminal session shows: the set asked for with --glyphs, or default_glyphs where
// none was (GlyphSet::automatic). braille and blocks under a locale that is not UTF-8 are refused
// (exit 2): "apcs: --glyphs braille needs a UTF-8 locale (LANG=C.UTF-8 or similar); use --glyphs
// ascii", since curses would show their characters as escapes. `locale_asked`, the locale the
// environment names (LC_ALL, else LC_CTYPE, else LANG), is said when it names a UTF-8 locale the
// machine does not have: the codeset is then not UTF-8 however right the name is.
[[nodiscard]] Expected<GlyphSet> terminal_glyphs(GlyphSet asked, std::string_view codeset, std::string_view term,
                                                 std::string_view locale_asked = {});

// terminal_glyphs for this process's locale and TERM.
[[nodiscard]] Expected<GlyphSet> terminal_glyphs_here(GlyphSet asked);

// What the session takes from the command line: samples, in-betweens, spacing, step; the staff
// values that seed path files of three columns (default 0); the answers an empty line takes
// (--theta, --phi, --delay, --slopes) only where given; and where the overlay PNG goes (--png; a
// relative name is taken from the current folder, also with --workdir).
SessionSettings session_settings(const CommonOptions& options);

// Runs the session headless through `replay` (ReplayAudience::headless, of `session`): every key of
// the script, the animation untimed, and each step's final screen (after its last key) to `out`:
// a line "--- STEP", then the 80x24 screen, trailing blanks removed. The replay's hooks hear of
// each caption as it is reached (the headless command prints ";; TEXT" there). Returns how many
// screens it drew: one a step and a few more, however many keys each step took.
std::size_t run_headless_session(ReplayDriver& replay, const Session& session, GlyphSet glyphs, std::ostream& out);

// What a headless replay left: the exit status `apcs --keys` ends with, and the outcome of each
// goal of the script (every goal: headless, the replay's finish() judges those left).
struct HeadlessReplay {
    ExitStatus status = ExitStatus::success;
    std::vector<GoalOutcome> goals;
    // The first file the session could not write (a full disk), if one.
    std::optional<Diagnostic> unwritten;
    // The operations its keys cost (ReplayDriver::work_done), and whether they went past the
    // budget: then the replay stopped there and judged no goal.
    std::uint64_t work_done = 0;
    bool over_budget = false;
};

// `script` (named `script_name` in messages) replayed headless in `folder` with `options`, as
// `apcs --keys SCRIPT --workdir FOLDER </dev/null` replays it: the same keys into the same
// session, the same files and apcs.log there; but no screen is drawn (nobody sees one, and
// drawing them is most of a replay's time). The script's OPTIONS line gives what `options` does
// not (script_options.h). Its problems go to `err`. The script's INPUT lines are not checked
// here: the caller did, or made the folder from them (apcs grade).
// Its keys may cost `work_budget` operations (ReplayDriver::work_done); past it the replay stops
// (HeadlessReplay::over_budget).
HeadlessReplay replay_in_folder(const KeyScript& script, const std::string& script_name, const CommonOptions& options,
                                const std::filesystem::path& folder, std::ostream& err,
                                std::uint64_t work_budget = std::numeric_limits<std::uint64_t>::max());

// `apcs` with no command: the interactive session in --workdir (default: the current folder).
// With a terminal the session runs there (--keys typed first) in the glyphs of terminal_glyphs,
// for the process's locale and TERM (a set the locale cannot show: exit 2); without one it needs
// --keys and runs headless (ascii unless --glyphs says otherwise); otherwise exit 3.
ExitStatus run_session_command(const CommonOptions& options, const TerminalRunner& terminal, std::ostream& out,
                               std::ostream& err);

} // namespace apcs
