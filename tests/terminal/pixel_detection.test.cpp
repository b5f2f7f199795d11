#include "apcs/terminal/pixel_detection.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;

namespace {

// Replies as terminals send them.
const std::string xterm_vt340_attributes = "\x1b[?63;1;2;4;6;9;15;16;22;28c";
const std::string xterm_attributes = "\x1b[?64;1;2;6;9;15;16;17;18;21;22;28c";
const std::string kitty_attributes = "\x1b[?62;c";
const std::string kitty_ok = "\x1b_Gi=31;OK\x1b\\";
const std::string kitty_error = "\x1b_Gi=31;EINVAL:Zero width/height not allowed\x1b\\";

} // namespace

TEST_CASE("device attributes with a 4 after the class mean sixel", "[terminal][pixels]")
{
    const TerminalReplies replies = read_terminal_replies(xterm_vt340_attributes);
    REQUIRE(replies.device_attributes);
    CHECK(replies.device_attributes->front() == 63);
    CHECK(attributes_have_sixel(*replies.device_attributes));
    CHECK(replies.other.empty());
}

TEST_CASE("device attributes without a 4, or with 4 only as a longer number, mean no sixel", "[terminal][pixels]")
{
    const TerminalReplies xterm = read_terminal_replies(xterm_attributes);
    REQUIRE(xterm.device_attributes);
    CHECK_FALSE(attributes_have_sixel(*xterm.device_attributes));
    const TerminalReplies kitty = read_terminal_replies(kitty_attributes);
    REQUIRE(kitty.device_attributes);
    CHECK(*kitty.device_attributes == std::vector<int>{62, 0});
    CHECK_FALSE(attributes_have_sixel(*kitty.device_attributes));
    CHECK_FALSE(attributes_have_sixel({64, 14, 44}));
    CHECK_FALSE(attributes_have_sixel({4}));
}

TEST_CASE("the kitty reply to query 31: OK accepts, an error refuses, another id is not ours", "[terminal][pixels]")
{
    CHECK(read_terminal_replies(kitty_ok + kitty_attributes).kitty == KittyAnswer::accepted);
    CHECK(read_terminal_replies(kitty_error + kitty_attributes).kitty == KittyAnswer::refused);
    CHECK(read_terminal_replies("\x1b_Gi=7;OK\x1b\\").kitty == KittyAnswer::none);
    CHECK(read_terminal_replies("\x1b_Gi=310;OK\x1b\\").kitty == KittyAnswer::none);
    CHECK(read_terminal_replies("\x1b_Gq=2,i=31;OK\x1b\\").kitty == KittyAnswer::accepted);
    // Another APC string is dropped, neither a reply nor keys.
    const TerminalReplies other = read_terminal_replies("\x1b_Xhello\x1b\\");
    CHECK(other.kitty == KittyAnswer::none);
    CHECK(other.other.empty());
}

TEST_CASE("the cell size report CSI 6 height width t gives the cell in pixels", "[terminal][pixels]")
{
    const TerminalReplies replies = read_terminal_replies("\x1b[6;15;9t");
    REQUIRE(replies.cell);
    CHECK(*replies.cell == CellPixels{9, 15});
    // Another window report, or a size of 0, is no cell size.
    CHECK_FALSE(read_terminal_replies("\x1b[4;360;720t").cell);
    CHECK_FALSE(read_terminal_replies("\x1b[6;0;9t").cell);
}

TEST_CASE("the sixel limit reply gives the largest picture, another status none, and is no key", "[terminal][pixels]")
{
    // xterm -ti vt340 in a window of 1530x825 pixels: 1000 across at most.
    const TerminalReplies xterm = read_terminal_replies("\x1b[?2;0;1000;825S" + xterm_vt340_attributes);
    REQUIRE(xterm.sixel_limit);
    CHECK(*xterm.sixel_limit == PictureLimit{1000, 825});
    CHECK(xterm.device_attributes);
    CHECK(xterm.other.empty());
    // Status 3: the terminal has no such setting; item 1 (colour registers) is not the size.
    const TerminalReplies failed = read_terminal_replies("\x1b[?2;3;0S\x1b[?1;0;1024S");
    CHECK_FALSE(failed.sixel_limit);
    CHECK(failed.other == "\x1b[?1;0;1024S");
}

TEST_CASE("keys typed among the replies are kept in order, whole sequences included", "[terminal][pixels]")
{
    const TerminalReplies replies = read_terminal_replies("a" + xterm_vt340_attributes + "\x1b[Ab\x1bOP");
    REQUIRE(replies.device_attributes);
    CHECK(replies.other == "a\x1b[Ab\x1bOP");
}

TEST_CASE("garbage: a broken sequence goes back as keys, a reply cut short is neither", "[terminal][pixels]")
{
    const TerminalReplies broken = read_terminal_replies("\x1b[?6\x01x");
    CHECK_FALSE(broken.device_attributes);
    CHECK(broken.other == "\x1b[?6\x01x");
    const TerminalReplies cut = read_terminal_replies("\x1b[?63;1;2;");
    CHECK_FALSE(cut.device_attributes);
    CHECK(cut.other.empty());
    const TerminalReplies cut_apc = read_terminal_replies("\x1b_Gi=31;O");
    CHECK(cut_apc.kitty == KittyAnswer::none);
    CHECK(cut_apc.other.empty());
    const TerminalReplies letters = read_terminal_replies("\x1b[?6x;c");
    CHECK_FALSE(letters.device_attributes);
    CHECK(letters.other == "\x1b[?6x;c");
    CHECK(read_terminal_replies("\x1b[?99999999999c").other == "\x1b[?99999999999c");
    CHECK(read_terminal_replies("\x1b").other.empty());
}

