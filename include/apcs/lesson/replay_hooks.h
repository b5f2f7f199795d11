#pragma once

#include "apcs/screens/program_screen.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace apcs {

class Session;

// What a replay of a key script tells the program that runs it, as it plays, and what it asks of
// it.
struct ReplayHooks {
    // Caption `index` of the script is reached: `shown` is the screen a paced replay shows it over,
    // the caption laid on (with_caption). Called once per caption, in the script's order, when the
    // session has played the keys before it and is neither splitting nor animating (the moment the
    // headless replay reaches it too). The headless transcript prints the caption here.
    std::function<void(std::size_t index, const ProgramScreen& shown)> caption_reached;
    // Caption `index` has played its keys: `caption` is its text as shown then ("(not reached) …"
    // when it closes a goal judged not reached), `screen` the session's screen (no caption laid on)
    // once they have, when the next caption is reached or the script's keys are all played (Esc
    // too), the session neither splitting nor animating. Called once per caption reached, in order,
    // so each caption's screen shows what the caption says. --handout writes its pages here;
    // `key_files` are the KEY files the replay's sessions have read so far (key_files_read), which
    // a page must not replace.
    std::function<void(std::size_t index, const std::string& caption, const ProgramScreen& screen,
                       const std::vector<std::string>& key_files)>
        caption_ended;
    // A line for apcs.log ("goal skipped").
    std::function<void(const std::string& line)> log;
    // PgUp and Home (SPEC §3.1): a new session on the inputs as they were when the replay started,
    // which writes nothing until caught_up() is called (the keys up to the caption gone back to are
    // played into it at once). Without it the replay cannot go back.
    std::function<std::unique_ptr<Session>()> session_as_started;
    std::function<void()> caught_up;
    // False when nobody will ask for recording() (apcs grade's replays): the keys are then not
    // kept a second time, as --record would write them (about 80 bytes a key).
    bool keeps_recording = true;
};

} // namespace apcs
