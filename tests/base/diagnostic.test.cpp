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

TEST_CASE("a name with control characters is printed escaped, never obeyed by the terminal", "[base][diagnostic][names]")
{
    const std::string name = "esc\x1B]0;PWN2\a.keys";
    CHECK(escape_controls(name) == "esc\\x1B]0;PWN2\\x07.keys");
    CHECK(Diagnostic{name, 3, "expected a key"}.to_string() == "esc\\x1B]0;PWN2\\x07.keys:3: expected a key");
    CHECK(Diagnostic{"a.dat", 0, "is a symbolic link to " + name}.to_string() ==
          "a.dat: is a symbolic link to esc\\x1B]0;PWN2\\x07.keys");
}

TEST_CASE("escaping keeps printable UTF-8 and names bidi controls, C1 controls and stray bytes", "[base][names]")
{
    CHECK(escape_controls("caf\xC3\xA9 \xE9\xB1\xBC\ttab.dat") == "caf\xC3\xA9 \xE9\xB1\xBC\ttab.dat");
    CHECK(escape_controls("gpj\xE2\x80\xAE.exe") == "gpjU+202E.exe");
    CHECK(escape_controls("a\xC2\x9B" "31m") == "aU+009B31m");
    CHECK(escape_controls("a\x9B\xFFz\x7F") == "a\\x9B\\xFFz\\x7F");
    CHECK(escape_controls(escape_controls("x\x1B")) == "x\\x1B");
    CHECK(first_control_character("caption \xE2\x81\xA6right") == "U+2066");
    CHECK_FALSE(first_control_character("caf\xC3\xA9\t\xFF").has_value());
}
