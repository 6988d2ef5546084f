#pragma once
// The session report's section on the user's answers to the fighter's blows (user_response lines): a table by
// attack (blows, answered, the median response time, the kinds of answer, in time / late / none, counters) and a
// histogram of the response times for each attack.

#include "session_log.h"

#include <string>

namespace kumite::report {

// Empty when the fighter's blows had no answers told (events from before they were measured).
std::string responses_section_html(const FighterLog& fighter);

} // namespace kumite::report
