#include "frame_output.h"

#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/cli/write_progress.h"

#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/print_format.h"
#include "apcs/raster/gif_encoder.h"
#include "apcs/playback/animation_player.h"
#include "apcs/screens/frames_overlay.h"

#include <optional>
#include <ostream>
#include <utility>
#include <string>
#include <vector>

namespace apcs {

std::string format_frames_print(const FrameSequence& frames)
{
    std::string text;
    // About 33 bytes a point: one allocation for the whole output.
    text.reserve(frames.frame_count() * (frames.points_per_frame() * 33 + 16));
    for (std::size_t k = 0; k < frames.frame_count(); ++k)
        append_print_section(text, "frame " + std::to_string(k), frames.frame(k));
    return text;
}

namespace {

Expected<void> write_overlay_pictures(const FrameSequence& frames, const Graphic& structure,
                                      const CommonOptions& options,
                                      std::span<const std::filesystem::path> key_files, std::ostream& out)
{
    if (!pictures_asked(options))
        return ok;
    const std::string key1 = key_files.front().filename().string();
    const std::string key2 = key_files.back().filename().string();
    const std::string caption = std::to_string(frames.frame_count()) + " frames overlaid: " + key1 + " to " + key2;
    const FramesOverlay overlay{key_frames_names(key1, key2, frames.frame_count()), {}, {}, false, {}};
    return write_pictures(frames_overlay_screen(frames, structure, options.view, caption, overlay), options, out);
}

// --gif: every frame as the session's animation shows it (KEY1, the in-betweens, KEY2).
Expected<void> write_animation_gif(const FrameSequence& frames, const Graphic& structure,
                                   const CommonOptions& options,
                                   std::span<const std::filesystem::path> key_files, std::ostream& out)
{
    if (!options.gif)
        return ok;
    UnloggedSteps log;
    AnimationPlayer player(frames, structure, {key_files.front().filename().string(), key_files.back().filename().string()},
                           options.view, options.delay_ms, log);
    return write_player_gif(player, frames.frame_count(), *options.gif, options.delay_ms, read_files_guard(options),
                            out);
}

} // namespace

Expected<void> write_player_gif(AnimationPlayer& player, std::size_t frame_count,
                                const std::filesystem::path& target, int delay_ms, const KeyFileGuard& inputs,
                                std::ostream& out)
{
    std::size_t shown = 0;
    const auto frame_at = [&](std::size_t k) {
        for (; shown < k; ++shown)
            player.tick();
        return render_raster(player.view());
    };
    const Expected<std::string> gif = encode_gif(frame_count, frame_at, gif_delay_centiseconds(delay_ms));
    if (!gif)
        return Diagnostic{target.string(), 0, "cannot encode the GIF image: " + gif.error().message};
    return write_picture_bytes(target, *gif, inputs, out);
}

ExitStatus deliver_frames(const FrameSequence& frames, const Graphic& structure, const CommonOptions& options,
                          std::span<const std::filesystem::path> key_files, std::ostream& out, std::ostream& err)
{
    if (Expected<void> done = write_overlay_pictures(frames, structure, options, key_files, out); !done)
        return report_bad_input(done.error(), err);
    if (Expected<void> done = write_animation_gif(frames, structure, options, key_files, out); !done)
        return report_bad_input(done.error(), err);
    if (options.print) {
        const std::string text = format_frames_print(frames);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
    const bool files_asked = options.out || !(options.print || pictures_asked(options));
    if (!files_asked)
        return ExitStatus::success;
    return deliver_inbetween_files(
        [&](const std::filesystem::path& folder, const KeyFileGuard& guard, const WriteProgress& progress) {
            return write_inbetween_files(frames, structure, folder, guard, progress);
        },
        options, key_files, err);
}

ExitStatus deliver_inbetween_files(const InbetweenWriter& write, const CommonOptions& options,
                                   std::span<const std::filesystem::path> key_files, std::ostream& err)
{
    KeyFileGuard guard = read_files_guard(options);
    for (const std::filesystem::path& key_file : key_files)
        guard.protect(key_file);
    const std::filesystem::path folder = options.out.value_or(".");
    WriteProgressLine progress(err, standard_error_is_terminal(), "the in-between files");
    const auto written = write(folder, guard, progress.report());
    if (!written)
        return report_bad_input(written.error(), err);
    std::vector<std::string> earlier = inbetweens_beyond(folder, written->size());
    if (options.out)
        for (std::string& name : earlier)
            name = (folder / name).string();
    if (const std::optional<std::string> note = earlier_inbetweens_note(earlier))
        err << "apcs: " << *note << '\n';
    return ExitStatus::success;
}

} // namespace apcs
