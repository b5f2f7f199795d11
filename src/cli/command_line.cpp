#include "apcs/cli/command_line.h"

#include "apcs/session/exit_status.h"
#include "apcs/cli/figures_command.h"
#include "apcs/cli/fit_command.h"
#include "apcs/cli/inbetween_command.h"
#include "apcs/cli/options.h"
#include "apcs/cli/path_command.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/version.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string>

namespace apcs {

namespace {

const CLI::Validator finite_number(
    [](std::string& text) -> std::string {
        try {
            std::size_t used = 0;
            const double value = std::stod(text, &used);
            if (used == text.size() && std::isfinite(value))
                return {};
        } catch (const std::exception&) {
        }
        return "expected a finite number, found '" + text + "'";
    },
    "NUMBER");

// A picture's name ends in .png (any case) or has no extension: PNG bytes in x.svg would mislead.
const CLI::Validator png_name(
    [](std::string& text) -> std::string {
        const std::string extension = std::filesystem::path(text).extension().string();
        if (extension.empty() || equals_ignoring_case(extension, ".png"))
            return {};
        return "a PNG file's name ends in .png, found '" + text + "'";
    },
    "FILE.png");

// CLI11's check of a range of apcs::limits, for options that take any number. (CLI11 names the
// range's type in --help and writes its bounds the type's way: whole_range keeps "INT in [1 - 100]".)
CLI::Range real_range(const limits::Range& range) { return CLI::Range(range.min, range.max); }

// The same for options that take whole numbers.
CLI::Range whole_range(const limits::Range& range)
{
    return CLI::Range(static_cast<int>(range.min), static_cast<int>(range.max));
}

void add_staff_options(CLI::App& command, CommonOptions& options)
{
    const CLI::Range staff_range = real_range(limits::staff_value);
    const std::string range = " in " + range_text(limits::staff_value) + " (default 0)";
    command.add_option("--tension", options.staff.tension, "tension t" + range)->check(finite_number & staff_range);
    command.add_option("--continuity", options.staff.continuity, "continuity c" + range)
        ->check(finite_number & staff_range);
    command.add_option("--bias", options.staff.bias, "bias b" + range)->check(finite_number & staff_range);
    command.add_option("--accel", options.staff.acceleration, "acceleration a" + range)
        ->check(finite_number & staff_range);
}

void add_path_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes)
{
    command
        .add_option("--slopes", slopes, "end slopes S0 S1, each in " + range_text(limits::end_slope) + " (default 1 1)")
        ->expected(2)
        ->check(finite_number & real_range(limits::end_slope));
    command.add_option("--samples", options.path.samples_per_segment, "curve samples per segment (default 32)")
        ->check(whole_range(limits::samples_per_segment));
    command.add_option("--inbetweens", options.path.inbetween_count, "in-between frames M (default 12)")
        ->check(whole_range(limits::inbetween_count));
    command
        .add_option_function<std::string>(
            "--spacing",
            [&options](const std::string& name) {
                options.path.spacing = name == "exact" ? Spacing::exact : Spacing::nearest;
            },
            "nearest (the thesis) or exact (arc length); default nearest")
        ->check(CLI::IsMember({"nearest", "exact"}));
}

void add_screen_options(CLI::App& command, CommonOptions& options)
{
    command.add_option("--theta", options.view.theta_degrees, "viewer direction theta in degrees (default 30)")
        ->check(finite_number & real_range(limits::view_degrees));
    CLI::Option* phi = command.add_option("--phi", options.view.phi_degrees, "viewer direction phi in degrees (default 40)")
        ->check(finite_number & real_range(limits::view_degrees));
    std::vector<std::string> preset_names;
    std::string preset_help = "a view along the axes instead of --theta/--phi";
    for (const ViewPreset& preset : view_presets) {
        preset_names.emplace_back(preset.name);
        preset_help += std::string(preset_names.size() == 1 ? ": " : "; ") + preset.name + " " + preset.shows;
    }
    command
        .add_option_function<std::string>(
            "--view",
            [&options](const std::string& name) {
                for (const ViewPreset& preset : view_presets)
                    if (name == preset.name)
                        options.view = preset.angles;
            },
            preset_help)
        ->check(CLI::IsMember(preset_names))
        ->excludes(phi)
        ->excludes(command.get_option("--theta"));
    command.add_option("--delay", options.delay_ms, "milliseconds per animation frame (default 200)")
        ->check(whole_range(limits::delay_ms));
    command
        .add_option_function<std::string>(
            "--glyphs",
            [&options](const std::string& name) {
                options.glyphs = name == "ascii" ? GlyphSet::ascii : name == "braille" ? GlyphSet::braille : GlyphSet::blocks;
            },
            "ascii, braille or blocks (default: braille in a UTF-8 locale on a terminal that shows it, else ascii)")
        ->check(CLI::IsMember({"ascii", "braille", "blocks"}));
    command.add_option("--step", options.step, "staff step per key (default 0.05)")
        ->check(finite_number & real_range(limits::staff_step));
    command.add_option("--png", options.png, "write the screen as a PNG as the monitor showed it (720x522)")
        ->check(png_name);
    command.add_option("--png-raw", options.png_raw, "write the bare 720x348 raster as a PNG (pixel aspect 3:2)")
        ->check(png_name);
}

void add_common_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes)
{
    add_staff_options(command, options);
    add_path_options(command, options, slopes);
    add_screen_options(command, options);
    command.add_option("--workdir", options.workdir, "folder the session works in (default: current)");
    command.add_option("--keys", options.keys, "replay keystrokes from FILE");
    command.add_option("--record", options.record, "record keystrokes to FILE");
    command.add_flag("--print", options.print, "write numbers to standard output");
    command.add_option("--out", options.out, "output folder");
}

