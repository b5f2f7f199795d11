#include "apcs/formats/numbered_files.h"

#include "apcs/animation/memory_budget.h"
#include "apcs/base/parallel_work.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <optional>
#include <set>
#include <sys/statvfs.h>
#include <thread>

namespace apcs {

namespace {

std::uintmax_t content_bytes(std::size_t index, const std::function<void(std::size_t, const ContentSink&)>& writer_of)
{
    std::uintmax_t bytes = 0;
    writer_of(index, [&bytes](std::string_view chunk) {
        bytes += chunk.size();
        return true;
    });
    return bytes;
}

// Files that a full disk would stop halfway through the run are refused before the first: what
// the folder's file system has free for the user against the estimate. Unknown free space lets
// the writes go on (a write that then fails leaves every file whole).
Expected<void> check_room(const std::filesystem::path& folder, std::size_t count,
                          const std::function<void(std::size_t, const ContentSink&)>& writer_of,
                          std::string_view purpose)
{
    struct statvfs space {};
    if (count == 0 || ::statvfs(folder.c_str(), &space) != 0)
        return ok;
    const std::uintmax_t free_bytes = static_cast<std::uintmax_t>(space.f_bavail) * space.f_frsize;
    // One file first, the middle one (whose frame carries the most digits): when the run would take
    // a quarter of the free space or less by it, no file of the run is four times its size and the
    // room is ample. Making the five samples (and counting their bytes) cost the fit of 10^5 points
    // x 12 in-betweens 5 of its 12 frames again, before the first was written (issue 44 item 7).
    const std::uintmax_t block = std::max<std::uintmax_t>(space.f_frsize, 1);
    const std::uintmax_t middle = (content_bytes((count - 1) / 2, writer_of) + block - 1) / block * block;
    constexpr std::uintmax_t ample = 4;
    if (middle <= free_bytes / ample / count)
        return ok;
    return room_for_files(estimated_files_bytes(count, writer_of, space.f_frsize), free_bytes, count, folder, purpose);
}

// A write that failed after the checks (a disk filled by someone else meanwhile): the problem,
// then how many of the run were written and which were not (those are as they were: an earlier
// run's, or none).
Diagnostic with_run_told(Diagnostic problem, const std::vector<std::filesystem::path>& targets,
                         const std::vector<Expected<void>>& outcomes)
{
    std::vector<std::string> left;
    for (std::size_t index = 0; index < targets.size(); ++index)
        if (!outcomes[index])
            left.push_back(targets[index].filename().string());
    const std::size_t written = targets.size() - left.size();
    problem.message += "; " + std::to_string(written) + " of " + std::to_string(targets.size()) +
                       " files were written, not " + left.front();
    if (left.size() > 1)
        problem.message += (left.size() == 2 ? " and " : " ... ") + left.back() + " (" + std::to_string(left.size()) + ")";
    problem.message += ", which are as they were";
    return problem;
}

} // namespace

std::uintmax_t estimated_files_bytes(std::size_t count,
                                     const std::function<void(std::size_t, const ContentSink&)>& writer_of,
                                     std::uintmax_t block_bytes)
{
    if (count == 0)
        return 0;
    // A file takes whole blocks of its file system: 500 bytes take 4 KiB on most.
    const std::uintmax_t block = std::max<std::uintmax_t>(block_bytes, 1);
    const auto on_disk = [block](std::uintmax_t bytes) { return (bytes + block - 1) / block * block; };
    const std::size_t last = count - 1;
    std::vector<std::size_t> samples{0, last / 4, last / 2, last - last / 4, last};
    samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
    long double sampled = 0;
    for (const std::size_t index : samples)
        sampled += static_cast<long double>(on_disk(content_bytes(index, writer_of)));
    const long double average = sampled / static_cast<long double>(samples.size());
    const long double total = average * static_cast<long double>(count);
    constexpr long double most = static_cast<long double>(UINTMAX_MAX);
    // A run that is small on the whole is measured file by file (a path that bulges between the
    // samples takes more than they say); a large one keeps the samples, made once each.
    constexpr long double measured_whole_below = 8.0L * 1024 * 1024;
    if (total < measured_whole_below && count > samples.size()) {
        std::uintmax_t measured = 0;
        for (std::size_t index = 0; index < count; ++index)
            measured += on_disk(content_bytes(index, writer_of));
        return measured;
    }
    return total >= most ? UINTMAX_MAX : static_cast<std::uintmax_t>(total);
}

Expected<void> room_for_files(std::uintmax_t needed, std::uintmax_t free_bytes, std::size_t count,
                              const std::filesystem::path& folder, std::string_view purpose)
{
    if (needed <= free_bytes)
        return ok;
    return Diagnostic{folder.string(), 0,
                      std::string(purpose) + " need about " + memory::byte_count_text(needed) + " (" +
                          std::to_string(count) + " files); the folder has " + memory::byte_count_text(free_bytes) +
                          " free"};
}

Expected<void> make_output_folder(const std::filesystem::path& folder, std::string_view purpose)
{
    std::error_code error;
    if (std::filesystem::is_directory(folder, error))
        return ok;
    if (std::filesystem::symlink_status(folder, error).type() != std::filesystem::file_type::not_found)
        return Diagnostic{folder.string(), 0, "is not a folder; expected a folder for " + std::string(purpose)};
    // "out/" names the folder out.
    const std::filesystem::path itself = folder.has_filename() ? folder : folder.parent_path();
    const std::filesystem::path parent = itself.parent_path().empty() ? "." : itself.parent_path();
    if (!std::filesystem::is_directory(parent, error))
        return Diagnostic{folder.string(), 0,
                          "cannot be made: " + parent.string() + " is not a folder (--out makes one level, not its parents)"};
    if (!std::filesystem::create_directory(itself, error) && error)
        return Diagnostic{folder.string(), 0, "cannot be made: " + error.message()};
    return ok;
}

Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<void(std::size_t, const ContentSink&)>& writer_of, const KeyFileGuard& guard,
                     std::string_view purpose, const WriteProgress& progress)
{
    if (Expected<void> made = make_output_folder(folder, purpose); !made)
        return made.error();
    // Opened before the checks: the files checked are those written, in this folder however it
    // is renamed or replaced meanwhile (a run of 10^5 frames takes minutes).
    const Expected<OutputFolder> opened = OutputFolder::open(folder);
    if (!opened)
        return opened.error();
    std::vector<std::filesystem::path> targets;
    targets.reserve(count);
    for (std::size_t index = 0; index < count; ++index) {
        targets.push_back(folder / name_of(index));
        if (Expected<void> writable = guard.may_write(targets.back()); !writable)
            return writable.error();
        const auto content = [&writer_of, index](const ContentSink& sink) { writer_of(index, sink); };
        if (Expected<void> replaceable = check_replaceable(targets.back(), content, &guard); !replaceable)
            return replaceable.error();
    }
    if (Expected<void> room = check_room(folder, count, writer_of, purpose); !room)
        return room.error();
    // The files are independent: making, formatting and flushing them is shared among the cores.
    std::vector<Expected<void>> outcomes(count, ok);
    std::vector<char> written(count, 0);
    std::atomic<std::size_t> finished = 0;
    const std::size_t workers = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    for_each_index_in_parallel(count, workers, [&](std::size_t index) {
        const auto write_content = [&writer_of, index](const ContentSink& sink) { writer_of(index, sink); };
        const Expected<WriteResult> result = write_file_atomically(*opened, targets[index].filename().string(),
                                                                   write_content, &guard, Durability::at_barrier);
        if (!result)
            outcomes[index] = result.error();
        else
            written[index] = result->outcome != WriteOutcome::unchanged;
        if (progress)
            progress(++finished, count);
    });
    // The files written are put on the disk even when another failed: they are whole and stay.
    Expected<void> flushed = ok;
    if (std::find(written.begin(), written.end(), 1) != written.end())
        flushed = flush_file_system(folder);
    for (const Expected<void>& outcome : outcomes)
        if (!outcome)
            return with_run_told(outcome.error(), targets, outcomes);
    if (!flushed)
        return flushed.error();
    return targets;
}

Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<std::string(std::size_t)>& content_of, const KeyFileGuard& guard,
                     std::string_view purpose, const WriteProgress& progress)
{
    return write_numbered_files(
        folder, count, name_of, [&content_of](std::size_t index, const ContentSink& sink) { sink(content_of(index)); },
        guard, purpose, progress);
}

