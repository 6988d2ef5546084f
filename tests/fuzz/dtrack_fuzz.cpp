// libFuzzer target: any datagram handed to the DTrack parser is refused with a line and a message, or gives a
// frame whose counts stay inside its fixed arrays and whose numbers are finite.

#include "kumite/runtime/dtrack.h"

#include <cmath>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    kumite::DtrackFrame frame;
    const kumite::DtrackParseResult result = kumite::dtrack_parse(std::string_view(reinterpret_cast<const char*>(data), size), frame);
    if (!result.ok) {
        if (result.what == nullptr || result.what[0] == '\0') std::abort();
        return 0;
    }
    if (frame.body_count < 0 || frame.body_count > kumite::k_dtrack_max_bodies) std::abort();
    if (frame.marker_count < 0 || frame.marker_count > kumite::k_dtrack_max_markers) std::abort();
    for (int i = 0; i < frame.body_count; ++i) {
        if (!frame.bodies[i].position_mm.allFinite() || !frame.bodies[i].rotation.allFinite() || !std::isfinite(frame.bodies[i].quality)) std::abort();
    }
    for (int i = 0; i < frame.marker_count; ++i) {
        if (!frame.markers[i].position_mm.allFinite()) std::abort();
    }
    return 0;
}
