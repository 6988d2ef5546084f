#pragma once
// Reading a capture the way every tool does: the BVH, then its body map override — the file given, or else the
// sidecar `NAME.bodymap.json` beside the capture when there is one.

#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <optional>

namespace kumite {

Result<BvhFile> capture_read_file(const std::filesystem::path& path, const BvhReadOptions& options = {},
                                  const std::optional<std::filesystem::path>& body_map_override = std::nullopt);

} // namespace kumite
