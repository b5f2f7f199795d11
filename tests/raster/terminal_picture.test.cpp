#include "apcs/raster/png_encoder.h"
#include "apcs/raster/terminal_picture.h"

#include <catch2/catch.hpp>

#include <array>
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

using namespace apcs;

namespace {

// A raster with lines in every direction and a scatter that no two neighbouring rows share, so that
// a row dropped, doubled or shifted in the 1.5-row stretch changes the picture.
Bitmap test_raster()
{
    Bitmap bitmap;
    for (int y = 0; y < bitmap.height(); ++y)
        for (int x = 0; x < bitmap.width(); ++x)
            bitmap.set(x, y, (x * 7 + y * 13) % 11 == 0 || x == y || y == 200 || x == 719 || y == 0);
    return bitmap;
}

// Whether pixel (x, y) of the monitor's 720x522 picture is lit.
bool monitor_lit(const Bitmap& bitmap, int x, int y) { return bitmap.get(x, raster_row_of(y, PngShape::monitor)); }

// A sixel picture decoded (DEC STD 070's DCS … q … ST, with "#N;2;R;G;B" colours in percent):
// the colour each pixel was painted with and how many times, for a `width` x `height` picture.
struct SixelPixels {
    std::map<int, std::array<int, 3>> palette;
    std::vector<int> colour;     // -1 unpainted
    std::vector<int> paint_count;
};

// The numbers of "N;N;…" at `at`, moving `at` past them.
std::vector<int> read_numbers(const std::string& text, std::size_t& at)
{
    std::vector<int> numbers{0};
    for (; at < text.size() && (std::isdigit(static_cast<unsigned char>(text[at])) || text[at] == ';'); ++at)
        if (text[at] == ';')
            numbers.push_back(0);
        else
            numbers.back() = numbers.back() * 10 + (text[at] - '0');
    return numbers;
}

SixelPixels decode_sixel(const std::string& text, int width, int height)
{
    SixelPixels decoded{{}, std::vector<int>(static_cast<std::size_t>(width * height), -1),
                        std::vector<int>(static_cast<std::size_t>(width * height), 0)};
    std::size_t at = text.find('q') + 1;
    int x = 0, band = 0, colour = 0;
    while (at < text.size() && text[at] != '\x1b') {
        const char code = text[at++];
        if (code == '"') {
            read_numbers(text, at);
        } else if (code == '#') {
            const std::vector<int> numbers = read_numbers(text, at);
            colour = numbers[0];
            if (numbers.size() == 5)
                decoded.palette[colour] = {numbers[2], numbers[3], numbers[4]};
        } else if (code == '$' || code == '-') {
            x = 0;
            band += code == '-' ? 1 : 0;
        } else {
            int repeat = 1;
            char sixel = code;
            if (code == '!') {
                repeat = read_numbers(text, at)[0];
                sixel = text[at++];
            }
            for (int step = 0; step < repeat; ++step, ++x)
                for (int bit = 0; bit < 6; ++bit)
                    if (((sixel - '?') >> bit & 1) != 0 && x < width && band * 6 + bit < height) {
                        const auto pixel = static_cast<std::size_t>((band * 6 + bit) * width + x);
                        decoded.colour[pixel] = colour;
                        ++decoded.paint_count[pixel];
                    }
        }
    }
    return decoded;
}

std::optional<std::vector<std::uint8_t>> decode_base64(const std::string& text)
{
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<std::uint8_t> bytes;
    unsigned bits = 0;
    int bit_count = 0;
    for (const char symbol : text) {
        if (symbol == '=')
            break;
        const std::size_t value = alphabet.find(symbol);
        if (value == std::string::npos)
            return std::nullopt;
        bits = (bits << 6 | static_cast<unsigned>(value)) & 0xffffffu;
        bit_count += 6;
        if (bit_count >= 8) {
            bit_count -= 8;
            bytes.push_back(static_cast<std::uint8_t>(bits >> bit_count & 0xffu));
        }
    }
    return bytes;
}

// A kitty picture's commands: each APC "ESC _ G keys ; payload ESC \", its keys and payload.
struct KittyCommand {
    std::string keys;
    std::string payload;
};

std::vector<KittyCommand> kitty_commands(const std::string& text)
{
    std::vector<KittyCommand> commands;
    for (std::size_t at = text.find("\x1b_G"); at != std::string::npos; at = text.find("\x1b_G", at)) {
        const std::size_t end = text.find("\x1b\\", at);
        REQUIRE(end != std::string::npos);
        const std::string body = text.substr(at + 3, end - at - 3);
        const std::size_t semicolon = body.find(';');
        commands.push_back({body.substr(0, semicolon),
                            semicolon == std::string::npos ? std::string() : body.substr(semicolon + 1)});
        at = end + 2;
    }
    return commands;
}

// The pixels the commands carry. Each chunk is whole base64 (padded where it ends), so each is
// decoded on its own.
std::vector<std::uint8_t> kitty_payload(const std::vector<KittyCommand>& commands)
{
    std::vector<std::uint8_t> rgba;
    for (const KittyCommand& command : commands) {
        const std::optional<std::vector<std::uint8_t>> chunk = decode_base64(command.payload);
        REQUIRE(chunk);
        rgba.insert(rgba.end(), chunk->begin(), chunk->end());
    }
    return rgba;
}

// The picture of `bitmap` in `protocol`, which must encode and end with the string terminator and
// a newline.
std::string encoded(const Bitmap& bitmap, TerminalPictureProtocol protocol)
{
    const Expected<std::string> picture = encode_terminal_picture(bitmap, protocol);
    REQUIRE(picture);
    REQUIRE(picture->ends_with("\x1b\\\n"));
    return *picture;
}

// The pixels of the monitor's 720x522 picture of `bitmap` for which `right(x, y, lit)` is false.
std::size_t wrong_pixels(const Bitmap& bitmap, const std::function<bool(std::size_t, bool)>& right)
{
    std::size_t wrong = 0;
    for (int y = 0; y < 522; ++y)
        for (int x = 0; x < 720; ++x)
            wrong += right(static_cast<std::size_t>(y * 720 + x), monitor_lit(bitmap, x, y)) ? 0u : 1u;
    return wrong;
}

} // namespace

