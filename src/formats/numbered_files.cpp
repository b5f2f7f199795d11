#include "apcs/formats/numbered_files.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/parallel_work.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <thread>

namespace apcs {

Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<std::string(std::size_t)>& content_of, const KeyFileGuard& guard,
                     std::string_view purpose)
{
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return Diagnostic{folder.string(), 0, "is not a folder; expected an existing folder for " + std::string(purpose)};
    std::vector<std::filesystem::path> targets;
    targets.reserve(count);
    for (std::size_t index = 0; index < count; ++index) {
        targets.push_back(folder / name_of(index));
        if (std::optional<Diagnostic> refusal = guard.refuse(targets.back()))
            return *std::move(refusal);
    }
    // The files are independent: making, formatting and flushing them is shared among the cores.
    std::vector<std::optional<Diagnostic>> problems(count);
    const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    for_each_index_in_parallel(count, workers, [&](std::size_t index) {
        const Expected<WriteResult> result = write_file_atomically(targets[index], content_of(index), &guard);
        if (!result)
            problems[index] = result.error();
    });
    for (const std::optional<Diagnostic>& problem : problems)
        if (problem)
            return *problem;
    return targets;
}

std::string picture_file_name(int number)
{
    char name[32];
    std::snprintf(name, sizeof name, "apcs%03d.png", number);
    return name;
}

} // namespace apcs
