// Preloaded into apcs by tmux_signal_at_takeover.sh (LD_PRELOAD): curses' cbreak() does its work,
// putting the terminal in cbreak mode, then SIGINT arrives, as a Ctrl-C typed in the few
// milliseconds while the session takes the terminal over would. The program must still give the
// terminal back (echo and icanon on).
#include <csignal>
#include <dlfcn.h>

extern "C" int cbreak()
{
    using Cbreak = int (*)();
    const auto curses_cbreak = reinterpret_cast<Cbreak>(dlsym(RTLD_NEXT, "cbreak"));
    const int result = curses_cbreak != nullptr ? curses_cbreak() : -1;
    std::raise(SIGINT);
    return result;
}
