#pragma once
// `kumite play --xr`: the bout in an OpenXR headset (runtime/xr/xr_play.h), and the report's `xr` object (frames
// waited and submitted, XR errors, the session states seen, frame work and render times, the eye image's geometry).

#include "arguments.h"
#include "viewer_settings.h"

#include "kumite/runtime/bout.h"

#include <nlohmann/json.hpp>

#include <functional>

namespace kumite::cli {

// Runs the bout in the headset for `duration_s` of bout time; session states go to `write_event` as `xr_session`
// events; the report's `xr` object into `xr_report`. `supervisor` (or null): the desktop window beside the headset,
// with these settings. Returns 0, or 1 (message on stderr) when no session started or a screenshot failed.
int play_xr(Bout& bout, const Arguments& arguments, double duration_s, const std::function<void()>& after_step,
            const std::function<void(nlohmann::json)>& write_event, const view::ViewerSettings* supervisor, nlohmann::json& xr_report);

} // namespace kumite::cli
