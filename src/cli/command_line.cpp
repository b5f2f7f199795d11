#include "apcs/cli/command_line.h"

#include "apcs/base/exit_status.h"
#include "apcs/base/utf8.h"
#include "draw_command.h"
#include "figures_command.h"
#include "fit_command.h"
#include "apcs/cli/grade_command.h"
#include "inbetween_command.h"
#include "apcs/cli/options.h"
#include "apcs/cli/path_command.h"
#include "apcs/formats/sif_path.h"
#include "apcs/cli/play_command.h"
#include "report.h"
#include "apcs/cli/script_options.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/version.h"
#include "option_sets.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <streambuf>
#include <string>
#include <string_view>
#include <utility>

namespace apcs {

namespace {

// How often the option `name` was given, to the command or before it.
std::size_t given_count(const CLI::App& app, const std::string& name)
{
    const auto count_in = [&name](const CLI::App& command) {
        const CLI::Option* option = command.get_option_no_throw(name);
        return option == nullptr ? std::size_t{0} : option->count();
    };
    std::size_t count = count_in(app);
    for (const CLI::App* command : app.get_subcommands())
        count += count_in(*command);
    return count;
}

} // namespace

namespace {

// Passes everything to `target` and remembers the errno of the first write or flush that failed.
class FailureRecordingBuffer : public std::streambuf {
public:
    explicit FailureRecordingBuffer(std::streambuf* target) : m_target(target) {}
    int first_error() const { return m_error; }

protected:
    int_type overflow(int_type c) override
    {
        if (traits_type::eq_int_type(c, traits_type::eof()))
            return traits_type::not_eof(c);
        errno = 0;
        const int_type result = m_target ? m_target->sputc(traits_type::to_char_type(c)) : traits_type::eof();
        if (traits_type::eq_int_type(result, traits_type::eof()))
            note_failure();
        return result;
    }
    std::streamsize xsputn(const char* text, std::streamsize count) override
    {
        errno = 0;
        const std::streamsize written = m_target ? m_target->sputn(text, count) : 0;
        if (written != count)
            note_failure();
        return written;
    }
    int sync() override
    {
        errno = 0;
        const int result = m_target ? m_target->pubsync() : -1;
        if (result != 0)
            note_failure();
        return result;
    }

private:
    void note_failure()
    {
        if (m_error == 0)
            m_error = errno != 0 ? errno : EIO;
    }

