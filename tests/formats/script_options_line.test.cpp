#include "apcs/formats/key_script.h"
#include "apcs/formats/key_recording.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

TEST_CASE("an OPTIONS line before the first key keeps its words one space apart without its comment",
          "[formats][record][options]")
{
    const Expected<KeyScript> script = parse_captioned_key_script(
        "INPUT way1.dat CRC32 1db7d833\nOPTIONS   --step 0.1\t--inbetweens 20 ; recorded so\nENTER\nSTART\n6\n",
        "mine.keys");
    REQUIRE(script);
    REQUIRE(script->options == ScriptOptions{"--step 0.1 --inbetweens 20", 2});
    REQUIRE(script->events.size() == 2);
    const Expected<KeyScript> tabbed = parse_captioned_key_script("OPTIONS\t--step\t0.1\nENTER\n", "mine.keys");
    REQUIRE(tabbed);
    REQUIRE(tabbed->options == ScriptOptions{"--step 0.1", 1});
    const Expected<KeyScript> none = parse_captioned_key_script("ENTER\n", "mine.keys");
    REQUIRE(none);
    REQUIRE(none->options.words.empty());
}

TEST_CASE("an OPTIONS line after a key or START or a caption or GOAL, a second one and an empty one are refused",
          "[formats][record][options]")
{
    const std::string expected = "; expected one OPTIONS line before the script's first key, START, caption and "
                                 "GOAL, holding the session's options (OPTIONS --step 0.1)";
    const auto [text, message] = GENERATE_COPY(table<std::string, std::string>({
        {"ENTER\nOPTIONS --step 0.1\n", "m.keys:2: OPTIONS after a key, START, a caption or GOAL" + expected},
        {"TEXT x\nOPTIONS --step 0.1\n", "m.keys:2: OPTIONS after a key, START, a caption or GOAL" + expected},
        {"START\nOPTIONS --step 0.1\n", "m.keys:2: OPTIONS after a key, START, a caption or GOAL" + expected},
        {";; a caption\nOPTIONS --step 0.1\n", "m.keys:2: OPTIONS after a key, START, a caption or GOAL" + expected},
        {"GOAL VALUE TENSION 0.4 0.6\nOPTIONS --step 0.1\n",
         "m.keys:2: OPTIONS after a key, START, a caption or GOAL" + expected},
        {"OPTIONS --step 0.1\n; between\nOPTIONS --inbetweens 3\n",
         "m.keys:3: a second OPTIONS (the first is on line 1)" + expected},
        {"OPTIONS\n", "m.keys:1: OPTIONS names no option" + expected},
        {"OPTIONS ; only a comment\n", "m.keys:1: OPTIONS names no option" + expected},
        {"OPTIONS" + std::string(1100, ' ') + "--step 0.1\n",
         "m.keys:1: OPTIONS line of 1117 bytes; expected at most 1024, each option once"},
    }));
    CAPTURE(text);
    const Expected<KeyScript> refused = parse_captioned_key_script(text, "m.keys");
    REQUIRE_FALSE(refused);
    REQUIRE(refused.error().to_string() == message);
    // The plain reader (no captions kept) refuses the same lines.
    REQUIRE_FALSE(parse_key_script(text, "m.keys"));
}

TEST_CASE("a recording writes its OPTIONS line after the INPUT lines and reads back with it",
          "[formats][record][options]")
{
    KeyRecording recording;
    recording.add_inputs({{"way1.dat", 0x1db7d833, 1}});
    recording.add_options("--step 0.1");
    recording.add_key(KeyEvent::typed(U'6'), false);
    REQUIRE(recording.text() == "INPUT way1.dat CRC32 1db7d833\nOPTIONS --step 0.1\n6\n");
    const Expected<KeyScript> read = parse_captioned_key_script(recording.text(), "mine.keys");
    REQUIRE(read);
    REQUIRE(read->options == ScriptOptions{"--step 0.1", 2});
    KeyRecording plain;
    plain.add_key(KeyEvent::typed(U'6'), false);
    REQUIRE(plain.text() == "6\n");
}
