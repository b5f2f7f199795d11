#include "apcs/lesson/handout.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace apcs {

namespace {

// A letter or digit of ASCII, lowercased; '\0' for anything else.
char name_character(char character)
{
    if (character >= 'A' && character <= 'Z')
        return static_cast<char>(character - 'A' + 'a');
    const bool kept = (character >= 'a' && character <= 'z') || (character >= '0' && character <= '9');
    return kept ? character : '\0';
}

bool all_of_characters(std::string_view text, bool (*kept)(char))
{
    return !text.empty() && std::all_of(text.begin(), text.end(), kept);
}

bool is_digit(char character) { return character >= '0' && character <= '9'; }

bool is_step_character(char character) { return character == '-' || name_character(character) == character; }

// "NN-STEP" as handout_file_stem makes it: two digits or more, a '-', a short name.
bool is_page_stem(std::string_view stem)
{
    const std::size_t dash = stem.find('-');
    if (dash == std::string_view::npos || dash < 2)
        return false;
    const std::string_view step = stem.substr(dash + 1);
    return all_of_characters(stem.substr(0, dash), is_digit) && step.size() <= max_step_name_length &&
           all_of_characters(step, is_step_character);
}

// ".bak", or ".b01" ... ".b99" (backup_path_for's names when NAME.bak is an input).
bool is_backup_extension(std::string_view extension)
{
    return extension == ".bak" ||
           (extension.size() == 4 && extension.starts_with(".b") && all_of_characters(extension.substr(2), is_digit));
}

struct NameParts {
    std::string_view stem;
    std::string_view extension; // from the last '.', which it includes
};

NameParts parts_of(std::string_view name)
{
    const std::size_t dot = name.rfind('.');
    if (dot == std::string_view::npos || dot == 0)
        return {name, {}};
    return {name.substr(0, dot), name.substr(dot)};
}

} // namespace

bool is_handout_page_name(std::string_view name)
{
    const NameParts parts = parts_of(name);
    return (parts.extension == ".png" || parts.extension == ".txt") && is_page_stem(parts.stem);
}

bool is_handout_file_name(std::string_view name)
{
    // write_file_atomically's temporary file: ".NAME.XXXXXX".
    constexpr std::size_t unique_tail = 7;
    if (name.starts_with('.') && name.size() > 1 + unique_tail)
        return is_handout_file_name(name.substr(1, name.size() - 1 - unique_tail));
    const NameParts parts = parts_of(name);
    if (parts.stem == "index")
        return parts.extension == ".html" || is_backup_extension(parts.extension);
    return is_page_stem(parts.stem) && (is_handout_page_name(name) || is_backup_extension(parts.extension));
}

std::string handout_step_name(std::string_view caption)
{
    std::string name;
    bool separated = false;
    for (const char character : caption) {
        const char kept = name_character(character);
        if (kept == '\0') {
            separated = !name.empty();
            continue;
        }
        if (separated)
            name += '-';
        name += kept;
        separated = false;
    }
    if (name.empty())
        return "caption";
    if (name.size() <= max_step_name_length)
        return name;
    // The last whole word that fits: the '-' at or before the limit (a '-' right at it ends a word).
    const std::size_t cut = name.rfind('-', max_step_name_length);
    return name.substr(0, cut == std::string::npos || cut == 0 ? max_step_name_length : cut);
}

std::string handout_file_stem(int number, std::size_t count, std::string_view caption)
{
    const int width = std::max(2, static_cast<int>(std::to_string(count).size()));
    char digits[32];
    std::snprintf(digits, sizeof digits, "%0*d-", width, number);
    return digits + handout_step_name(caption);
}

std::string screen_text(const ProgramScreen& screen, GlyphSet glyphs)
{
    const CellGrid grid = screen.graphics
                              ? render_cells(screen.picture, {text_screen_columns, text_screen_rows}, glyphs)
                              : screen.text;
    std::string text;
    for (int row = 0; row < grid.rows(); ++row) {
        std::string line = grid.row_text(row);
        line.erase(line.find_last_not_of(' ') + 1);
        text += line + '\n';
    }
    return text;
}

bool is_empty_prompt(const ProgramScreen& screen)
{
    if (screen.graphics)
        return false;
    int rows_written = 0;
    for (int row = 0; row < screen.text.rows(); ++row) {
        std::string line = screen.text.row_text(row);
        line.erase(line.find_last_not_of(' ') + 1);
        if (!line.empty() && line != "_")
            ++rows_written;
    }
    return rows_written <= 1;
}

GraphicsScreen screen_picture(const ProgramScreen& screen)
{
    if (screen.graphics)
        return screen.picture;
    GraphicsScreen picture;
    for (int row = 0; row < screen.text.rows(); ++row) {
        std::string line = screen.text.row_text(row);
        line.erase(line.find_last_not_of(' ') + 1);
        if (!line.empty())
            picture.text.push_back({0, row, line, screen.text.style_at(0, row)});
    }
    return picture;
}

} // namespace apcs
