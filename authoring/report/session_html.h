#pragma once
// The supervisor's session report: one self-contained HTML page (inline CSS and SVG, nothing fetched, no script)
// drawn from a bout's event lines — the summary, then a section per fighter with its numbers, its timeline, the
// room from above and the distributions (command → strike latency, effector speed at contact, overshoot, the aim's
// prediction error). The first k_detailed_fighters fighters get a whole section, the others a row of a table.

#include "session_log.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace kumite::report {

inline constexpr int k_detailed_fighters = 24;

// `play_report`: the bout's report (kumite play --report), when there is one: it adds what the events do not say.
// `source`: what the events came from, shown on the page.
std::string session_html(const SessionLog& log, const nlohmann::json* play_report = nullptr, std::string_view source = {});

} // namespace kumite::report
