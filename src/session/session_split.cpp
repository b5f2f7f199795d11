// addpoint.c and split.c (SPEC §5.1, §5.2): equal point counts, then one path file per point,
// written a batch at a time so that the shell can read keys between batches.
#include "apcs/session/session_steps.h"

#include "apcs/formats/path_files.h"

#include <algorithm>

namespace apcs::step {

namespace {

// Path files per work(): small enough that a key is read within a few milliseconds even on a
// slow disk, large enough that reading keys costs nothing next to the writing.
constexpr std::size_t split_batch_files = 64;

} // namespace

Splitting Splitting::after(const Key2Prompt&, StepContext& context)
{
    SessionModel& model = context.model;
    model.keys = equalise_key_frames(model.key_frames[0], model.key_frames[1]);
    model.point_count = model.keys.key1.point_count();
    return {model.keys.key1.all_points(), model.keys.key2.all_points(), 0};
}

// Keys of up to a batch of points are split at once, as in the thesis.
StepResult Splitting::start(StepContext& context)
{
    context.files.begin_batch();
    return work(context);
}

StepResult Splitting::work(StepContext& context)
{
    const std::size_t batch_end = std::min(total(), written + split_batch_files);
    while (written < batch_end) {
        const NamedText file = split_path_file(written + 1, key1[written], key2[written]);
        if (const Expected<void> wrote = context.write_file(file.name, file.content); !wrote) {
            static_cast<void>(close(context));
            return StepResult::refused(wrote.error().to_string());
        }
        context.model.written.add(file.name);
        ++written;
    }
    return written == total() ? finish(context) : StepResult{};
}

StepResult Splitting::finish(StepContext& context)
{
    if (const Expected<void> closed = close(context); !closed)
        return StepResult::refused(closed.error().to_string());
    const SessionModel& model = context.model;
    context.files.log("added points: both keys have " + std::to_string(model.point_count) + " points in " +
                      std::to_string(model.keys.key1.parts.size()) + " parts; wrote ani1.dat … " +
                      path_file_name(model.point_count));
    return {StepOutcome::done};
}

StepResult Splitting::submit(StepContext& context, const std::string&)
{
    const Expected<void> closed = close(context);
    const std::string files = written == 0 ? std::string("no path file")
                                           : "ani1.dat … " + path_file_name(written) + " (" + std::to_string(written) +
                                                 " of " + std::to_string(total()) + ")";
    context.files.log("split stopped: " + files + " written");
    return {StepOutcome::stopped,
            closed ? "Split stopped: " + files + " written, none half-written" : closed.error().to_string()};
}

Expected<void> Splitting::close(StepContext& context)
{
    Expected<void> closed = context.files.end_batch();
    if (!closed)
        context.model.written.set_problem(closed.error());
    return closed;
}

std::string Splitting::progress() const
{
    const std::string last = written == 0 ? std::string("nothing") : path_file_name(written);
    return "Splitting: " + last + " of " + std::to_string(total()) + " written - Esc stops, Ctrl-C ends APCS";
}

} // namespace apcs::step
