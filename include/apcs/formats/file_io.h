#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/dat_file.h"
#include "apcs/formats/key_file_guard.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>

namespace apcs {

// The file a user means by `name`: the name itself when it exists (so Case.dat beside case.DAT
// is Case.dat), else the one entry of its folder whose name matches case-insensitively (as DOS
// did: KEY1.DAT finds key1.dat), else `name`. Two or more such entries and no exact one is an
// error that names them all ("is ambiguous: Case.dat and case.DAT differ only in case; ...").
Expected<std::filesystem::path> find_input_path(const std::filesystem::path& name);

// find_input_path's file, or `name` itself when that is ambiguous.
std::filesystem::path resolve_input_path(const std::filesystem::path& name);

// Whole text of a file, resolved as above. Errors name the file as the user typed it. Only a
// regular file (or a symbolic link to one) is read: a directory, a FIFO, a device or a socket is
// refused without being opened, so that a FIFO nobody writes never hangs the program. A file of
// more than `most_bytes` is refused by its size before it is read, and a NUL byte (no text has
// one) at the chunk that holds it, so that neither costs the memory of the whole file.
inline constexpr std::uintmax_t max_input_bytes = 1ull << 30;
Expected<std::string> read_text_file(const std::filesystem::path& name, std::uintmax_t most_bytes = max_input_bytes);

// read_text_file's checks and messages for a file read a block at a time: each block goes to
// `consume` (whose problem ends the reading), none is kept. `file_size`, when given, receives the
// file's size before the first block.
Expected<void> read_text_pieces(const std::filesystem::path& name, const TextPieceSink& consume,
                                std::uintmax_t most_bytes = max_input_bytes,
                                std::uintmax_t* file_size = nullptr);

// A .dat file, or standard input when `name` is "-" (messages then say "standard input:LINE").
Expected<DatFile> read_dat_file(const std::filesystem::path& name, std::size_t minimum_points = 2);

// A key frame: a .dat file of at least two points, as a graphic.
Expected<Graphic> read_key_frame(const std::filesystem::path& name);

// A keystroke script (--keys): read as read_text_file reads, except that a pipe or a FIFO is read
// too, once to its end, since scripts come from other programs (bash's <(...) is /dev/fd/N); one
// that nobody writes waits for a writer, as `cat` would. "-" is standard input. A stream is held
// to the line limit as it is read: a line of more than max_text_line_bytes stops the reading.
Expected<std::string> read_script_text(const std::filesystem::path& name, std::uintmax_t most_bytes = max_input_bytes);

enum class WriteOutcome { created, replaced, unchanged };

struct WriteResult {
    WriteOutcome outcome = WriteOutcome::created;
    // Where the previous content was kept when the file was replaced (NAME.bak), else empty.
    std::filesystem::path backup;
};

// When a written file's bytes must be on the disk: before its rename (each file on its own), or
// at one barrier the caller makes for many files (flush_file_system). Either way a reader, or a
// program stopped by a signal, never sees half a file; only a crash of the whole machine before
// the barrier could lose the new files' content.
enum class Durability { each_file, at_barrier };

// Writes `content` to `target` atomically: a temporary file in the same folder, flushed, then
// renamed over the target, so a reader never sees half a file. An existing target whose content
// differs is first kept as the same name with the extension .bak (way1.dat → way1.bak, replacing an
// older .bak); identical content leaves the file untouched. A replaced file keeps its mode (and
// its owner and group where the user may set them); a new one is 0644. Only regular files are
// replaced: a symbolic link to a regular file in the link's folder or below it is written through
// (the file it names is replaced in its own folder, its .bak beside it, the link stays), a link
// that leads elsewhere is refused (check_link_stays_in_folder); a directory, a FIFO, a device, a socket, a
// link to one or a dangling link is refused, and so is a read-only file (no write permission for
// the user; for root, no write bit at all). A refusal, a missing folder, a full disk or a failed
// rename is reported and leaves every file as it was. When NAME.bak is one of `inputs` (a key
// file of the run), the old file is kept as NAME.b01 (or the first of .b02 … .b99 that is free)
// instead, so that a backup never replaces an input; WriteResult::backup names it.
Expected<WriteResult> write_file_atomically(const std::filesystem::path& target, std::string_view content,
                                            const KeyFileGuard* inputs = nullptr,
                                            Durability durability = Durability::each_file);

// Whether check_writable refuses a read-only target now, or leaves it to the write, which refuses
// it only when its content would change.
enum class ReadOnlyTarget { refused, left_to_the_write };

// What write_file_atomically would refuse before writing anything, checked ahead of a run that
// writes `target` only at its end (--record) or after other files (in-betweens): a target that is
// not a regular file (or a link to one), a read-only one (as `read_only` says), or a folder that
// does not exist or cannot be written. The problem, if any.
Expected<void> check_writable(const std::filesystem::path& target, ReadOnlyTarget read_only = ReadOnlyTarget::refused);

// A file's content in chunks: the writer calls the sink with each chunk in order and stops when
// it says false (the write failed; the problem is in write_file_atomically's result).
using ContentSink = std::function<bool(std::string_view chunk)>;
using ContentWriter = std::function<void(const ContentSink& sink)>;

// write_file_atomically for content made chunk by chunk, never whole in memory: while it equals
// the existing file it is only compared; the temporary file is made at the first difference.
Expected<WriteResult> write_file_atomically(const std::filesystem::path& target, const ContentWriter& write_content,
                                            const KeyFileGuard* inputs = nullptr,
                                            Durability durability = Durability::each_file);

// A folder that a run of files is written into, opened once: every file written through it
// (write_file_atomically below) is made, replaced and kept as .bak in the folder opened, wherever
// it is renamed or moved meanwhile, and never in a folder or a link put in its place (mv out out2;
// ln -s elsewhere out, issue 56). The files are reached through /proc/self/fd (Linux); where /proc
// is not mounted (a bare chroot) they are reached by the folder's name, as before issue 56.
class OutputFolder {
public:
    // `folder` opened, or why it cannot be.
    [[nodiscard]] static Expected<OutputFolder> open(const std::filesystem::path& folder);
    OutputFolder(OutputFolder&& other) noexcept;
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;
    OutputFolder& operator=(OutputFolder&&) = delete;
    ~OutputFolder();