    std::streambuf* m_target;
    int m_error = 0;
};

// Gives `stream` another buffer while it lives, and its own back at the end.
class ReplacedBuffer {
public:
    ReplacedBuffer(std::ostream& stream, std::streambuf* buffer) : m_stream(stream), m_old(stream.rdbuf(buffer)) {}
    ~ReplacedBuffer() { m_stream.rdbuf(m_old); }
    ReplacedBuffer(const ReplacedBuffer&) = delete;
    ReplacedBuffer& operator=(const ReplacedBuffer&) = delete;

private:
    std::ostream& m_stream;
    std::streambuf* m_old;
};

// What GNU tools print for --version: the program, its version, and what it is.
std::string version_text()
{
    return "apcs (APCS) " + std::string(version) +
           "\nThe Animation Path Control System of the 1989 master's thesis \"Design of An Animation Path\n"
           "Control System\" (National Chung Hsing University, Taiwan), re-created: Kochanek-Bartels\n"
           "motion paths between two key frames, the four-line staff and surface fitting.";
}

std::string command_name(const CLI::App* command)
{
    return command->get_parent() == nullptr ? "apcs" : "apcs " + command->get_name();
}

// The commands of `app` (the session included) that take the option `name`.
std::string commands_taking(const CLI::App& app, const std::string& name)
{
    std::string names;
    const auto note = [&](const CLI::App* command) {
        if (command->get_option_no_throw(name) != nullptr)
            names += (names.empty() ? "'" : ", '") + command_name(command) + "'";
    };
    note(&app);
    for (const CLI::App* command : app.get_subcommands({}))
        note(command);
    return names;
}

// The first "--NAME" on the command line that the place it stands in does not take, with the line
// that says so. CLI11 reports such an option late and by its effect (its value counted as one file
// too many, or "arguments were not expected"): name it instead.
std::optional<std::string> foreign_option(const CLI::App& app, std::span<const char* const> arguments)
{
    const CLI::App* command = nullptr;
    for (const char* argument : arguments)
        for (const CLI::App* candidate : app.get_subcommands({}))
            if (command == nullptr && candidate->get_name() == argument)
                command = candidate;
    bool after_command = false;
    for (const char* argument : arguments) {
        const std::string token(argument);
        if (token == "--")
            break;
        if (command != nullptr && token == command->get_name()) {
            after_command = true;
            continue;
        }
        const std::string name = token.substr(0, token.find('='));
        if (!name.starts_with("--") || name == "--help")
            continue;
        const CLI::App& place = after_command ? *command : app;
        if (place.get_option_no_throw(name) != nullptr)
            continue;
        if (!after_command && command != nullptr && command->get_option_no_throw(name) != nullptr)
            return name + " goes after the command: " + command_name(command) + " ... " + name;
        const CLI::App& shown = command != nullptr ? *command : app;
        const std::string owners = commands_taking(app, name);
        if (owners.empty())
            return "unknown option " + name;
        return name + " is not an option of '" + command_name(&shown) + "' (it is one of " + owners + ")";
    }
    return std::nullopt;
}

// CLI11 says "--slopes: At least 2 required but received 1" of an option given too few or too
// many values: say what it takes instead.
std::optional<std::string> wrong_value_count(const CLI::App& command, const CLI::ParseError& error)
{
    const std::string what = error.what();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) == nullptr || !what.starts_with("-"))
        return std::nullopt;
    const CLI::Option* option = command.get_option_no_throw(what.substr(0, what.find(':')));
    if (option == nullptr)
        return std::nullopt;
    const int values = option->get_expected_max();
    return option->get_name() + " takes " + std::to_string(values) + (values == 1 ? " value (" : " values (") +
           option->get_type_name() + "); " + std::to_string(option->results().size()) + " given";
}

// CLI11 says "Could not convert: --paper = banana" of a flag given a value: say it takes none.
std::optional<std::string> flag_given_a_value(const CLI::App& command, const CLI::ParseError& error)
{
    constexpr std::string_view prefix = "Could not convert: ";
    const std::string what = error.what();
    const std::size_t equals = what.find(" = ");
    if (dynamic_cast<const CLI::ConversionError*>(&error) == nullptr || !what.starts_with(prefix) ||
        equals == std::string::npos)
        return std::nullopt;
    const std::string name = what.substr(prefix.size(), equals - prefix.size());
    const CLI::Option* option = command.get_option_no_throw(name);
    if (option == nullptr || option->get_expected_max() != 0) // a flag expects no value
        return std::nullopt;
    return option->get_name() + " is a flag and takes no value ('" + what.substr(equals + 3) + "' given); write " +
           option->get_name() + " alone";
}

// CLI11 says "FILES: At least 4 required but received 2": say what the command takes instead.
std::optional<std::string> wrong_operand_count(const CLI::App& command, const CLI::ParseError& error,
                                               const char* operands)
{
    const bool too_few = dynamic_cast<const CLI::RequiredError*>(&error) != nullptr ||
                         dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr;
    const bool too_many = dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr;
    if (!too_few && !too_many)
        return std::nullopt;
    // A required option missing (export's --sif) is CLI11's own line, not a count of files.
    for (const CLI::Option* option : command.get_options())
        if (option->get_required() && !option->get_positional() && option->count() == 0)
            return std::nullopt;
    std::size_t given = command.remaining_size();
    for (const CLI::Option* option : command.get_options())
        if (option->get_positional())
            given += option->results().size();
    return command.get_name() + " takes " + operands + "; " + std::to_string(given) + " given";
}

