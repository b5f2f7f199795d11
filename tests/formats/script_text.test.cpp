#include "apcs/formats/file_io.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <thread>

using namespace apcs;

TEST_CASE("a keystroke script is read from a FIFO to its end, a .dat file from one never", "[formats][fifo]")
{
    const test::TempFolder folder;
    const std::filesystem::path fifo = folder / "script.keys";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);

    SECTION("a script through a FIFO is read whole")
    {
        const std::string script = "ENTER\nTEXT way1.dat\nENTER\n";
        std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << script; });
        const Expected<std::string> text = read_script_text(fifo);
        writer.join();
        REQUIRE(text.has_value());
        REQUIRE(*text == script);
    }
    SECTION("a script larger than its limit is refused with both sizes")
    {
        std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << std::string(100, 'x'); });
        const Expected<std::string> text = read_script_text(fifo, 10);
        writer.join();
        REQUIRE_FALSE(text.has_value());
        REQUIRE(text.error().file == fifo.string());
        REQUIRE_THAT(text.error().message, Catch::Contains("expected at most 10 bytes"));
    }
    SECTION("the same FIFO as a .dat input is refused without waiting for a writer")
    {
        const Expected<std::string> text = read_text_file(fifo);
        REQUIRE_FALSE(text.has_value());
        REQUIRE_THAT(text.error().message, Catch::Contains("(a FIFO)"));
    }
}

TEST_CASE("a keystroke script that is a regular file is read as read_text_file reads it", "[formats]")
{
    const test::TempFolder folder;
    folder.write("session.keys", "ENTER\n");
    const Expected<std::string> text = read_script_text(folder / "session.keys");
    REQUIRE(text.has_value());
    REQUIRE(*text == "ENTER\n");
}
