#include "apcs/formats/inbetween_files.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/parallel_work.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"

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
    const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    for_each_index_in_parallel(count, workers, [&](std::size_t index) {
        const NamedText file = inbetween_file(frames, structure, index + 1);
        const Expected<WriteResult> result = write_file_atomically(targets[index], file.content, &guard);
        if (!result)
            problems[index] = result.error();
    });
    for (const std::optional<Diagnostic>& problem : problems)
        if (problem)
            return *problem;
    return targets;
}

namespace {

// The number of an in-between file's name ("inb013.dat" → 13), nullopt for any other name.
std::optional<std::size_t> inbetween_number(std::string_view name)
{
    constexpr std::string_view prefix = "inb";
    constexpr std::string_view suffix = ".dat";
    constexpr std::size_t fewest_digits = 3;
    if (name.size() < prefix.size() + fewest_digits + suffix.size() ||
        !equals_ignoring_case(name.substr(0, prefix.size()), prefix) ||
        !equals_ignoring_case(name.substr(name.size() - suffix.size()), suffix))
        return std::nullopt;
    const std::string_view digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.find_first_not_of("0123456789") != std::string_view::npos)
        return std::nullopt;
    return parse_count_value(digits);
}

} // namespace

std::vector<std::string> inbetweens_beyond(std::span<const std::string> names, std::size_t written_count)
{
    std::vector<std::pair<std::size_t, std::string>> numbered;
    for (const std::string& name : names)
        if (const std::optional<std::size_t> number = inbetween_number(name); number && *number > written_count)
            numbered.emplace_back(*number, name);
    std::sort(numbered.begin(), numbered.end());
    std::vector<std::string> earlier;
    for (auto& [number, name] : numbered)
        earlier.push_back(std::move(name));
    return earlier;
}

std::vector<std::string> inbetweens_beyond(const std::filesystem::path& folder, std::size_t written_count)
{
    std::vector<std::string> names;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
        names.push_back(entry->path().filename().string());
    return inbetweens_beyond(names, written_count);
}

std::optional<std::string> earlier_inbetweens_note(std::span<const std::string> earlier)
{
    if (earlier.empty())
        return std::nullopt;
    if (earlier.size() == 1)
        return earlier.front() + " is from an earlier run (not rewritten)";
    return earlier.front() + " to " + earlier.back() + " (" + std::to_string(earlier.size()) +
           " files) are from an earlier run (not rewritten)";
}

} // namespace apcs