// The one line a usage error prints: an option of another command is named as such.
std::string usage_error_text(const CLI::App& app, const CLI::App& command, std::span<const char* const> arguments,
                             const CLI::ParseError& error, const char* operands)
{
    if (auto line = foreign_option(app, arguments))
        return *std::move(line);
    if (auto line = wrong_value_count(command, error))
        return *std::move(line);
    if (auto line = flag_given_a_value(command, error))
        return *std::move(line);
    if (operands != nullptr) {
        if (auto line = wrong_operand_count(command, error, operands))
            return *std::move(line);
    }
    if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr && command.get_parent() == nullptr &&
        !command.remaining().empty() && !command.remaining().front().starts_with("-"))
    {
        std::string names;
        for (const CLI::App* known : app.get_subcommands({}))
            names += (names.empty() ? "" : ", ") + known->get_name();
        return "unknown command '" + command.remaining().front() + "' (the commands: " + names + ")";
    }
    return error.what();
}

// An option given before the command belongs to the session unless the command takes it too; given
// both before and after it, the first would be lost.
std::optional<std::string> session_option_before_command(const CLI::App& app, const CLI::App& command)
{
    for (const CLI::Option* option : app.get_options()) {
        const std::string name = option->get_name();
        if (option->count() == 0 || name == "--help")
            continue;
        const CLI::Option* own = command.get_option_no_throw(name);
        if (own == nullptr)
            return name + " is not an option of '" + command_name(&command) + "' (it is one of " +
                   commands_taking(app, name) + ")";
        if (own->count() > 0)
            return name + " is given twice, before and after '" + command.get_name() + "'";
    }
    return std::nullopt;
}

// A picture is never written over an input of the run (check_pictures_spare_inputs), and two
// pictures never go to one file, where one would be lost silently (a usage error).
Expected<void> check_picture_targets(const CommonOptions& options, std::span<const std::filesystem::path> inputs,
                                     bool& usage)
{
    if (Expected<void> spared = check_pictures_spare_inputs(options, inputs); !spared)
        return spared;
    const std::filesystem::path dash(standard_stream_name);
    KeyFileGuard pictures;
    for (const auto& [option, target] : picture_targets(options)) {
        if (!*target || **target == dash)
            continue;
        if (pictures.guards(**target)) {
            usage = true;
            return Diagnostic{"apcs", 0, std::string(option) + " names a file another picture option names: " +
                                             (*target)->string()};
        }
        pictures.protect(**target);
    }
    return ok;
}

// "-" is standard input where a file is read and standard output where one is written: each holds
// one stream, and the session's standard output is its screen.
std::optional<std::string> standard_stream_clash(const CommonOptions& options,
                                                 std::span<const std::filesystem::path> inputs, bool session)
{
    const std::filesystem::path dash(standard_stream_name);
    if (std::count(inputs.begin(), inputs.end(), dash) > 1)
        return "standard input (-) can be read only once";
    int writers = options.print ? 1 : 0;
    for (const auto& [option, target] : picture_targets(options))
        writers += *target == dash ? 1 : 0;
    if (session && writers > 0)
        return "the session's standard output is its screen: name a file for --png, --png-raw and --svg";
    if (writers > 1)
        return "only one of --print, --png -, --png-raw -, --svg -, --gif -, --sixel - and --kitty - can write to "
               "standard output";
    return std::nullopt;
}

int usage_error(const std::string& line, const CLI::App* command, std::ostream& err)
{
    err << "apcs: " << escape_controls(line) << "\nTry '" << command_name(command) << " --help' for more information.\n";
    return to_int(ExitStatus::bad_usage);
}

