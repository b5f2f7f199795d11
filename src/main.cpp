#include "apcs/cli/command_line.h"
#include "apcs/terminal/terminal_session.h"

#include <clocale>
#include <cstring>
#include <iostream>
#include <langinfo.h>

namespace {

// --glyphs' default: braille where the locale speaks UTF-8, plain ASCII elsewhere.
apcs::GlyphSet resolve_glyphs(apcs::GlyphSet chosen)
{
    if (chosen != apcs::GlyphSet::automatic)
        return chosen;
    return std::strcmp(nl_langinfo(CODESET), "UTF-8") == 0 ? apcs::GlyphSet::braille : apcs::GlyphSet::ascii;
}

} // namespace

int main(int argc, char** argv)
{
    std::setlocale(LC_ALL, "");
    const apcs::TerminalSessionRunner terminal = [](apcs::Session& session, const std::vector<apcs::KeyEvent>& scripted,
                                                    apcs::GlyphSet glyphs, std::vector<apcs::KeyEvent>& recorded,
                                                    std::string& problem) {
        return apcs::run_terminal_session(session, scripted, resolve_glyphs(glyphs), recorded, problem);
    };
    return apcs::run_command_line(argc, argv, std::cout, std::cerr, terminal);
}
