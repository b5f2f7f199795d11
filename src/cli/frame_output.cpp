#include "apcs/cli/frame_output.h"

#include "apcs/cli/report.h"

#include "apcs/formats/dat_file.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/print_format.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <optional>
#include <thread>
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

namespace {

bool is_protected(const std::filesystem::path& target, std::span<const std::filesystem::path> protected_files)
{
    std::error_code error;
    for (const std::filesystem::path& file : protected_files)
        if (std::filesystem::equivalent(target, resolve_input_path(file), error))
            return true;
    return false;
}

} // namespace

Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames, const Graphic& structure,
                                                                   const std::filesystem::path& folder,
                                                                   std::span<const std::filesystem::path> protected_files)
{
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return Diagnostic{folder.string(), 0, "is not a folder; expected an existing folder for the in-between files"};
    const std::size_t count = inbetween_count(frames);
    std::vector<std::filesystem::path> targets;
    for (std::size_t number = 1; number <= count; ++number) {
        targets.push_back(folder / inbetween_file_name(number));
        if (is_protected(targets.back(), protected_files))
            return Diagnostic{targets.back().string(), 0, "is a key file; key files are never written"};
    }
    // The files are independent: formatting and flushing them to disk is shared among the cores.
    std::vector<std::optional<Diagnostic>> problems(count);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t index = next++; index < count; index = next++) {
            const NamedText file = inbetween_file(frames, structure, index + 1);
            const Expected<WriteResult> result = write_file_atomically(targets[index], file.content);
            if (!result)
                problems[index] = result.error();
        }
    };
    const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    {
        std::vector<std::jthread> helpers;
        for (std::size_t i = 1; i < std::min(workers, count); ++i)
            helpers.emplace_back(work);
        work();
    }
    for (const std::optional<Diagnostic>& problem : problems)
        if (problem)
            return *problem;
    return targets;
}

ExitStatus deliver_frames(const FrameSequence& frames, const Graphic& structure, const CommonOptions& options,
                          std::span<const std::filesystem::path> key_files, std::ostream& out, std::ostream& err)
{
    if (options.print) {
        const std::string text = format_frames_print(frames);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        return ExitStatus::success;
    }
    const auto written = write_inbetween_files(frames, structure, options.out.value_or("."), key_files);
    if (!written)
        return report_bad_input(written.error(), err);
    return ExitStatus::success;
}

} // namespace apcs