// Everything the command line sets as CLI11 parses it: the options, and each command's arguments.
struct ParsedLine {
    CommonOptions options;
    std::vector<double> slopes;
    std::filesystem::path path_file;
    std::vector<std::filesystem::path> key_files;
    InbetweenSettings inbetween;
    std::vector<std::filesystem::path> fit_files;
    std::vector<std::filesystem::path> draw_files;
    PlayRequest play;
    GradeRequest grade;
    GradeClassRequest grade_class;
    ExportRequest export_request;
    std::string sif_param = "origin"; // apcs path FILE.sif --sif-param

    // The files the run reads: only the chosen command's are given, the others stay empty.
    std::vector<std::filesystem::path> inputs() const
    {
        std::vector<std::filesystem::path> files = key_files;
        files.insert(files.end(), fit_files.begin(), fit_files.end());
        files.insert(files.end(), draw_files.begin(), draw_files.end());
        files.insert(files.end(), export_request.files.begin(), export_request.files.end());
        files.push_back(path_file);
        files.push_back(play.scene);
        return files;
    }
};

// What a command runs with besides the parsed line.
struct RunPlace {
    const CLI::App& app;
    const CLI::App& command;
    const TerminalRunner& terminal;
    std::ostream& out;
    std::ostream& err;
};

// One row per command: its name and summary (in `apcs --help`, in this order), its arguments and
// options, and how it runs. Without a command, apcs runs the session (run_session_command).
struct Subcommand {
    const char* name;
    const char* summary;
    const char* operands; // what it takes besides options, for "fit takes four files …; 2 given"
    const char* examples; // command lines for --help, each runnable where `place` says
    const char* place;    // "a copy of data/n-to-l"
    void (*set_up)(CLI::App& command, ParsedLine& line);
    int (*run)(ParsedLine& line, const RunPlace& place);
};

// Where most commands' --help examples run: the files they name are that example's.
constexpr const char* n_to_l_copy = "a copy of data/n-to-l";

