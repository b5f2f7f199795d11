#include "apcs/cli/command_line.h"
#include "apcs/version.h"

#include "support/run_apcs.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <vector>

using namespace apcs;

using test::run_apcs;

TEST_CASE("the --version option prints the version and exits 0", "[cli]")
{
    const auto result = run_apcs({"--version"});
    REQUIRE(result.status == 0);
    REQUIRE(result.out == "apcs " + std::string(version) + "\n");
}

TEST_CASE("the --help option lists the subcommands and exits 0", "[cli]")
{
    const auto result = run_apcs({"--help"});
    REQUIRE(result.status == 0);
    for (const char* command : {"path", "inbetween", "fit", "figures", "play"})
        REQUIRE(result.out.find(command) != std::string::npos);
}

TEST_CASE("bad usage is exit 2 with a one-line reason and the usage", "[cli]")
{
    for (const auto& arguments : std::vector<std::vector<std::string>>{
             {"--frobnicate"},
             {"path", "a.dat", "--tension", "2"},
             {"path", "a.dat", "--tension", "nan"},
             {"path", "a.dat", "--slopes", "0.5"},
             {"path", "a.dat", "--slopes", "0.5", "1.5"},
             {"path", "a.dat", "--samples", "0"},
             {"path", "a.dat", "--spacing", "wobbly"},
             {"path", "a.dat", "--glyphs", "emoji"},
             {"path"},
             {"fit", "a.dat"},
         }) {
        const auto result = run_apcs(arguments);
        CAPTURE(arguments);
        REQUIRE(result.status == 2);
        REQUIRE(result.out.empty());
        REQUIRE(result.err.starts_with("apcs: "));
        REQUIRE(result.err.find("Usage:") != std::string::npos);
    }
}
