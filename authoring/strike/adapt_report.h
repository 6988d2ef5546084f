#pragma once
// The report of one adapted strike (`kumite adapt --report`, the Python module's adapt): contact, overshoot, speed,
// joint limits, bone lengths, feet, cost, and which clip from where.

#include "kumite/core/retrieval.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/strike_playback.h"

#include <nlohmann/json.hpp>

namespace kumite {

nlohmann::json adapt_report_json(const StrikePlayback& playback, const RetrievalResult& retrieved, const MotionDatabaseView& database,
                                 const Skeleton& skeleton, const Eigen::Vector3d& target);

} // namespace kumite
