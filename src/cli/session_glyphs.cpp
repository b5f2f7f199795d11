// The glyphs a session's screens are drawn in: what the terminal and its locale can show.
#include "apcs/cli/session_command.h"

#include "session_parts.h"
#include "apcs/formats/text_fields.h"

#include <cctype>
#include <cstdlib>
#include <langinfo.h>
#include <string>

namespace apcs {

namespace {

std::string_view glyph_set_name(GlyphSet glyphs)
{
    switch (glyphs) {
    case GlyphSet::braille: return "braille";
    case GlyphSet::blocks: return "blocks";
    case GlyphSet::ascii: return "ascii";
    case GlyphSet::automatic: break;
    }
    return "automatic";
}

// The terminal's type, "" when TERM is unset.
std::string_view term_of_environment()
{
    const char* term = std::getenv("TERM");
    return term == nullptr ? std::string_view() : std::string_view(term);
}

// The locale the environment asks for the character set: LC_ALL, else LC_CTYPE, else LANG (as
// setlocale reads them); "" when none is set.
std::string_view locale_of_environment()
{
    for (const char* name : {"LC_ALL", "LC_CTYPE", "LANG"})
        if (const char* value = std::getenv(name); value != nullptr && *value != '\0')
            return value;
    return {};
}

} // namespace

bool is_utf8_codeset(std::string_view codeset)
{
    std::string letters;
    for (const char c : codeset)
        if (c != '-' && c != '_')
            letters += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return letters == "utf8";
}

GlyphSet default_glyphs(std::string_view codeset, std::string_view term)
{
    const bool linux_console = term == "linux" || term.starts_with("linux-");
    const bool dec_terminal =
        term.size() > 2 && term.starts_with("vt") && std::isdigit(static_cast<unsigned char>(term[2])) != 0;
    const bool shows_braille = !term.empty() && !linux_console && !dec_terminal && term != "dumb";
    return is_utf8_codeset(codeset) && shows_braille ? GlyphSet::braille : GlyphSet::ascii;
}

Expected<GlyphSet> terminal_glyphs(GlyphSet asked, std::string_view codeset, std::string_view term,
                                   std::string_view locale_asked)
{
    if (asked == GlyphSet::automatic)
        return default_glyphs(codeset, term);
    if (asked == GlyphSet::ascii || is_utf8_codeset(codeset))
        return asked;
    const std::string needs = "--glyphs " + std::string(glyph_set_name(asked)) + " needs a UTF-8 locale";
    const std::string lower = ascii_lower_case(locale_asked);
    if (lower.find("utf-8") != std::string::npos || lower.find("utf8") != std::string::npos)
        return Diagnostic{"apcs", 0,
                          needs + ": " + std::string(locale_asked) +
                              " is not installed here (locale -a lists those that are); use LANG=C.UTF-8, or "
                              "--glyphs ascii"};
    return Diagnostic{"apcs", 0, needs + " (LANG=C.UTF-8 or similar); use --glyphs ascii"};
}

Expected<GlyphSet> terminal_glyphs_here(GlyphSet asked)
{
    return terminal_glyphs(asked, nl_langinfo(CODESET), term_of_environment(), locale_of_environment());
}

Expected<GlyphSet> session_glyphs(GlyphSet asked, bool headless)
{
    if (headless)
        return asked == GlyphSet::automatic ? GlyphSet::ascii : asked;
    return terminal_glyphs_here(asked);
}

} // namespace apcs
