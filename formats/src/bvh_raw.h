#pragma once
// What the BVH reader knows between its passes: the hierarchy in file units and the MOTION header.

#include "kumite/formats/bvh_reader.h"
#include "text_cursor.h"

namespace kumite {

struct RawBvh {
    Skeleton skeleton; // file units
    BvhLayout layout;
    double frame_time_s = 0.0;   // 0: the file gives no rate
    std::string frame_time_note; // "file:line: why there is no rate", when there is none
    int frame_count = 0;
};

// Frame text at least this large is parsed by two threads when allowed.
inline constexpr std::size_t k_bvh_parallel_min_bytes = 256 * 1024;

// Parses raw.frame_count frames (one per line, raw.layout.channel_count() values each) into clip's per-frame
// arrays, in file units. The cursor stands after "Frame Time: t". With threads >= 2, large frame text is split
// at a line near its middle and both halves are parsed at once. Unless `strict`, frames that are not one per
// line are read again as one stream of values, and whole values after the declared frames are ignored, each
// with a line in `warnings`.
Result<void> bvh_parse_frames(TextCursor& cursor, std::string_view source, const RawBvh& raw, Clip& clip, int threads, bool strict,
                              std::vector<std::string>& warnings);

} // namespace kumite
