#include "apcs/cli/session_command.h"

#include "apcs/cli/report.h"
#include "apcs/formats/file_io.h"

#include <ostream>
#include <unistd.h>

namespace apcs {

namespace {

std::string screen_text(const Session& session, GlyphSet glyphs)
{
    const SessionScreen screen = session.screen();
    const CellGrid grid = screen.graphics ? render_cells(screen.picture, {80, 25}, glyphs) : screen.text;
    std::string text;
    for (int row = 0; row < grid.rows(); ++row) {
        std::string line = grid.row_text(row);
        line.erase(line.find_last_not_of(' ') + 1);
        text += line + '\n';
    }
    return text;
}

void print_step(const Session& session, GlyphSet glyphs, std::ostream& out)
{
    out << "--- " << phase_name(session.phase()) << '\n' << screen_text(session, glyphs);
}

} // namespace

std::vector<KeyEvent> run_headless_session(Session& session, const std::vector<KeyEvent>& keys, GlyphSet glyphs,
                                           std::ostream& out)
{
    std::vector<KeyEvent> handled;
    print_step(session, glyphs, out);
    for (const KeyEvent& key : keys) {
        if (session.finished())
            break;
        const SessionPhase before = session.phase();
        handled.push_back(key);
        session.handle(key);
        if (session.phase() == SessionPhase::animating && session.phase() != before)
            print_step(session, glyphs, out);
        while (session.animating())
            session.tick();
        if (session.phase() != before)
            print_step(session, glyphs, out);
    }
    return handled;
}

ExitStatus run_session_command(const CommonOptions& options, const TerminalSessionRunner& terminal, std::ostream& out,
                               std::ostream& err)
{
    const std::filesystem::path folder = options.workdir.empty() ? std::filesystem::path(".") : options.workdir;
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) {
        err << folder.string() << ": is not a folder; expected the folder to work in (--workdir)\n";
        return ExitStatus::bad_input;
    }
    std::vector<KeyEvent> scripted;
    if (options.keys) {
        const Expected<std::string> text = read_text_file(*options.keys);
        if (!text)
            return report_bad_input(text.error(), err);
        Expected<std::vector<KeyEvent>> script = parse_key_script(*text, options.keys->string());
        if (!script)
            return report_bad_input(script.error(), err);
        scripted = std::move(*script);
    }
    const bool headless = !::isatty(STDIN_FILENO) || !terminal;
    if (headless && !options.keys) {
        err << "apcs: standard input is not a terminal; give --keys FILE to replay a session without one\n";
        return ExitStatus::terminal_problem;
    }
    FolderFiles files(folder);
    files.log("session started");
    SessionSettings settings;
    settings.samples_per_segment = options.path.samples_per_segment;
    settings.inbetween_count = options.path.inbetween_count;
    settings.spacing = options.path.spacing;
    settings.step = options.step;
    Session session(settings, files);
    std::vector<KeyEvent> recorded;
    ExitStatus status = ExitStatus::success;
    if (headless) {
        const GlyphSet glyphs = options.glyphs == GlyphSet::automatic ? GlyphSet::ascii : options.glyphs;
        recorded = run_headless_session(session, scripted, glyphs, out);
        if (!session.finished())
            err << "apcs: the key script ended at " << phase_name(session.phase()) << '\n';
    } else {
        Diagnostic problem;
        status = terminal(session, scripted, options.glyphs, recorded, problem);
        if (status == ExitStatus::terminal_problem) {
            err << problem.to_string() << '\n';
            return ExitStatus::terminal_problem;
        }
        if (status == ExitStatus::stopped)
            err << "apcs: stopped; every file written so far is whole\n";
        else
            for (const std::string& name : session.written_files())
                out << name << '\n';
    }
    if (options.record) {
        const Expected<WriteResult> written = write_file_atomically(*options.record, format_key_script(recorded));
        if (!written)
            return report_bad_input(written.error(), err);
    }
    return status;
}

} // namespace apcs
