#pragma once

#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/screens/program_screen.h"

#include <string>
#include <string_view>

namespace apcs {

// A handout (--handout DIR, SPEC §3) holds, per caption of a key script, the screen a paced replay
// shows it over: NN-STEP.png and NN-STEP.txt, NN the caption's number from 01 (two digits, three
// past 99), STEP the caption's short name.

// The most characters of a caption's short name.
inline constexpr std::size_t max_step_name_length = 32;

// A caption's short name, for file names that sort and print well: its ASCII letters (lowercased)
// and digits, every run of anything else one '-', none at either end, cut to max_step_name_length
// at the last '-' that fits (a single longer word is cut where it reaches the limit). A caption
// with no letter or digit is "caption". "W opens the waypoint editor; I inserts a control point"
// is "w-opens-the-waypoint-editor-i".
std::string handout_step_name(std::string_view caption);

// "NN-STEP" for caption `number` (1, 2, …) of `count`: the handout's file names less .png and
// .txt. The number has two digits, or as many as `count` has, so that the pages of one handout
// sort in their order by name (099 before 100).
std::string handout_file_stem(int number, std::size_t count, std::string_view caption);

// Whether `name` is a page of a handout: NN-STEP.png or NN-STEP.txt as handout_file_stem makes them.
bool is_handout_page_name(std::string_view name);

// Whether `name` is one of the files a handout's folder holds: index.html, a page, what was kept of
// either when it was replaced (index.bak, NN-STEP.bak, .b01 ... .b99), or a hidden temporary file
// of one (.NAME.XXXXXX) that a crash of the machine left. A handout is written only into a folder
// that holds nothing else (HandoutWriter::open), so that no file of the user's is replaced.
bool is_handout_file_name(std::string_view name);

// The 80x24 screen as text, one line a row, trailing blanks removed, each line ending in a newline:
// graphics mode mapped to characters in `glyphs`, the console as it is. What headless replays print
// for each step and what the lessons' golden screens hold.
std::string screen_text(const ProgramScreen& screen, GlyphSet glyphs);

// Whether `screen` (the session's, no caption laid on) is an empty prompt: the text console showing
// a question and nothing else, its answer not begun (a row holding only the cursor '_' counts as
// empty). A handout has no page of it: it says nothing a caption could be about (issue 42: the
// opening KEY1 prompt was page 01).
bool is_empty_prompt(const ProgramScreen& screen);

// The screen as the Hercules card showed it: graphics mode's picture, or the text console's rows
// drawn in the 9x14 font on an empty raster (80 columns fill its 720 pixels, 24 rows its top 336).
GraphicsScreen screen_picture(const ProgramScreen& screen);

} // namespace apcs
