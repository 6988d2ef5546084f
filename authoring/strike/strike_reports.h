#pragma once
// The reports of one strike (the command line's and the Python module's): what retrieval found (`kumite query`)
// and how the adapted strike went (`kumite adapt --report`: contact, overshoot, speed, joint limits, bone lengths,
// feet, cost, and which clip from where).

#include "kumite/core/retrieval.h"
#include "kumite/formats/motion_database_file.h"
#include "kumite/runtime/strike_playback.h"

#include <nlohmann/json.hpp>

namespace kumite {

// The retrieval's answer; `latency_us`: how long it took.
nlohmann::json query_result_json(const Retriever& retriever, const RetrievalResult& result, double latency_us);

nlohmann::json adapt_report_json(const StrikePlayback& playback, const RetrievalResult& retrieved, const MotionDatabaseView& database,
                                 const Skeleton& skeleton, const Eigen::Vector3d& target);

} // namespace kumite