TEST_CASE("tmux and screen are found by TMUX, STY or TERM", "[terminal][pixels]")
{
    CHECK(multiplexer_around("/tmp/tmux-0/default,1,0", nullptr, "xterm") == "tmux");
    CHECK(multiplexer_around(nullptr, nullptr, "tmux-256color") == "tmux");
    CHECK(multiplexer_around(nullptr, "1234.pts-0.host", "xterm") == "screen");
    CHECK(multiplexer_around(nullptr, nullptr, "screen.xterm-256color") == "screen");
    CHECK_FALSE(multiplexer_around(nullptr, nullptr, "xterm-256color"));
    CHECK_FALSE(multiplexer_around("", "", nullptr));
}

TEST_CASE("off asks nothing, and inside tmux every choice falls back with one line", "[terminal][pixels]")
{
    const std::optional<PixelDecision> off = decide_before_asking(PixelChoice::off, std::nullopt);
    REQUIRE(off);
    CHECK_FALSE(off->protocol);
    CHECK(off->why_not.empty());
    for (const PixelChoice choice : {PixelChoice::automatic, PixelChoice::sixel, PixelChoice::kitty}) {
        const std::optional<PixelDecision> tmux = decide_before_asking(choice, "tmux");
        REQUIRE(tmux);
        CHECK_FALSE(tmux->protocol);
        CHECK(tmux->why_not == "pixels off: tmux passes no sixel or kitty pictures; run apcs outside it");
        CHECK_FALSE(decide_before_asking(choice, std::nullopt));
    }
    CHECK(asks_kitty(PixelChoice::automatic));
    CHECK(asks_kitty(PixelChoice::kitty));
    CHECK_FALSE(asks_kitty(PixelChoice::sixel));
}

TEST_CASE("the protocol follows the choice and the replies, else one line says why", "[terminal][pixels]")
{
    const TerminalReplies none = read_terminal_replies(""); // no answer within 100 ms
    const TerminalReplies vt340 = read_terminal_replies(xterm_vt340_attributes);
    const TerminalReplies xterm = read_terminal_replies(xterm_attributes);
    const TerminalReplies kitty = read_terminal_replies(kitty_ok + kitty_attributes);
    const TerminalReplies refusing = read_terminal_replies(kitty_error + kitty_attributes);
    TerminalReplies both = vt340;
    both.kitty = KittyAnswer::accepted;
    struct Row {
        PixelChoice choice;
        const TerminalReplies& replies;
        std::optional<TerminalPictureProtocol> protocol;
        std::string why_not;
    };
    const std::vector<Row> table{
        {PixelChoice::sixel, vt340, TerminalPictureProtocol::sixel, ""},
        {PixelChoice::automatic, vt340, TerminalPictureProtocol::sixel, ""},
        {PixelChoice::automatic, kitty, TerminalPictureProtocol::kitty, ""},
        {PixelChoice::automatic, both, TerminalPictureProtocol::kitty, ""},
        {PixelChoice::sixel, both, TerminalPictureProtocol::sixel, ""},
        {PixelChoice::kitty, kitty, TerminalPictureProtocol::kitty, ""},
        {PixelChoice::sixel, none, std::nullopt, "pixels off: no answer to device attributes within 100 ms"},
        {PixelChoice::automatic, none, std::nullopt, "pixels off: no answer to device attributes within 100 ms"},
        {PixelChoice::sixel, xterm, std::nullopt,
         "pixels off: no sixel (4) in the terminal's attributes (xterm: -ti vt340)"},
        {PixelChoice::sixel, kitty, std::nullopt,
         "pixels off: no sixel (4) in the terminal's attributes (xterm: -ti vt340)"},
        {PixelChoice::automatic, xterm, std::nullopt,
         "pixels off: no sixel or kitty graphics in this terminal (xterm: -ti vt340)"},
        {PixelChoice::kitty, vt340, std::nullopt, "pixels off: no answer to the kitty graphics query within 100 ms"},
        {PixelChoice::kitty, refusing, std::nullopt, "pixels off: the terminal refused the kitty graphics query"},
    };
    for (const Row& row : table) {
        const PixelDecision decision = decide_protocol(row.choice, row.replies);
        CHECK(decision.protocol == row.protocol);
        CHECK(decision.why_not == row.why_not);
        // One line on an 80-column message line.
        CHECK(decision.why_not.size() <= 78);
    }
}

TEST_CASE("TIOCGWINSZ's pixels give the cell size where the terminal fills them in", "[terminal][pixels]")
{
    CHECK(cell_from_window(720, 360, 80, 24) == CellPixels{9, 15});
    CHECK(cell_from_window(1000, 500, 100, 25) == CellPixels{10, 20});
    CHECK_FALSE(cell_from_window(0, 0, 80, 24));
    CHECK_FALSE(cell_from_window(720, 0, 80, 24));
    CHECK_FALSE(cell_from_window(720, 360, 0, 24));
    CHECK_FALSE(cell_from_window(40, 360, 80, 24));
}
