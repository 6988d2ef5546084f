#pragma once
// Body map override files: JSON that fixes or completes the detected body map of one skeleton.
//
//   { "body_map": { "hand_l": "L_Wrist_Joint", "toe_r": null } }
//
// A part name maps to a joint name of the skeleton, or to null to leave the part unmapped. Parts not listed
// keep their detected joint. A sidecar next to a capture (`walk.bvh` -> `walk.bodymap.json`) is picked up by
// the tools automatically.

#include "kumite/core/body_map.h"
#include "kumite/core/result.h"

#include <filesystem>
#include <string_view>

namespace kumite {

// Applies the override text to `body_map` (parsed from `source_name`, used in error messages).
Result<BodyMap> body_map_apply_override(const BodyMap& body_map, const Skeleton& skeleton, std::string_view text,
                                        std::string_view source_name);

Result<BodyMap> body_map_apply_override_file(const BodyMap& body_map, const Skeleton& skeleton,
                                             const std::filesystem::path& path);

// `capture.bvh` -> `capture.bodymap.json`.
std::filesystem::path body_map_sidecar_path(const std::filesystem::path& capture_path);

} // namespace kumite