constexpr std::array<Subcommand, 8> subcommands{{
    {"path", "one point's path: print its numbers or draw it", "one path file FILE.dat (or FILE.sif)",
     "  apcs path way1.dat --print --samples 4 --inbetweens 3\n"
     "  apcs path way1.dat --tension 0.5 --accel 0.3 --png way1.png\n"
     "  apcs path way1.dat --sixel -         (the picture in xterm -ti vt340, not through tmux)",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("FILE", line.path_file, "the path file (.dat), or a Synfig document (.sif)")
             ->required()
             ->type_name("");
         add_path_command_options(command, line.options, line.slopes);
         command
             .add_option("--sif-param", line.sif_param,
                         "FILE.sif: the animated vector read as the path, default origin (the first layer's that is "
                         "animated)")
             ->type_name("NAME");
     },
     [](ParsedLine& line, const RunPlace& place) {
         if (place.command.count("--sif-param") > 0 && !is_sif_name(line.path_file.string()))
             return usage_error("--sif-param names what to read of a Synfig document (FILE.sif); " +
                                    line.path_file.string() + " is read as a .dat file",
                                &place.command, place.err);
         return to_int(run_path_command(line.path_file, line.options, line.sif_param, place.out, place.err));
     }},
    {"inbetween", "in-between frames by an interpolation law and a padding", "two key files KEY1 KEY2",
     "  apcs inbetween key1.dat key2.dat --law ease-in --print\n"
     "  apcs inbetween key1.dat key2.dat --inbetweens 6 --out linear",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("KEYS", line.key_files, "KEY1 KEY2: the key frames (.dat)")
             ->expected(2)
             ->required()
             ->type_name("");
         add_inbetween_command_options(command, line.options, line.inbetween);
     },
     [](ParsedLine& line, const RunPlace& place) {
         line.inbetween.key1 = line.key_files[0];
         line.inbetween.key2 = line.key_files[1];
         return to_int(run_inbetween_command(line.inbetween, line.options, place.out, place.err));
     }},
    {"fit", "surface fitting: the in-between frames of two key frames", "four files KEY1 KEY2 PATH_FIRST PATH_LAST",
     "  apcs fit key1.dat key2.dat way1.dat way4.dat --out frames\n"
     "  apcs fit key1.dat key2.dat way1.dat way4.dat --surface ferguson --png fit.png",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("FILES", line.fit_files, "KEY1 KEY2 PATH_FIRST PATH_LAST (.dat)")
             ->expected(4)
             ->required()
             ->type_name("");
         add_fit_command_options(command, line.options, line.slopes);
     },
     [](ParsedLine& line, const RunPlace& place) {
         const std::vector<std::filesystem::path>& files = line.fit_files;
         return to_int(run_fit_command({files[0], files[1], files[2], files[3]}, line.options, place.out, place.err));
     }},
    {"export", "a path or a whole animation as a Synfig document (.sif), its TCB waypoints or APCS's frames",
     "one path file FILE.dat, or four files KEY1 KEY2 PATH_FIRST PATH_LAST",
     "  apcs export way1.dat --sif way1.sif\n"
     "  apcs export way1.dat --sif way1-frames.sif --sif-motion frames\n"
     "  apcs export key1.dat key2.dat way1.dat way4.dat --sif n-to-l.sif",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("FILES", line.export_request.files, "FILE.dat, or KEY1 KEY2 PATH_FIRST PATH_LAST (.dat)")
             ->required()
             ->type_name("");
         add_export_command_options(command, line.options, line.slopes, line.export_request);
     },
     [](ParsedLine& line, const RunPlace& place) {
         const std::size_t count = line.export_request.files.size();
         if (count != 1 && count != 4)
             return usage_error("apcs export takes one path file, or four files KEY1 KEY2 PATH_FIRST PATH_LAST; " +
                                    std::to_string(count) + " given",
                                &place.command, place.err);
         for (const char* one_path_only : {"--sif-motion", "--frames-per-span"})
             if (count == 4 && place.command.count(one_path_only) > 0)
                 return usage_error(std::string(one_path_only) +
                                        " shapes one path's document; an animation's moves one waypoint a frame",
                                    &place.command, place.err);
         return to_int(run_export_command(line.export_request, line.options, place.out, place.err));
     }},
    {"draw", "draw key frames and in-between files overlaid as a picture", "one or more .dat files",
     "  apcs draw key1.dat key2.dat --png keys.png",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command
             .add_option("FILES", line.draw_files,
                         "the graphics (.dat): the first solid, the last dashed, the others dotted")
             ->required()
             ->type_name("");
         add_draw_command_options(command, line.options);
     },
     [](ParsedLine& line, const RunPlace& place) {
         if (!pictures_asked(line.options))
             return usage_error("apcs draw writes a picture: give --png, --png-raw, --svg, --sixel or --kitty",
                                &place.command, place.err);
         return to_int(run_draw_command(line.draw_files, line.options, place.out, place.err));
     }},
    {"play", "play a scene of several objects and actors (.scn)", "one scene file SCENE.scn",
     "  apcs play ../robot/robot.scn --tree\n"
     "  apcs play ../car/car.scn --gif car.gif",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("SCENE", line.play.scene, "the scene file (.scn)")->required()->type_name("");
         add_play_command_options(command, line.options, line.slopes, line.play.tree);
     },
     [](ParsedLine& line, const RunPlace& place) {
         return to_int(run_play_command(line.play, line.options, place.terminal, place.out, place.err));
     }},
    {"figures", "redraw the thesis' figures and examples as PNG", "no files (--out names the folder)",
     "  apcs figures --out figures",
     n_to_l_copy,
     [](CLI::App& command, ParsedLine& line) { add_figures_command_options(command, line.options, line.slopes); },
     [](ParsedLine& line, const RunPlace& place) {
         return to_int(run_figures_command(line.options, place.out, place.err));
     }},
    {"grade", "grade homework: replay each recording of an exercise, one CSV row per goal; or a class's "
              "folders, one row per student",
     "an exercise EXERCISE.keys and one or more recordings RECORDING...; with --class DIR, one or more exercises",
     "  apcs grade data/exercises/exercise-1-tension.keys data/exercises/answers/exercise-1-tension-answer.keys\n"
     "  apcs grade --class CLASS --feedback RETURNED data/exercises/exercise-*.keys   (CLASS/STUDENT/EXERCISE.keys)",
     "the source tree (data/exercises: the exercises, their inputs and answers/)",
     [](CLI::App& command, ParsedLine& line) {
         command.add_option("EXERCISE", line.grade.exercise, "the exercise (.keys), its INPUT files beside it")
             ->required()
             ->type_name("");
         command.add_option("RECORDINGS", line.grade.recordings,
                            "what --record kept of each student's keys (.keys); with --class, more exercises")
             ->type_name("");
         CLI::Option* in_class =
             command.add_option("--class", line.grade_class.class_folder,
                                "a gradebook: DIR holds a folder per student, each recording named as its exercise")
                 ->type_name("DIR");
         command.add_option("--feedback", line.grade_class.feedback,
                            "with --class: write DIR2/STUDENT.txt, each goal reached or not, the value, what was wanted")
             ->type_name("DIR2")
             ->needs(in_class);
     },
     [](ParsedLine& line, const RunPlace& place) {
         if (!line.grade_class.class_folder.empty()) {
             line.grade_class.exercises = {line.grade.exercise};
             line.grade_class.exercises.insert(line.grade_class.exercises.end(), line.grade.recordings.begin(),
                                               line.grade.recordings.end());
             return to_int(run_grade_class_command(line.grade_class, line.options, place.out, place.err));
         }
         if (line.grade.recordings.empty()) {
             place.err << "apcs grade: expected one or more recordings after the exercise (or --class DIR)\n";
             return to_int(ExitStatus::bad_usage);
         }
         return to_int(run_grade_command(line.grade, line.options, place.out, place.err));
     }},
}};

