#include "apcs/cli/frame_output.h"

#include "apcs/cli/report.h"

#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/print_format.h"

#include <ostream>

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

ExitStatus deliver_frames(const FrameSequence& frames, const Graphic& structure, const CommonOptions& options,
                          std::span<const std::filesystem::path> key_files, std::ostream& out, std::ostream& err)
{
    if (options.print) {
        const std::string text = format_frames_print(frames);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        return ExitStatus::success;
    }
    KeyFileGuard guard;
    for (const std::filesystem::path& key_file : key_files)
        guard.protect(key_file);
    const auto written = write_inbetween_files(frames, structure, options.out.value_or("."), guard);
    if (!written)
        return report_bad_input(written.error(), err);
    return ExitStatus::success;
}

} // namespace apcs
