#pragma once
// A bout's event as one line of JSON: {"t", "type", "fighter", ...} with the fields of its type (docs/reports.md,
// "What a bout writes"; ../../shared/docs/CLI.md). What `kumite play --events` writes and the C API's events give.
// Formatting allocates: call it outside the frame's hot path (events are a few a second).

#include "kumite/runtime/bout.h"

#include <string>

namespace kumite {

std::string bout_event_json(const Bout& bout, const BoutEvent& event);

} // namespace kumite