// The session's options on `app`, then one subcommand per row of the table.
void set_up_command_line(CLI::App& app, ParsedLine& line)
{
    app.set_version_flag("--version", version_text());
    app.require_subcommand(0, 1);
    app.formatter(std::make_shared<PlainOptionFormatter>());
    const std::string manual = "The user's manual: manual.txt (installed as share/doc/apcs/manual.txt); man apcs.";
    app.footer("Examples, in a copy of the n-to-l example (data/n-to-l; installed: share/apcs/n-to-l):\n"
               "  apcs                                   the session, as in 1989\n"
               "  apcs --keys session.keys --pace 300    the shipped session replayed\n"
               "  apcs --pixels sixel                    real pixels, in xterm -ti vt340 -fn 9x15 (not tmux)\n"
               "  apcs path way1.dat --print             a path's numbers\n\n" +
               manual);
    add_session_options(app, line.options, line.slopes);
    for (const Subcommand& row : subcommands) {
        CLI::App* command = app.add_subcommand(row.name, row.summary);
        command->footer("Examples, in " + std::string(row.place) + ":\n" + row.examples + "\n\n" + manual);
        row.set_up(*command, line);
        command->group("Commands");
    }
}

// nullopt when the line parses; else the exit status of --help, --version or the usage error.
std::optional<int> parse_or_refuse(CLI::App& app, int argc, const char* const* argv, std::ostream& out,
                                   std::ostream& err)
{
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0)
            return app.exit(error, out, err);
        const std::vector<CLI::App*> parsed = app.get_subcommands();
        const CLI::App* command = parsed.empty() ? &app : parsed.back();
        const std::span<const char* const> arguments(argv + 1, static_cast<std::size_t>(argc > 0 ? argc - 1 : 0));
        const auto row = std::ranges::find_if(subcommands, [command](const Subcommand& known) {
            return command->get_name() == known.name;
        });
        const char* operands = row == subcommands.end() ? nullptr : row->operands;
        return usage_error(usage_error_text(app, *command, arguments, error, operands), command, err);
    }
    return std::nullopt;
}