namespace {

// The number of `name` in the set PREFIX + digits + SUFFIX ("frm013.dat" -> 13), nullopt for any
// other name.
std::optional<std::size_t> number_in_set(std::string_view name, std::string_view prefix, std::string_view suffix)
{
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

std::vector<std::string> numbered_names(std::span<const std::string> names, std::string_view prefix,
                                        std::string_view suffix,
                                        const std::function<bool(std::size_t number, const std::string& name)>& keep)
{
    std::vector<std::pair<std::size_t, std::string>> numbered;
    for (const std::string& name : names)
        if (const std::optional<std::size_t> number = number_in_set(name, prefix, suffix); number && keep(*number, name))
            numbered.emplace_back(*number, name);
    std::sort(numbered.begin(), numbered.end());
    std::vector<std::string> kept;
    for (auto& [number, name] : numbered)
        kept.push_back(std::move(name));
    return kept;
}

std::vector<std::string> file_names_in(const std::filesystem::path& folder)
{
    std::vector<std::string> names;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error))
        names.push_back(entry->path().filename().string());
    return names;
}

std::vector<std::string> earlier_numbered_files(std::span<const std::string> names, std::string_view prefix,
                                                std::string_view suffix, std::span<const std::string> written)
{
    const std::set<std::string_view> now(written.begin(), written.end());
    return numbered_names(names, prefix, suffix, [&now](std::size_t, const std::string& name) { return !now.contains(name); });
}

std::vector<std::string> earlier_numbered_files(const std::filesystem::path& folder, std::string_view prefix,
                                                std::string_view suffix, std::span<const std::string> written)
{
    return earlier_numbered_files(file_names_in(folder), prefix, suffix, written);
}

std::string picture_file_name(int number)
{
    char name[32];
    std::snprintf(name, sizeof name, "apcs%03d.png", number);
    return name;
}

} // namespace apcs
