#pragma once

#include "apcs/raster/pixel_picture.h"
#include "apcs/raster/terminal_picture.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// The questions --pixels asks the terminal (SPEC §7.2.1). Pure: what is asked, how the answers
// read and what they decide; the Terminal writes and reads the bytes (without <curses.h> here, so
// that the tests take this file without ncurses).
// Primary device attributes: every terminal of the VT100 line answers ESC [ ? class ; attr … c.
inline constexpr std::string_view device_attributes_query = "\x1b[c";
// The kitty graphics protocol's query: a terminal that has it answers ESC _ G i=31 ; OK ESC \ and
// draws nothing; one without it ignores the APC string.
inline constexpr std::string_view kitty_graphics_query = "\x1b_Gi=31,s=1,v=1,a=q,t=d,f=24;AAAA\x1b\\";
inline constexpr int kitty_query_id = 31;
// The largest sixel picture the terminal shows now (xterm's XTSMGRAPHICS, read the current sixel
// geometry): ESC [ ? 2 ; 0 ; width ; height S. Sent before the device attributes, whose answer ends
// the wait: a terminal that does not know it ignores it.
inline constexpr std::string_view sixel_limit_query = "\x1b[?2;1;0S";
// The cell size in pixels (xterm's window operation 16): ESC [ 6 ; height ; width t.
inline constexpr std::string_view cell_size_query = "\x1b[16t";
// How long each question waits for its answer; a terminal silent that long counts as no answer.
inline constexpr int pixel_reply_limit_ms = 100;

enum class KittyAnswer : unsigned char { none, accepted, refused };

// What the terminal answered, read from the bytes that came after the questions.
struct TerminalReplies {
    // The numbers of the device attributes reply, its class (62, 63, 64, …) first.
    std::optional<std::vector<int>> device_attributes;
    KittyAnswer kitty = KittyAnswer::none;
    std::optional<CellPixels> cell; // from ESC [ 6 ; height ; width t
    std::optional<PictureLimit> sixel_limit; // from ESC [ ? 2 ; 0 ; width ; height S
    // What was no reply, in order: keys typed meanwhile (whole escape sequences of keys included),
    // given back to the keyboard. A reply cut short at the end is neither.
    std::string other;
};

// The replies in `bytes`: device attributes (ESC [ ? n ; … c), the kitty graphics reply to the
// query of id 31 (ESC _ G i=31 ; OK ESC \ is ok, any other message refused; other APC strings are
// dropped), the cell size (ESC [ 6 ; h ; w t, both positive), the sixel limit (ESC [ ? 2 ; 0 ; w ; h
// S: status 0, both positive; another status is no limit known). Anything else goes to `other`.
TerminalReplies read_terminal_replies(std::string_view bytes);

// Whether device attributes name sixel graphics: a 4 among the attributes after the class.
bool attributes_have_sixel(const std::vector<int>& attributes);

// "tmux" or "screen" when the program runs inside one (TMUX or STY set and not empty; TERM
// screen… or tmux…), which pass no sixel or kitty pictures (tmux 3.3, screen 4.9): nullopt
// otherwise. Each argument is the environment variable's value, null when unset.
std::optional<std::string> multiplexer_around(const char* tmux, const char* sty, const char* term);

// What the session shows: a protocol, or why not (one line for the message line: "pixels off: …").
struct PixelDecision {
    std::optional<TerminalPictureProtocol> protocol;
    std::string why_not;
};

// Before any question: off stays off; inside a multiplexer every choice falls back (`auto` never
// tries, and an explicit sixel or kitty cannot pass). nullopt: ask the terminal.
std::optional<PixelDecision> decide_before_asking(PixelChoice choice, const std::optional<std::string>& multiplexer);

// Whether `choice` asks the kitty query after the device attributes (auto and kitty do).
bool asks_kitty(PixelChoice choice);

// After the device attributes (and the kitty query, if asked): kitty where asked for or, with
// auto, where the terminal answered OK; else sixel where the attributes hold 4; else why not.
PixelDecision decide_protocol(PixelChoice choice, const TerminalReplies& replies);

// The cell size from TIOCGWINSZ's window size in pixels and cells; nullopt where the terminal
// leaves the pixel size 0 (many do), or any size is not positive.
std::optional<CellPixels> cell_from_window(int pixel_width, int pixel_height, int columns, int rows);

// The fallback lines of what the Terminal finds after deciding a protocol.
inline constexpr std::string_view no_cell_size_line =
    "pixels off: the terminal gave no cell size in pixels (TIOCGWINSZ, CSI 16 t)";
inline constexpr std::string_view encoding_failed_line = "pixels off: libchafa could not encode the picture";

} // namespace apcs
