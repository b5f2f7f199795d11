#include "apcs/formats/script_input.h"

#include "apcs/formats/text_fields.h"

#include <charconv>
#include <cstdio>
#include <optional>
#include <vector>

namespace apcs {

namespace {

constexpr std::size_t crc32_digits = 8;

// The CRC-32 of 8 hex digits (any case), or why not.
std::optional<std::uint32_t> crc32_of(std::string_view digits)
{
    if (digits.size() != crc32_digits)
        return std::nullopt;
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value, 16);
    if (error != std::errc() || end != digits.data() + digits.size())
        return std::nullopt;
    return value;
}

// An input's name is looked for in the work folder only: a folder part would reach outside the
// exercise's copy, which is what the check guards.
bool is_plain_file_name(std::string_view name)
{
    return name != "." && name != ".." && name.find('/') == std::string_view::npos;
}

} // namespace

Expected<ScriptInput> parse_input_line(std::string_view words, const std::string& file_name, int line_number)
{
    const std::string_view line = words.substr(0, words.find(';'));
    std::vector<std::string_view> fields;
    for_each_field(line, [&fields](std::string_view field) { fields.push_back(field); });
    const auto refused = [&](const std::string& reason) {
        return Diagnostic{file_name, line_number,
                          "expected INPUT NAME [CRC32 XXXXXXXX] (" + reason + "); found 'INPUT " +
                              std::string(line.substr(0, line.find_last_not_of(" \t\r") + 1)) + "'"};
    };
    const bool named_alone = fields.size() == 1;
    const bool with_checksum = fields.size() == 3 && equals_ignoring_case(fields[1], "CRC32");
    if (!named_alone && !with_checksum)
        return refused("a file's name, then the word CRC32 and its checksum or nothing");
    if (!is_plain_file_name(fields[0]))
        return refused("NAME a file of the work folder, without a folder");
    if (named_alone)
        return ScriptInput{std::string(fields[0]), std::nullopt, line_number};
    const std::optional<std::uint32_t> crc32 = crc32_of(fields[2]);
    if (!crc32)
        return refused("XXXXXXXX the CRC-32 of the file's bytes in 8 hex digits");
    return ScriptInput{std::string(fields[0]), *crc32, line_number};
}

std::string input_line(const ScriptInput& input)
{
    if (!input.crc32)
        return "INPUT " + input.name;
    return "INPUT " + input.name + " CRC32 " + crc32_text(*input.crc32);
}

std::string crc32_text(std::uint32_t crc32)
{
    char digits[crc32_digits + 1] = {};
    std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(crc32));
    return digits;
}

} // namespace apcs
