#include "apcs/cli/command_line.h"
#include "apcs/terminal/terminal_session.h"

#include <clocale>
#include <cstring>
#include <iostream>
#include <langinfo.h>
#include <malloc.h>

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
    // Large buffers (key files, frames, file texts) come and go in a batch run; a fixed mmap
    // threshold hands each back to the system when freed instead of letting glibc keep it in the
    // heap, so peak memory is what is in use at once.
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
    const apcs::TerminalSessionRunner terminal = [](apcs::Session& session, const std::vector<apcs::KeyEvent>& scripted,
                                                    apcs::GlyphSet glyphs, std::vector<apcs::KeyEvent>& recorded,
                                                    std::string& problem) {
        return apcs::run_terminal_session(session, scripted, resolve_glyphs(glyphs), recorded, problem);
    };
    return apcs::run_command_line(argc, argv, std::cout, std::cerr, terminal);
}
