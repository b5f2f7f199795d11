// The files the session read, which neither a recording nor a handout may replace; --record's
// target checked before the session runs, and its keys written after it.
#include "session_parts.h"

#include "report.h"
#include "apcs/cli/script_options.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/text_fields.h"

#include <algorithm>
#include <cctype>
#include <unistd.h>

namespace apcs {

namespace {

// ani1.dat …, inb001.dat …: names the session writes frames under, whatever the answers (any case).
bool is_session_frame_name(const std::filesystem::path& target)
{
    std::string name = target.filename().string();
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    return name.ends_with(".dat") && (name.starts_with("ani") || name.starts_with("inb"));
}

// The names the script's TEXT lines type (SPEC §3: line ends LF, CRLF or CR), cut at spaces.
std::vector<std::string> typed_names(std::string_view script_text)
{
    std::vector<std::string> names;
    constexpr std::string_view text_token = "TEXT ";
    while (!script_text.empty()) {
        const std::size_t end = std::min(script_text.find_first_of("\r\n"), script_text.size());
        std::string_view line = script_text.substr(0, end);
        script_text.remove_prefix(std::min(end + 1, script_text.size()));
        if (!line.starts_with(text_token))
            continue;
        line.remove_prefix(text_token.size());
        while (!line.empty()) {
            const std::size_t space = std::min(line.find(' '), line.size());
            if (space > 0)
                names.emplace_back(line.substr(0, space));
            line.remove_prefix(std::min(space + 1, line.size()));
        }
    }
    return names;
}

// Why --record may not write its target: a file the session reads or writes (the key script,
// the example key files, apcs.log, a frame file, a name the script types), found at start so the
// session never runs for a recording that would replace one; nullopt for none.
std::optional<std::string> record_target_clash(const CommonOptions& options, std::string_view script_text,
                                               const std::filesystem::path& folder)
{
    const std::filesystem::path& target = *options.record;
    KeyFileGuard script_file;
    if (options.keys && *options.keys != "-")
        script_file.protect(*options.keys);
    const std::string never = "; --record never writes over it";
    if (script_file.guards(target))
        return "is the key script of this session (--keys)" + never;
    if (is_session_frame_name(target))
        return "is a name the session writes its frames under (ani*.dat, inb*.dat)" + never;
    const auto names = [&](const std::string& name) {
        KeyFileGuard used;
        used.protect(folder / name);
        return used.guards(target);
    };
    if (names("apcs.log"))
        return "is the session's log" + never;
    if (names("key1.dat") || names("key2.dat"))
        return std::string("is a key file; key files are never written (the session did not start)");
    for (const std::string& name : typed_names(script_text))
        if (names(name))
            return "is a file the key script names at a prompt (" + name + ")" + never;
    return std::nullopt;
}

} // namespace

std::optional<ExitStatus> refuse_record_target(const CommonOptions& options, std::string_view script_text,
                                               const std::filesystem::path& folder, bool headless,
                                               std::ostream& err)
{
    if (!options.record)
        return std::nullopt;
    if (*options.record == "-") {
        if (::isatty(STDOUT_FILENO)) {
            err << "apcs: --record -: standard output is a terminal; redirect it, or give --record FILE\n";
            return ExitStatus::bad_usage;
        }
        if (!headless) {
            err << "apcs: --record -: the session's screen is standard output; give --record FILE\n";
            return ExitStatus::bad_usage;
        }
        return std::nullopt;
    }
    if (const std::optional<std::string> clash = record_target_clash(options, script_text, folder))
        return report_bad_input({options.record->string(), 0, *clash}, err);
    if (const Expected<void> writable = check_writable(*options.record); !writable)
        return report_bad_input(writable.error(), err);
    return std::nullopt;
}

KeyFileGuard files_read(const CommonOptions& options, const std::vector<std::string>& key_files,
                        const std::filesystem::path& folder)
{
    KeyFileGuard read;
    if (options.keys && *options.keys != "-")
        read.protect(*options.keys);
    for (const std::string& key : key_files)
        read.protect(folder / key);
    return read;
}

std::optional<ExitStatus> record_keys(const CommonOptions& options, const KeyFileGuard& read, KeyRecording& recorded,
                                      std::ostream& out, std::ostream& err)
{
    if (!options.record)
        return std::nullopt;
    recorded.add_options(carried_options_words(options));
    if (*options.record == "-") {
        out << recorded.text();
        return std::nullopt;
    }
    if (read.guards(*options.record))
        return report_bad_input({options.record->string(), 0,
                                 "is a key file; key files are never written (the keystrokes were not recorded)"},
                                err);
    const Expected<WriteResult> written = write_file_atomically(*options.record, recorded.text(), &read);
    if (!written)
        return report_bad_input(written.error(), err);
    return std::nullopt;
}

} // namespace apcs
