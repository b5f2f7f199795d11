#include "apcs/cli/write_progress.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <sstream>

using namespace apcs;
using namespace std::chrono_literals;

TEST_CASE("the progress line is rewritten in place, at most ten times a second, and ended by the last count",
          "[cli][progress]")
{
    std::ostringstream err;
    {
        WriteProgressLine line(err, true, "the files", 0ms);
        const WriteProgress report = line.report();
        REQUIRE(report);
        report(1, 3);
        report(2, 3); // within 100 ms of the first: not shown
        report(3, 3);
    }
    REQUIRE(err.str() == "\rapcs: writing the files: 1 of 3 (33%)\rapcs: writing the files: 3 of 3 (100%)\n");
}

TEST_CASE("a run that ends while the progress is quiet, or one not on a terminal, says nothing", "[cli][progress]")
{
    std::ostringstream err;
    {
        WriteProgressLine quiet(err, true, "the files", 1h);
        quiet.report()(1, 2);
        quiet.report()(2, 2);
        WriteProgressLine off(err, false, "the files", 0ms);
        REQUIRE_FALSE(off.report());
    }
    REQUIRE(err.str().empty());
}

TEST_CASE("a progress line left open by a failed run is ended, so that the reason gets a line of its own",
          "[cli][progress]")
{
    std::ostringstream err;
    {
        WriteProgressLine line(err, true, "the frame files", 0ms);
        line.report()(5, 100);
    }
    REQUIRE(err.str() == "\rapcs: writing the frame files: 5 of 100 (5%)\n");
}
