#include "apcs/terminal/pixel_detection.h"

#include <algorithm>
#include <cstddef>

namespace apcs {

namespace {

constexpr char escape = '\x1b';

// The numbers of a CSI's parameter bytes "n;n;…" (an empty field is 0); nullopt when they hold
// anything but digits and ';' or a number too large to be a reply's.
std::optional<std::vector<int>> parameter_numbers(std::string_view parameters)
{
    std::vector<int> numbers{0};
    for (const char c : parameters) {
        if (c == ';') {
            numbers.push_back(0);
        } else if (c >= '0' && c <= '9') {
            if (numbers.back() > 99999)
                return std::nullopt;
            numbers.back() = numbers.back() * 10 + (c - '0');
        } else {
            return std::nullopt;
        }
    }
    return numbers;
}

// How a CSI that starts at an ESC [ ends: whole (`end` is the index after its final byte), cut
// short by the end of the bytes, or broken by a byte no CSI holds (at `end`).
struct CsiEnd {
    enum class Kind { whole, cut_short, broken } kind;
    std::size_t end;
};

CsiEnd csi_end(std::string_view bytes, std::size_t at)
{
    for (std::size_t i = at + 2; i < bytes.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(bytes[i]);
        if (c >= 0x40 && c <= 0x7e)
            return {CsiEnd::Kind::whole, i + 1};
        if (c < 0x20 || c > 0x3f)
            return {CsiEnd::Kind::broken, i};
    }
    return {CsiEnd::Kind::cut_short, bytes.size()};
}

// A whole CSI sequence: a reply it is, or another sequence (a key's) for `other`.
void read_csi(std::string_view sequence, TerminalReplies& replies)
{
    const char final_byte = sequence.back();
    const std::string_view parameters = sequence.substr(2, sequence.size() - 3);
    if (!parameters.empty() && parameters.front() == '?') {
        const auto numbers = parameter_numbers(parameters.substr(1));
        if (numbers && final_byte == 'c') {
            replies.device_attributes = *numbers;
            return;
        }
        // XTSMGRAPHICS' answer for sixel geometry: item 2; status 0 (success) gives the size.
        if (numbers && final_byte == 'S' && !numbers->empty() && (*numbers)[0] == 2) {
            if (numbers->size() == 4 && (*numbers)[1] == 0 && (*numbers)[2] > 0 && (*numbers)[3] > 0)
                replies.sixel_limit = PictureLimit{(*numbers)[2], (*numbers)[3]};
            return;
        }
    }
    if (final_byte == 't') {
        const auto numbers = parameter_numbers(parameters);
        if (numbers && numbers->size() == 3 && (*numbers)[0] == 6 && (*numbers)[1] > 0 && (*numbers)[2] > 0) {
            replies.cell = CellPixels{(*numbers)[2], (*numbers)[1]};
            return;
        }
    }
    replies.other += sequence;
}

// The text of an APC string (between ESC _ and ESC \): the kitty reply to our query, or dropped.
void read_apc(std::string_view text, TerminalReplies& replies)
{
    if (text.empty() || text.front() != 'G')
        return;
    const std::size_t semicolon = text.find(';');
    const std::string_view keys = text.substr(1, semicolon == std::string_view::npos ? std::string_view::npos : semicolon - 1);
    const std::string_view message = semicolon == std::string_view::npos ? std::string_view{} : text.substr(semicolon + 1);
    const std::string id_key = "i=" + std::to_string(kitty_query_id);
    bool ours = false;
    for (std::size_t start = 0; start <= keys.size();) {
        const std::size_t comma = std::min(keys.find(',', start), keys.size());
        ours = ours || keys.substr(start, comma - start) == id_key;
        start = comma + 1;
    }
    if (ours)
        replies.kitty = message == "OK" ? KittyAnswer::accepted : KittyAnswer::refused;
}

} // namespace

TerminalReplies read_terminal_replies(std::string_view bytes)
{
    TerminalReplies replies;
    std::size_t at = 0;
    while (at < bytes.size()) {
        if (bytes[at] != escape || at + 1 == bytes.size()) {
            // A lone Esc at the very end may begin a reply still on its way: neither.
            if (bytes[at] != escape)
                replies.other += bytes[at];
            ++at;
            continue;
        }
        if (bytes[at + 1] == '[') {
            const CsiEnd end = csi_end(bytes, at);
            if (end.kind == CsiEnd::Kind::cut_short)
                break; // left out
            if (end.kind == CsiEnd::Kind::broken) {
                // No reply: the bytes go back as keys, and the byte that broke it is read anew.
                replies.other += bytes.substr(at, end.end - at);
                at = end.end;
                continue;
            }
            read_csi(bytes.substr(at, end.end - at), replies);
            at = end.end;
            continue;
        }
        if (bytes[at + 1] == '_') {
            const std::size_t terminator = bytes.find("\x1b\\", at + 2);
            if (terminator == std::string_view::npos)
                break; // cut short: left out
            read_apc(bytes.substr(at + 2, terminator - at - 2), replies);
            at = terminator + 2;
            continue;
        }
        replies.other += bytes[at];
        ++at;
    }
    return replies;
}

bool attributes_have_sixel(const std::vector<int>& attributes)
{
    return attributes.size() > 1 && std::find(attributes.begin() + 1, attributes.end(), 4) != attributes.end();
}

std::optional<std::string> multiplexer_around(const char* tmux, const char* sty, const char* term)
{
    const auto set = [](const char* value) { return value != nullptr && *value != '\0'; };
    const std::string_view term_name = term == nullptr ? std::string_view{} : std::string_view(term);
    if (set(tmux) || term_name.starts_with("tmux"))
        return "tmux";
    if (set(sty) || term_name.starts_with("screen"))
        return "screen";
    return std::nullopt;
}

std::optional<PixelDecision> decide_before_asking(PixelChoice choice, const std::optional<std::string>& multiplexer)
{
    if (choice == PixelChoice::off)
        return PixelDecision{std::nullopt, {}};
    if (multiplexer)
        return PixelDecision{std::nullopt, "pixels off: " + *multiplexer +
                                               " passes no sixel or kitty pictures; run apcs outside it"};
    return std::nullopt;
}

bool asks_kitty(PixelChoice choice) { return choice == PixelChoice::automatic || choice == PixelChoice::kitty; }

PixelDecision decide_protocol(PixelChoice choice, const TerminalReplies& replies)
{
    const bool sixel = replies.device_attributes && attributes_have_sixel(*replies.device_attributes);
    const bool kitty = replies.kitty == KittyAnswer::accepted;
    switch (choice) {
    case PixelChoice::off:
        return {};
    case PixelChoice::kitty:
        if (kitty)
            return {TerminalPictureProtocol::kitty, {}};
        if (replies.kitty == KittyAnswer::refused)
            return {std::nullopt, "pixels off: the terminal refused the kitty graphics query"};
        break;
    case PixelChoice::sixel:
        if (sixel)
            return {TerminalPictureProtocol::sixel, {}};
        break;
    case PixelChoice::automatic:
        if (kitty)
            return {TerminalPictureProtocol::kitty, {}};
        if (sixel)
            return {TerminalPictureProtocol::sixel, {}};
        break;
    }
    if (!replies.device_attributes)
        return {std::nullopt, "pixels off: no answer to device attributes within 100 ms"};
    if (choice == PixelChoice::kitty)
        return {std::nullopt, "pixels off: no answer to the kitty graphics query within 100 ms"};
    if (choice == PixelChoice::sixel)
        return {std::nullopt, "pixels off: no sixel (4) in the terminal's attributes (xterm: -ti vt340)"};
    return {std::nullopt, "pixels off: no sixel or kitty graphics in this terminal (xterm: -ti vt340)"};
}

std::optional<CellPixels> cell_from_window(int pixel_width, int pixel_height, int columns, int rows)
{
    if (pixel_width <= 0 || pixel_height <= 0 || columns <= 0 || rows <= 0 || pixel_width < columns ||
        pixel_height < rows)
        return std::nullopt;
    return CellPixels{pixel_width / columns, pixel_height / rows};
}

} // namespace apcs
