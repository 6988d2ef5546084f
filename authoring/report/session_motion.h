#pragma once
// The session report's motion table: how fast the fighter's wrists, ankles, elbows and knees moved in each
// kind of move against the library's fastest for that kind, the speed at contact by kind of strike, and the distance
// kept to the user between strikes, from the bout_end line's `motion` object (kumite play writes it).

#include <nlohmann/json.hpp>

#include <string>

namespace kumite::report {

// The table, or a line saying the events have none (a bout from before the motion was measured).
std::string motion_html(const nlohmann::json* bout_end);

} // namespace kumite::report
