#pragma once

// The steps of run_session_command kept in files of their own: the glyphs the screens are drawn in
// (session_glyphs.cpp), and the files the session read, which neither a recording nor a handout may
// replace, with --record's target checked and its keys written (session_record.cpp).
#include "apcs/cli/options.h"
#include "apcs/base/exit_status.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/formats/key_recording.h"
#include "apcs/raster/glyph_mapper.h"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// The glyphs the screens are drawn in: ascii for a replay without a terminal unless --glyphs says
// otherwise; on a terminal, what it can show.
Expected<GlyphSet> session_glyphs(GlyphSet asked, bool headless);

// --record checked before the session runs: "-" is standard output, which must not be the
// terminal nor the session's screen; a file is neither one the session uses nor unwritable.
std::optional<ExitStatus> refuse_record_target(const CommonOptions& options, std::string_view script_text,
                                               const std::filesystem::path& folder, bool headless,
                                               std::ostream& err);

// The files the session read that a recording (or its backup) must never replace: the key script
// and the key frames as typed at the KEY prompts.
KeyFileGuard files_read(const CommonOptions& options, const std::vector<std::string>& key_files,
                        const std::filesystem::path& folder);

// --record FILE: the keys handled, as a script with the options that shaped them; "-" writes
// them to `out`. The target was checked before the session (refuse_record_target) and guarded
// during it, so the session wrote nothing there; a KEY answer typed live may still have named it,
// and then it is a key file.
std::optional<ExitStatus> record_keys(const CommonOptions& options, const KeyFileGuard& read, KeyRecording& recorded,
                                      std::ostream& out, std::ostream& err);

} // namespace apcs