TEST_CASE("a sixel picture paints every pixel of the monitor's 720x522 picture once, lit white, the rest black",
          "[raster][sixel]")
{
    const Bitmap bitmap = test_raster();
    const std::string sixel = encoded(bitmap, TerminalPictureProtocol::sixel);
    REQUIRE(sixel.starts_with("\x1bP"));
    REQUIRE(sixel.find("\"1;1;720;522") != std::string::npos);
    const SixelPixels decoded = decode_sixel(sixel, 720, 522);
    REQUIRE(wrong_pixels(bitmap, [&decoded](std::size_t pixel, bool lit) {
                const std::array<int, 3> wanted = lit ? std::array{100, 100, 100} : std::array{0, 0, 0};
                return decoded.paint_count[pixel] == 1 && decoded.palette.contains(decoded.colour[pixel]) &&
                       decoded.palette.at(decoded.colour[pixel]) == wanted;
            }) == 0);
}

TEST_CASE("a kitty picture's base64 chunks decode to the monitor's 720x522 picture as RGBA, on 80x29 cells",
          "[raster][kitty]")
{
    const Bitmap bitmap = test_raster();
    const std::vector<KittyCommand> commands = kitty_commands(encoded(bitmap, TerminalPictureProtocol::kitty));
    REQUIRE(commands.size() > 1);
    CHECK(commands.front().keys.find("a=T,f=32,s=720,v=522,c=80,r=29") != std::string::npos);
    CHECK(commands.back().keys.find("m=0") != std::string::npos);
    const std::vector<std::uint8_t> rgba = kitty_payload(commands);
    REQUIRE(rgba.size() == 720u * 522u * 4u);
    REQUIRE(wrong_pixels(bitmap, [&rgba](std::size_t pixel, bool lit) {
                const std::uint8_t level = lit ? 255 : 0;
                const std::uint8_t* rgba_pixel = rgba.data() + pixel * 4;
                return rgba_pixel[0] == level && rgba_pixel[1] == level && rgba_pixel[2] == level &&
                       rgba_pixel[3] == 255;
            }) == 0);
}