// What CLI11 cannot check: an option before the command, the standard streams, the pictures'
// targets. nullopt when all is well; else the exit status, the reason written to `err`.
std::optional<int> refuse_clashes(const CLI::App& app, const CLI::App& chosen, const ParsedLine& line,
                                  std::ostream& err)
{
    for (const CLI::App* command : app.get_subcommands())
        if (const auto misplaced = session_option_before_command(app, *command))
            return usage_error(*misplaced, command, err);
    const std::vector<std::filesystem::path> inputs = line.inputs();
    if (const auto clash = standard_stream_clash(line.options, inputs, &chosen == &app))
        return usage_error(*clash, &chosen, err);
    bool usage = false;
    if (const Expected<void> targets = check_picture_targets(line.options, inputs, usage); !targets) {
        if (usage)
            return usage_error(targets.error().message, &chosen, err);
        return to_int(report_bad_input(targets.error(), err));
    }
    return std::nullopt;
}

// The options that are known only once the whole line is read: the slopes, which were given, and
// the files the run reads.
void complete_options(const CLI::App& app, ParsedLine& line)
{
    if (line.slopes.size() == 2)
        line.options.path.slopes = {line.slopes[0], line.slopes[1]};
    const bool view_given = given_count(app, "--view") > 0;
    line.options.given = {view_given || given_count(app, "--theta") > 0, view_given || given_count(app, "--phi") > 0,
                          given_count(app, "--delay") > 0, line.slopes.size() == 2, given_count(app, "--spacing") > 0,
                          given_carried_options([&app](const std::string& name) { return given_count(app, name) > 0; })};
    line.options.read_files = line.inputs();
}

int parse_and_run(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                  const TerminalRunner& terminal)
{
    CLI::App app{"APCS - the Animation Path Control System of 1989: Kochanek-Bartels motion paths.\n"
                 "Without a command, the interactive session of the thesis (manual.txt, section 4).",
                 "apcs"};
    ParsedLine line;
    set_up_command_line(app, line);
    if (const std::optional<int> refused = parse_or_refuse(app, argc, argv, out, err))
        return *refused;
    const CLI::App* chosen = app.get_subcommands().empty() ? &app : app.get_subcommands().front();
    if (const std::optional<int> refused = refuse_clashes(app, *chosen, line, err))
        return *refused;
    complete_options(app, line);
    for (const Subcommand& row : subcommands)
        if (chosen->get_name() == row.name)
            return row.run(line, {app, *chosen, terminal, out, err});
    return to_int(run_session_command(line.options, terminal, out, err));
}

} // namespace

int run_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                     const TerminalRunner& terminal)
{
    // Output that never arrived (a full disk, /dev/full, a closed pipe with SIGPIPE ignored) is a
    // failure, not a success. Standard output is buffered, so the failure may show only at the
    // last flush, or long before it (then errno is gone): the buffer below keeps the first reason.
    FailureRecordingBuffer recorder(out.rdbuf());
    int status = 0;
    {
        const ReplacedBuffer replaced(out, &recorder);
        status = parse_and_run(argc, argv, out, err, terminal);
        out.flush();
    }
    if (out.fail() || recorder.first_error() != 0) {
        err << "apcs: cannot write to standard output: " << std::strerror(recorder.first_error() != 0 ? recorder.first_error() : EIO) << '\n';
        if (status == to_int(ExitStatus::success))
            status = to_int(ExitStatus::bad_input);
    }
    return status;
}

} // namespace apcs
