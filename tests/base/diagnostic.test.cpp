#include "apcs/base/diagnostic.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("a diagnostic names the file, the line when there is one, and the message", "[base][diagnostic]")
{
    CHECK(Diagnostic{"a.dat", 3, "expected a number"}.to_string() == "a.dat:3: expected a number");
    CHECK(Diagnostic{"a.dat", 0, "is missing"}.to_string() == "a.dat: is missing");
}

TEST_CASE("Expected<void> is a success or the diagnostic of a failure", "[base][diagnostic]")
{
    const Expected<void> done = ok;
    CHECK(done.has_value());
    CHECK(static_cast<bool>(done));
    const Expected<void> failed = Diagnostic{"b.dat", 0, "is a key file"};
    CHECK_FALSE(failed);
    CHECK(failed.error().to_string() == "b.dat: is a key file");
}

TEST_CASE("a failure passes from Expected<T> to Expected<void> and back as its diagnostic", "[base][diagnostic]")
{
    const Expected<int> number = Diagnostic{"c.dat", 2, "expected an integer"};
    const Expected<void> checked = number.error();
    const Expected<double> again = checked.error();
    CHECK(again.error().to_string() == "c.dat:2: expected an integer");
}