namespace {

// A picture of 3x2 cells of 9x15 pixels: a diagonal, a frame and a scatter, so that a band taken
// from the wrong rows, or scaled, shows.
Bitmap band_test_picture()
{
    Bitmap picture(27, 30);
    for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x)
            picture.set(x, y, x == y || x == 0 || y == 29 || (x * 5 + y * 3) % 7 == 0);
    return picture;
}

} // namespace

TEST_CASE("a sixel band is the picture's cell rows of the band, unscaled, each pixel painted once, then transparent rows to a multiple of 6", "[raster][sixel][pixels]")
{
    const Bitmap picture = band_test_picture();
    const CellPixels cell{9, 15};
    const Expected<std::string> band = encode_picture_band(picture, {1, 2}, cell, TerminalPictureProtocol::sixel);
    REQUIRE(band);
    REQUIRE(band->starts_with("\x1bP"));
    REQUIRE(band->ends_with("\x1b\\"));
    // 15 rows go out as 18, the sixels' multiple of 6; rows 15-17 are left unpainted. White is
    // register 0 and black 1, and no other register is defined.
    CHECK(band->find("\"1;1;27;18#0;2;100;100;100#1;2;0;0;0#") != std::string::npos);
    CHECK(band->find("#2;") == std::string::npos);
    const SixelPixels decoded = decode_sixel(*band, 27, 18);
    int wrong = 0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 27; ++x) {
            const auto pixel = static_cast<std::size_t>(y * 27 + x);
            if (y >= 15) {
                wrong += decoded.paint_count[pixel] == 0 ? 0 : 1;
                continue;
            }
            const std::array<int, 3> wanted = picture.get(x, 15 + y) ? std::array{100, 100, 100} : std::array{0, 0, 0};
            wrong += decoded.paint_count[pixel] == 1 && decoded.palette.contains(decoded.colour[pixel]) &&
                             decoded.palette.at(decoded.colour[pixel]) == wanted
                         ? 0
                         : 1;
        }
    CHECK(wrong == 0);
}

TEST_CASE("a kitty band decodes to the band's RGBA pixels, placed on the band's cells", "[raster][kitty][pixels]")
{
    const Bitmap picture = band_test_picture();
    const Expected<std::string> band = encode_picture_band(picture, {0, 2}, {9, 15}, TerminalPictureProtocol::kitty);
    REQUIRE(band);
    const std::vector<KittyCommand> commands = kitty_commands(*band);
    REQUIRE_FALSE(commands.empty());
    CHECK(commands.front().keys.find("a=T,f=32,s=27,v=30,c=3,r=2") != std::string::npos);
    const std::vector<std::uint8_t> rgba = kitty_payload(commands);
    REQUIRE(rgba.size() == 27u * 30u * 4u);
    int wrong = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 27; ++x)
            wrong += rgba[static_cast<std::size_t>(y * 27 + x) * 4] == (picture.get(x, y) ? 255 : 0) ? 0 : 1;
    CHECK(wrong == 0);
}

TEST_CASE("a band outside the picture, empty or of no cell height is refused", "[raster][pixels]")
{
    const Bitmap picture = band_test_picture();
    CHECK_FALSE(encode_picture_band(picture, {1, 3}, {9, 15}, TerminalPictureProtocol::sixel));
    CHECK_FALSE(encode_picture_band(picture, {1, 1}, {9, 15}, TerminalPictureProtocol::sixel));
    CHECK_FALSE(encode_picture_band(picture, {-1, 1}, {9, 15}, TerminalPictureProtocol::sixel));
    CHECK_FALSE(encode_picture_band(picture, {0, 1}, {9, 0}, TerminalPictureProtocol::kitty));
    // The reason is kept for the notice the session shows when pixels go off.
    const Expected<std::string> outside = encode_picture_band(picture, {1, 3}, {9, 15}, TerminalPictureProtocol::sixel);
    REQUIRE_FALSE(outside);
    CHECK(outside.error().to_string() ==
          "libchafa: cell rows 1 to 3 of cells 9x15 are not within a picture of " +
              std::to_string(picture.width()) + "x" + std::to_string(picture.height()) + " pixels");
}
