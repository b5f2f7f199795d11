#include "apcs/formats/inbetween_files.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <thread>

namespace apcs {

Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames, const Graphic& structure,
                                                                   const std::filesystem::path& folder,
                                                                   const KeyFileGuard& guard)
{
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return Diagnostic{folder.string(), 0, "is not a folder; expected an existing folder for the in-between files"};
    const std::size_t count = inbetween_count(frames);
    std::vector<std::filesystem::path> targets;
    targets.reserve(count);
    for (std::size_t number = 1; number <= count; ++number) {
        targets.push_back(folder / inbetween_file_name(number));
        if (std::optional<Diagnostic> refusal = guard.refuse(targets.back()))
            return *std::move(refusal);
    }
    // The files are independent: formatting and flushing them to disk is shared among the cores.
    std::vector<std::optional<Diagnostic>> problems(count);
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t index = next++; index < count; index = next++) {
            const NamedText file = inbetween_file(frames, structure, index + 1);
            const Expected<WriteResult> result = write_file_atomically(targets[index], file.content, &guard);
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

} // namespace apcs
