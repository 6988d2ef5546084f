#pragma once
// The bout that `kumite play` runs, shared with `kumite train`: the tracker, the database and characters, the frame
// loop (headless, the viewer or the headset), the events, the recordings and the report, from play's flags (those a
// command's spec does not have are simply absent). What train adds comes through BoutRunExtras.

#include "arguments.h"
#include "kumite/core/result.h"
#include "kumite/runtime/bout.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>

namespace kumite::cli {

// The bout as it is about to start.
struct BoutRunStart {
    const Bout& bout;
    const nlohmann::json& settings; // play --print-settings as JSON
    const std::string& character;   // the starting character's name
    const std::string& tracker;     // the tracker's source as given ("xr" for the headset)
};

struct BoutRunExtras {
    std::optional<DrillRun> drill;  // run it; the bout lasts as long as it
    // Before the first step; an error ends the command (exit 1) before anything ran.
    std::function<Result<void>(const BoutRunStart&)> on_start;
    // Every event line, as the events file gets it (also without --events): all of them, or without --events and
    // --html only those of the types wants_event takes (when given), and the drill's parts.
    std::function<void(const nlohmann::json&)> on_event;
    std::function<bool(FighterEvent::Type)> wants_event;
    // With the report, after the bout; an error ends the command (exit 1) after the files were written.
    std::function<Result<void>(const nlohmann::json& report)> on_end;
};

// Runs the bout the arguments describe (parsed against `spec`); returns the exit status.
int run_bout(const CommandSpec& spec, const Arguments& arguments, BoutRunExtras* extras);

} // namespace kumite::cli
