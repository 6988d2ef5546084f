#pragma once
// The fighters' motion in numbers: the fastest wrist, ankle, elbow and knee in each kind of move against
// the library's fastest for that kind (the database's clips played on the starting character), and the distance kept
// to the user's head between strikes. Written into the report and the bout_end event (the session report reads it).

#include "kumite/runtime/bout.h"

#include <nlohmann/json.hpp>

namespace kumite::cli {

nlohmann::json play_motion_json(const Bout& bout);

} // namespace kumite::cli
