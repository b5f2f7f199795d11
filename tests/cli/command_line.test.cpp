#include "apcs/cli/command_line.h"
#include "apcs/version.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <vector>

using namespace apcs;

namespace {

struct Run {
    int status = 0;
    std::string out;
    std::string err;
};

Run run(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), "apcs");
    std::vector<const char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(argument.c_str());
    std::ostringstream out;
    std::ostringstream err;
    const int status = run_command_line(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

} // namespace

TEST_CASE("the --version option prints the version and exits 0", "[cli]")
{
    const auto result = run({"--version"});
    REQUIRE(result.status == 0);
    REQUIRE(result.out == "apcs " + std::string(version) + "\n");
}

TEST_CASE("the --help option lists the subcommands and exits 0", "[cli]")
{
    const auto result = run({"--help"});
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
        const auto result = run(arguments);
        CAPTURE(arguments);
        REQUIRE(result.status == 2);
        REQUIRE(result.out.empty());
        REQUIRE(result.err.starts_with("apcs: "));
        REQUIRE(result.err.find("Usage:") != std::string::npos);
    }
}
