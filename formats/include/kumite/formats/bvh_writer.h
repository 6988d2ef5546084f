#pragma once
// BVH writer: a Clip (metres) and its channel layout back to BVH text in a chosen length unit. The hierarchy,
// names, channel order and rotation orders are the layout's; rotations are written as each joint's canonical
// Euler angles (euler_from_quaternion: middle angle within +-90 degrees, the others within +-180), the convention
// exporters use, so a capture read and written back keeps its numbers except where its exporter chose the other
// equivalent triple. Numbers carry 10 significant digits: positions agree with the clip far below a micrometre.

#include "kumite/core/clip.h"
#include "kumite/core/result.h"
#include "kumite/formats/bvh_reader.h"

#include <filesystem>
#include <string>

namespace kumite {

// A layout for a skeleton that has none (e.g. a retargeted character): 6 channels on the root, 3 on other
// joints, all in `order`; joints with animated translations also get position channels.
BvhLayout bvh_default_layout(const Clip& clip, EulerOrder order = EulerOrder{});

// The whole file as text. Asserts that layout matches the clip's skeleton.
std::string bvh_write_string(const Clip& clip, const BvhLayout& layout, const LengthUnit& unit);

// Writes atomically: to a temporary file beside `path`, then renamed over it, so a failure leaves no half file.
Result<void> bvh_write_file(const std::filesystem::path& path, const Clip& clip, const BvhLayout& layout,
                            const LengthUnit& unit);

} // namespace kumite
