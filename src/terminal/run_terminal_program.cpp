#include "apcs/terminal/run_terminal_program.h"

#include "terminal.h"
#include "apcs/terminal/terminal_pixels.h"

#include <memory>
#include <utility>

namespace apcs {

Expected<ExitStatus> run_terminal_program(InteractiveProgram& program, GlyphSet glyphs, ColourChoice colour,
                                          PixelChoice pixel_choice)
{
    Expected<std::unique_ptr<Terminal>> opened = Terminal::open(colour);
    if (!opened)
        return opened.error();
    const std::unique_ptr<Terminal> terminal = std::move(*opened);
    TerminalPixels pixels(*terminal, terminal->detect_pixels(pixel_choice));
    return run_program_on(program, *terminal, pixels, glyphs);
}

} // namespace apcs
