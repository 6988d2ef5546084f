#pragma once
// What `kumite play` prints at the end of a bout without --json: a few lines a supervisor reads at a glance (the
// orders and strikes, what the user's blows did, the fighter's speeds and distance, the frame cost) and where the
// files went. Drawn from the bout report (play_output.h), whose file keeps the rest.

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace kumite::cli {

// `files`: what was written, as (what, path) pairs ("events", "build/demo/bout.jsonl"), in the order to list them.
std::string play_summary_text(const nlohmann::json& report, const std::vector<std::pair<std::string, std::string>>& files);

} // namespace kumite::cli
