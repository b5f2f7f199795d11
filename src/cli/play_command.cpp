#include "apcs/cli/play_command.h"

#include "apcs/animation/memory_budget.h"
#include "frame_output.h"
#include "memory_limit.h"
#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/cli/write_progress.h"
#include "apcs/cli/session_command.h"
#include "apcs/formats/dat_file.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/formats/print_format.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "apcs/scene/scene_joints.h"
#include "apcs/scene/scene_tree.h"
#include "apcs/screens/frames_overlay.h"
#include "apcs/base/step_log.h"
#include "apcs/playback/scene_player.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace apcs {

namespace {

// What the scene holds while it plays: the KEYS frames, the MOVE offsets, a state a frame for each
// object that turns or scales, and all frames when they are drawn or played (not when only printed
// or written, one frame at a time).
std::uint64_t scene_bytes(const Scene& scene, const PathSettings& settings, bool all_frames)
{
    std::uint64_t bytes = 0;
    std::size_t points = 0;
    const auto path = [&settings](const ControlPoints& control, const FrameSpan& frames) {
        const int inbetweens = std::max(0, frames.to - frames.from - 1);
        return memory::path_bytes({control.size(), settings.samples_per_segment, inbetweens, false});
    };
    for (const SceneObject& object : scene.objects) {
        if (const Graphic* drawing = object.first_drawing())
            points += drawing->point_count();
        if (object.keys) {
            const std::size_t frames = static_cast<std::size_t>(object.keys->frames.to - object.keys->frames.from) + 1;
            bytes = memory::saturating_sum(bytes, memory::frames_bytes({frames, object.keys->keys.key1.point_count(), false}));
            bytes = memory::saturating_sum(bytes, path(object.keys->first_path, object.keys->frames));
            bytes = memory::saturating_sum(bytes, path(object.keys->last_path, object.keys->frames));
        }
        if (object.move)
            bytes = memory::saturating_sum(bytes, path(object.move->path, object.move->frames));
        if (object.accumulates())
            bytes = memory::saturating_sum(bytes, (static_cast<std::uint64_t>(scene.last_frame) + 1) * sizeof(ActorState));
    }
    const std::size_t frame_count = static_cast<std::size_t>(scene.last_frame) + 1;
    return memory::saturating_sum(bytes, memory::frames_bytes({all_frames ? frame_count : 1, points, false}));
}

void print_frames(const SceneAnimation& animation, const Scene& scene, std::ostream& out)
{
    std::vector<Vec3> points(animation.points_per_frame());
    std::string text;
    for (int f = 0; f <= animation.last_frame(); ++f) {
        animation.frame(f, points);
        text = "# frame " + std::to_string(f) + "\n";
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const ObjectPoints place = animation.object_points()[i];
            append_print_section(text, "object " + scene.objects[i].name,
                                 std::span<const Vec3>(points).subspan(place.first, place.count));
        }
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
}

// frm000.dat … into `folder`, one frame computed, formatted and written at a time on each core,
// its progress shown on a terminal's standard error.
Expected<void> write_frame_files(const SceneAnimation& animation, const std::filesystem::path& folder,
                                 const KeyFileGuard& guard, std::ostream& err)
{
    WriteProgressLine progress(err, standard_error_is_terminal(), "the frame files");
    const int last = animation.last_frame();
    const auto written = write_numbered_files(
        folder, animation.frame_count(),
        [last](std::size_t f) { return scene_frame_file_name(static_cast<int>(f), last); },
        [&animation, last](std::size_t f) {
            return "; APCS scene frame " + std::to_string(f) + " of " + std::to_string(last) + "\n" +
                   format_graphic(animation.structure(), animation.frame(static_cast<int>(f)));
        },
        guard, "the frame files", progress.report());
    if (!written)
        return written.error();
    // A folder of an earlier play --out keeps the frames this run did not rewrite (more frames, or
    // numbers of another width): they are the user's to delete, and are named so that none is
    // taken for this scene's.
    std::vector<std::string> names;
    for (const std::filesystem::path& path : *written)
        names.push_back(path.filename().string());
    std::vector<std::string> earlier = earlier_numbered_files(folder, "frm", ".dat", names);
    for (std::string& name : earlier)
        name = (folder / name).string();
    if (const std::optional<std::string> note = earlier_inbetweens_note(earlier))
        err << "apcs: " << *note << '\n';
    return ok;
}

// The scene's name in messages, as read_scene_file writes it.
std::string scene_file_name(const std::filesystem::path& scene_file)
{
    return scene_file == "-" ? "standard input" : scene_file.string();
}

// |value| as a message shows it: three significant digits ("1.27e+09") unless they would round it
// to the limit or below it, then as many as show it is over (1000000001 is not "1e+09"); never
// with the locale's decimal comma.
std::string magnitude_beyond(double magnitude, double limit)
{
    std::string text;
    for (int digits = 3; digits <= 17; ++digits) {
        text = significant_number(magnitude, digits);
        double shown = 0;
        std::from_chars(text.data(), text.data() + text.size(), shown);
        if (shown > limit)
            break;
    }
    return text;
}

// A scene whose frames a frame file could not hold (values past 1e9, or not numbers) is refused
// before anything is printed or written, at the line of the object that goes out of reach.
Expected<void> check_frames_in_reach(const SceneAnimation& animation, const Scene& scene,
                                     const std::filesystem::path& scene_file)
{
    const std::optional<OutOfReach> beyond = animation.first_out_of_reach(max_dat_magnitude);
    if (!beyond)
        return ok;
    const SceneObject& object = scene.objects[beyond->object];
    // A turn of its hub's travel / RADIUS radians that is no number (a radius of 1e-308): its ROLL.
    if (std::isnan(beyond->magnitude) && object.roll && !(beyond->at_anchor && object.anchor))
        return Diagnostic{scene_file.string(), object.roll->line,
                          "object " + object.name + " reaches values that are not numbers at frame " +
                              std::to_string(beyond->frame) + ": its ROLL turns it by its hub's travel / RADIUS " +
                              significant_number(object.roll->radius, 3) +
                              " radians, beyond a number; expected a wheel's radius"};
    const std::string reach = std::isnan(beyond->magnitude)
                                  ? "values that are not numbers"
                                  : "|value| " + magnitude_beyond(beyond->magnitude, max_dat_magnitude);
    const std::string how = beyond->at_anchor && object.anchor
                                ? "put on its joint '" + object.joints[object.anchor->joint].name + "' with '" +
                                      scene.objects[object.anchor->partner].name + "'" +
                                      (object.rigid() ? ", turned about it" : "")
                                : "its MOVE, ROTATE and SCALE composed with its parents'";
    return Diagnostic{scene_file.string(), object.line,
                      "object " + object.name + " reaches " + reach + " at frame " +
                          std::to_string(beyond->frame) + " (" + how + "); a frame holds |value| <= 1e9, "
                          "as a .dat file does"};
}

// What only the computed frames show, before anything is printed or written: every value within
// what a frame file holds, and every joint that closes a cycle of joints still closed.
Expected<void> check_frames(const SceneAnimation& animation, const Scene& scene, const std::filesystem::path& scene_file)
{
    if (Expected<void> reachable = check_frames_in_reach(animation, scene, scene_file); !reachable)
        return reachable;
    return check_closing_joints(scene, animation, scene_file_name(scene_file));
}

// --out: every frame file must read back, so a PART line longer than a .dat line may be (an
// object's name and its part's name, each up to a scene or .dat line long, joined as
// "OBJECT/PART") is refused before any frame is written, at the object's line.
Expected<void> check_part_lines_fit(const SceneAnimation& animation, const Scene& scene,
                                    const std::filesystem::path& scene_file)
{
    const std::vector<GraphicPart>& parts = animation.structure().parts;
    std::size_t index = 0;
    for (const SceneObject& object : scene.objects) {
        const Graphic* drawing = object.first_drawing();
        for (std::size_t p = 0; drawing != nullptr && p < drawing->parts.size() && index < parts.size(); ++p, ++index) {
            const std::string line = part_line(parts[index].name, parts[index].closure, index);
            if (line.size() <= max_dat_line_bytes)
                continue;
            return Diagnostic{scene_file.string(), object.line,
                              "object " + quote_field(object.name) + ": its part " + std::to_string(p + 1) +
                                  " would be written to the frame files as the line " + quote_field(line) + " of " +
                                  std::to_string(line.size()) + " bytes; expected at most " +
                                  std::to_string(max_dat_line_bytes) +
                                  ", as a .dat file is read (give the object or the part a shorter name)"};
        }
    }
    return ok;
}

ViewAngles view_of(const Scene& scene, const CommonOptions& options)
{
    ViewAngles view = scene.view.value_or(ViewAngles{});
    if (options.given.theta)
        view.theta_degrees = options.view.theta_degrees;
    if (options.given.phi)
        view.phi_degrees = options.view.phi_degrees;
    return view;
}

// The options the outputs use: the scene's VIEW unless --theta or --phi says otherwise, and the
// files the scene reads (`inputs`) among those no output or backup replaces.
CommonOptions scene_shown_options(const Scene& scene, const CommonOptions& options,
                                  const std::vector<std::filesystem::path>& inputs)
{
    CommonOptions shown = options;
    shown.view = view_of(scene, options);
    shown.read_files.insert(shown.read_files.end(), inputs.begin(), inputs.end());
    return shown;
}

// The overlay of a scene's frames: its legend names frames 0 … N, and the timed waypoints are
// lettered A, B, … in file order, a line per object saying when it is at them ("A-D: car at frames
// 0, 10, 35, 60"). Waypoints past Z are not lettered.
FramesOverlay scene_overlay(const Scene& scene, const SceneAnimation& animation)
{
    FramesOverlay overlay{scene_frames_names(animation.frame_count()), {}, {}, false, {}};
    const std::vector<TimedWaypoint> waypoints = timed_waypoints(scene, animation);
    for (std::size_t k = 0; k < waypoints.size() && k < 26;) {
        const std::size_t object = waypoints[k].object;
        const std::size_t first = k;
        std::string frames;
        for (; k < waypoints.size() && k < 26 && waypoints[k].object == object; ++k) {
            overlay.points.push_back({std::string(1, static_cast<char>('A' + k)), waypoints[k].position});
            frames += (frames.empty() ? "" : ", ") + std::to_string(waypoints[k].frame);
        }
        const std::string letters = overlay.points[first].label + (k - first > 1 ? "-" + overlay.points[k - 1].label : "");
        overlay.notes.push_back(letters + ": " + scene.objects[object].name + " at frame" + (k - first > 1 ? "s " : " ") +
                                frames);
    }
    return overlay;
}

// The scene as the options play it, and the .dat files it reads (`inputs`), which no picture may
// write over.
Expected<Scene> read_played_scene(const PlayRequest& request, const CommonOptions& options,
                                  std::vector<std::filesystem::path>& inputs)
{
    Expected<Scene> scene = read_scene_file(request.scene, options.staff, &inputs);
    if (!scene)
        return scene;
    // An explicit --slopes overrides the PATHS files' SLOPES lines, as in apcs fit (SPEC §2.1).
    if (options.given.slopes)
        for (SceneObject& object : scene->objects)
            if (object.keys)
                object.keys->first_slopes = object.keys->last_slopes = std::nullopt;
    // The .dat files a scene reads are known only now; the command line checked the scene file.
    if (Expected<void> done = check_pictures_spare_inputs(options, inputs); !done)
        return done.error();
    return scene;
}

ExitStatus play_on_terminal(AnimationPlayer& player, const CommonOptions& options,
                            const TerminalRunner& terminal, std::ostream& err)
{
    if (!terminal || !::isatty(STDIN_FILENO)) {
        err << "apcs: standard input is not a terminal; give --print, --out, --png, --svg, --sixel, --kitty or --gif "
               "to play a scene without one\n";
        return ExitStatus::terminal_problem;
    }
    const Expected<GlyphSet> glyphs = terminal_glyphs_here(options.glyphs);
    if (!glyphs) {
        err << glyphs.error().to_string() << '\n';
        return ExitStatus::bad_usage;
    }
    ScenePlayer program(player, options.delay_ms, save_screen_picture);
    const Expected<ExitStatus> played = terminal(program, *glyphs, ColourChoice::never, options.pixels);
    if (!played) {
        err << played.error().to_string() << '\n';
        return ExitStatus::terminal_problem;
    }
    return *played;
}

} // namespace

