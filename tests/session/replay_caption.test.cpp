// Captions of a guided replay: ";;" comments of a key script, laid over the screen.
#include "apcs/session/key_event.h"
#include "apcs/session/replay_caption.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("a ';;' comment is a caption placed after the keys before it; ';' comments and TEXT are not",
          "[session][captions]")
{
    const Expected<KeyScript> script = parse_captioned_key_script(";; Step 1: the key frames\n"
                                                                  "ENTER ; KEY1\n"
                                                                  "ENTER   ;;  Step 2: the split  \n"
                                                                  "TEXT ;; typed, not a caption\n"
                                                                  "; a plain comment\n"
                                                                  "8 6 ;;\n",
                                                                  "class.keys");
    REQUIRE(script);
    REQUIRE(script->events.size() == 2 + 23 + 2);
    REQUIRE(script->captions == std::vector<ScriptCaption>{{0, "Step 1: the key frames"},
                                                           {2, "Step 2: the split"},
                                                           {27, ""}});
    REQUIRE(caption_at(*script, 0)->text == "Step 1: the key frames");
    REQUIRE(caption_at(*script, 1)->text == "Step 1: the key frames");
    REQUIRE(caption_at(*script, 2)->text == "Step 2: the split");
    REQUIRE(caption_at(*script, 27)->text.empty());
    // The keys are those of the script read without captions.
    REQUIRE(*parse_key_script(";; x\nENTER ;; y\n", "a.keys") == parse_captioned_key_script(";; x\nENTER ;; y\n", "a.keys")->events);
    REQUIRE(caption_at(KeyScript{}, 5) == nullptr);
}

TEST_CASE("a caption takes the message line in graphics mode and the bottom row of the console", "[session][captions]")
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 6 0\n";
    files.files["key2.dat"] = "0 0 10\n0 6 10\n";
    Session session({}, files);
    const SessionScreen text = with_caption(session.screen(), "Step 1: KEY1 is the first key frame");
    REQUIRE(text.text.row_text(23).starts_with("Step 1: KEY1 is the first key frame   "));
    REQUIRE(text.text.style_at(0, 23) == CellStyle::reverse);
    REQUIRE(text.text.style_at(79, 23) == CellStyle::reverse);
    REQUIRE(with_caption(session.screen(), "").text.row_text(23) == session.screen().text.row_text(23));
    for (const char* answer : {"", "", "", "ani1.dat", ""})
        test::type(session, answer);
    REQUIRE(session.screen().graphics);
    const SessionScreen graphics = with_caption(session.screen(), "Step 3: 8 is global control");
    std::vector<TextLine> on_message_line;
    for (const TextLine& line : graphics.picture.text)
        if (line.row == 18)
            on_message_line.push_back(line);
    REQUIRE(on_message_line.size() == 1);
    REQUIRE(on_message_line[0].text == "Step 3: 8 is global control");
    REQUIRE(on_message_line[0].style == CellStyle::reverse);
}
