// Build-time converter: a PSF1 console font (e.g. Lat15-VGA14.psf of Debian's console-setup-linux,
// gunzipped) to a C++ table of {code point, rows} for the raster's text. Usage:
//   psf_to_cpp FONT.psf OUT.inc
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <vector>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: psf_to_cpp FONT.psf OUT.inc\n";
        return 2;
    }
    std::ifstream input(argv[1], std::ios::binary);
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>()};
    if (bytes.size() < 4 || bytes[0] != 0x36 || bytes[1] != 0x04) {
        std::cerr << argv[1] << ": not a PSF1 font\n";
        return 1;
    }
    const unsigned mode = bytes[2];
    const unsigned height = bytes[3];
    const std::size_t glyph_count = (mode & 0x01) ? 512 : 256;
    const std::size_t table_start = 4 + glyph_count * height;
    if (bytes.size() < table_start || !(mode & 0x02)) {
        std::cerr << argv[1] << ": expected a PSF1 font with a Unicode table\n";
        return 1;
    }
    // Unicode table: per glyph, 16-bit code points up to 0xFFFF (0xFFFE starts sequences).
    std::map<std::uint32_t, std::size_t> glyph_of;
    std::size_t glyph = 0;
    bool in_sequence = false;
    for (std::size_t at = table_start; at + 1 < bytes.size() && glyph < glyph_count; at += 2) {
        const std::uint32_t value = bytes[at] | (bytes[at + 1] << 8);
        if (value == 0xFFFF) {
            ++glyph;
            in_sequence = false;
        } else if (value == 0xFFFE) {
            in_sequence = true;
        } else if (!in_sequence) {
            glyph_of.emplace(value, glyph);
        }
    }
    std::ofstream output(argv[2]);
    if (!output) {
        std::cerr << argv[2] << ": cannot write\n";
        return 1;
    }
    output << "// Generated from " << argv[1] << " by tools/psf_to_cpp; do not edit.\n";
    output << "inline constexpr int font_glyph_rows = " << height << ";\n";
    output << "inline constexpr FontGlyph font_glyphs[] = {\n";
    for (const auto& [code_point, index] : glyph_of) {
        output << "    {0x" << std::hex << code_point << std::dec << ", {";
        for (unsigned row = 0; row < height; ++row)
            output << (row ? "," : "") << unsigned(bytes[4 + index * height + row]);
        output << "}},\n";
    }
    output << "};\n";
    return output.good() ? 0 : 1;
}