// How often the option `name` was given, to the command or before it.
std::size_t given_count(const CLI::App& app, const std::string& name)
{
    std::size_t count = app.count(name);
    for (const CLI::App* command : app.get_subcommands())
        count += command->count(name);
    return count;
}

ExitStatus not_built(const std::string& command, std::ostream& err)
{
    err << "apcs: '" << command << "' is not built yet in this version\n";
    return ExitStatus::bad_usage;
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

int parse_and_run(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                  const TerminalSessionRunner& terminal)
{
    CLI::App app{"APCS - the Animation Path Control System of 1989: Kochanek-Bartels motion paths", "apcs"};
    app.set_version_flag("--version", std::string("apcs ") + std::string(version));
    app.require_subcommand(0, 1);

    CommonOptions options;
    std::vector<double> slopes;
    add_common_options(app, options, slopes);

    std::filesystem::path path_file;
    CLI::App* path = app.add_subcommand("path", "one point's path: print it or draw it (SPEC 4)");
    path->add_option("FILE", path_file, "path file (.dat)")->required();
    add_common_options(*path, options, slopes);

    std::vector<std::filesystem::path> key_files;
    InbetweenSettings inbetween_settings;
    CLI::App* inbetween = app.add_subcommand("inbetween", "in-betweens by interpolation law and padding (SPEC 6)");
    inbetween->add_option("KEYS", key_files, "KEY1 KEY2")->expected(2)->required();
    inbetween->add_option("--frames", inbetween_settings.frame_intervals, "T: frames 0 ... T (default: --inbetweens + 1)")
        ->check(whole_range(limits::frame_intervals));
    inbetween
        ->add_option_function<std::string>(
            "--law", [&](const std::string& name) { inbetween_settings.law = *speed_law_from_name(name); },
            "linear, sqrt, square, ease-in, ease-out or ease-in-out (default linear)")
        ->check(CLI::IsMember({"linear", "sqrt", "square", "ease-in", "ease-out", "ease-in-out"}));
    inbetween
        ->add_option_function<std::string>(
            "--pad", [&](const std::string& name) { inbetween_settings.padding = *padding_from_name(name); },
            "apcs, start, end, middle or midpoint (default apcs)")
        ->check(CLI::IsMember({"apcs", "start", "end", "middle", "midpoint"}));
    add_common_options(*inbetween, options, slopes);

    std::vector<std::filesystem::path> fit_files;
    CLI::App* fit = app.add_subcommand("fit", "surface fitting: all in-between frames");
    fit->add_option("FILES", fit_files, "KEY1 KEY2 PATH_FIRST PATH_LAST")->expected(4)->required();
    add_common_options(*fit, options, slopes);

    CLI::App* figures = app.add_subcommand("figures", "redraw the thesis' figures as PNG");
    add_common_options(*figures, options, slopes);

    std::filesystem::path scene;
    CLI::App* play = app.add_subcommand("play", "scenes of several objects and actors");
    play->add_option("SCENE", scene, "scene file")->required();
    add_common_options(*play, options, slopes);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0)
            return app.exit(error, out, err);
        err << "apcs: " << error.what() << "\n\n" << app.help();
        return to_int(ExitStatus::bad_usage);
    }
    if (slopes.size() == 2)
        options.path.slopes = {slopes[0], slopes[1]};
    const bool view_given = given_count(app, "--view") > 0;
    options.given = {view_given || given_count(app, "--theta") > 0, view_given || given_count(app, "--phi") > 0,
                     given_count(app, "--delay") > 0, slopes.size() == 2};

    if (path->parsed())
        return to_int(run_path_command(path_file, options, out, err));
    if (inbetween->parsed()) {
        inbetween_settings.key1 = key_files[0];
        inbetween_settings.key2 = key_files[1];
        return to_int(run_inbetween_command(inbetween_settings, options, out, err));
    }
    if (fit->parsed())
        return to_int(run_fit_command({fit_files[0], fit_files[1], fit_files[2], fit_files[3]}, options, out, err));
    if (figures->parsed())
        return to_int(run_figures_command(options, APCS_DATA_DIR, out, err));
    if (play->parsed())
        return to_int(not_built("play", err));
    return to_int(run_session_command(options, terminal, out, err));
}

} // namespace

int run_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                     const TerminalSessionRunner& terminal)
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