    // The folder as it was named, for messages.
    const std::filesystem::path& path() const { return m_path; }
    // `name` in the folder opened, as a path the kernel resolves through its descriptor.
    std::filesystem::path reached(const std::string& name) const;

private:
    OutputFolder(std::filesystem::path path, int descriptor, bool reached_by_descriptor)
        : m_path(std::move(path)), m_descriptor(descriptor), m_reached_by_descriptor(reached_by_descriptor)
    {
    }

    std::filesystem::path m_path;
    int m_descriptor;
    bool m_reached_by_descriptor;
};

// write_file_atomically of the file `name` in `folder` (a name, not a path), its messages naming it
// FOLDER/NAME as `folder` was named.
Expected<WriteResult> write_file_atomically(const OutputFolder& folder, const std::string& name,
                                            const ContentWriter& write_content, const KeyFileGuard* inputs = nullptr,
                                            Durability durability = Durability::each_file);
Expected<WriteResult> write_file_atomically(const OutputFolder& folder, const std::string& name, std::string_view content,
                                            const KeyFileGuard* inputs = nullptr,
                                            Durability durability = Durability::each_file);

// What write_file_atomically(requested, write_content, inputs) would refuse, found before anything
// of a run is written (a run of files must not stop halfway, issue 45): check_writable's problems
// and, for an existing file, its being read-only or a backup that cannot be kept (NAME.bak a
// folder, a link, read-only) — those only when the content changes, so the content is made (and
// compared, never held whole) only for such a file.
Expected<void> check_replaceable(const std::filesystem::path& requested, const ContentWriter& write_content,
                                 const KeyFileGuard* inputs);

// The barrier of Durability::at_barrier: every file written on the file system of `folder` is
// flushed to the disk (syncfs), the folders' entries with them. The problem, if any.
Expected<void> flush_file_system(const std::filesystem::path& folder);

// Whether `file` is `folder` or lies below it; both canonical (no '.', '..' or link on the way).
bool lies_within(const std::filesystem::path& file, const std::filesystem::path& folder);

// ok unless `output` is a symbolic link (or the first of a chain) whose end lies outside the
// link's own folder and the folders below it: "w/my.keys: is a symbolic link to ../victim/passwd,
// which leads out of its folder (to /home/v/victim/passwd); APCS writes through a link only to a
// file in the link's folder or below it". Every write of write_file_atomically checks it first.
Expected<void> check_link_stays_in_folder(const std::filesystem::path& output);

// NAME.ext → NAME.bak in the same folder; NAME.b01 … NAME.b99 when NAME.bak is one of `inputs`
// (the first of those that is neither an input nor an existing file; NAME.b99 when all exist;
// empty when all are inputs).
std::filesystem::path backup_path_for(const std::filesystem::path& target, const KeyFileGuard* inputs = nullptr);

} // namespace apcs