std::string save_screen_picture(const GraphicsScreen& screen)
{
    for (int number = 1; number <= most_pictures; ++number) {
        const std::string name = picture_file_name(number);
        std::error_code error;
        if (std::filesystem::exists(std::filesystem::symlink_status(name, error)))
            continue;
        std::ostringstream unused;
        // A name not taken: no old picture is replaced, so no backup needs guarding.
        const KeyFileGuard nothing_read;
        if (const Expected<void> written = write_png_file(name, screen, PngShape::monitor, nothing_read, unused);
            !written)
            return written.error().to_string();
        return "wrote " + name;
    }
    return "apcs001.png … apcs999.png all exist; move some away";
}

std::string scene_frame_file_name(int frame, int last_frame)
{
    const std::size_t width = std::max<std::size_t>(3, std::to_string(last_frame).size());
    std::string number = std::to_string(frame);
    number.insert(0, width - std::min(width, number.size()), '0');
    return "frm" + number + ".dat";
}

ExitStatus run_play_command(const PlayRequest& request, const CommonOptions& options,
                            const TerminalRunner& terminal, std::ostream& out, std::ostream& err)
{
    if (request.tree && (options.print || options.out || pictures_asked(options))) {
        err << "apcs: --tree prints the scene's tree and nothing else; give --print, --out and the pictures without it\n";
        return ExitStatus::bad_usage;
    }
    std::vector<std::filesystem::path> inputs;
    Expected<Scene> scene = read_played_scene(request, options, inputs);
    if (!scene)
        return report_bad_input(scene.error(), err);
    const std::string scene_name = request.scene.filename().string();
    if (request.tree) {
        out << format_scene_tree(*scene, scene_name);
        return ExitStatus::success;
    }
    const PathSettings settings = scene_path_settings(*scene, options.path, options.given.spacing);
    const bool played = !options.print && !options.out && !pictures_asked(options);
    const bool all_frames = played || pictures_asked(options);
    if (const auto refused = refuse_over_budget("the frames of " + scene_name, scene_bytes(*scene, settings, all_frames),
                                                options, "use fewer FRAMES or drawings of fewer points", err))
        return *refused;
    const SceneAnimation animation(*scene, settings, options.surface);
    if (Expected<void> playable = check_frames(animation, *scene, request.scene); !playable)
        return report_bad_input(playable.error(), err);
    if (options.out)
        if (Expected<void> fits = check_part_lines_fit(animation, *scene, request.scene); !fits)
            return report_bad_input(fits.error(), err);
    if (options.print)
        print_frames(animation, *scene, out);
    const CommonOptions shown = scene_shown_options(*scene, options, inputs);
    if (options.out)
        if (Expected<void> done = write_frame_files(animation, *options.out, read_files_guard(shown), err); !done)
            return report_bad_input(done.error(), err);
    if (!all_frames)
        return ExitStatus::success;
    FrameSequence frames = animation.all_frames();
    const std::size_t frame_count = frames.frame_count();
    FramesOverlay overlay = scene_overlay(*scene, animation);
    if (still_pictures_asked(options)) {
        const std::string caption = std::to_string(frames.frame_count()) + " frames overlaid: " + scene_name;
        if (Expected<void> done = write_pictures(
                frames_overlay_screen(frames, animation.structure(), shown.view, caption, overlay), shown, out);
            !done)
            return report_bad_input(done.error(), err);
    }
    UnloggedSteps log;
    AnimationPlayer player(std::move(frames), animation.structure(), {scene_name, scene_name}, shown.view,
                           options.delay_ms, log);
    player.name_frames_by_scene(scene_name);
    player.letter_points(std::move(overlay.points), std::move(overlay.notes));
    if (options.gif)
        if (Expected<void> done =
                write_player_gif(player, frame_count, *options.gif, options.delay_ms, read_files_guard(shown), out);
            !done)
            return report_bad_input(done.error(), err);
    if (!played)
        return ExitStatus::success;
    return play_on_terminal(player, shown, terminal, err);
}

} // namespace apcs
