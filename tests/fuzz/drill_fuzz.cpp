// libFuzzer target for the drill file reader (formats/drill_file.h).
//
// Every input is parsed with drill_parse. A refusal must name the file and a line ("fuzz.toml:N: reason", N >= 1);
// a drill that reads must hold what the reader promises: a name, at least one part, each with a name, attacks or
// free sparring (not both), one of count and duration_s, a cadence range in order within its bounds. A failed check
// prints what failed and traps, so libFuzzer saves the input as a crash-* reproducer.

#include "kumite/formats/drill_file.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "drill_fuzz: check failed: %s\n%s\n", what, detail.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > (std::size_t(1) << 20) + 16) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const kumite::Result<kumite::Drill> drill = kumite::drill_parse(text, "fuzz.toml");
    if (!drill) {
        const std::string& message = drill.error().message;
        if (message.rfind("fuzz.toml:", 0) != 0) fail("a refusal that does not name the file", message);
        const long line = std::strtol(message.c_str() + 10, nullptr, 10);
        if (line < 1) fail("a refusal without a line", message);
        return 0;
    }
    if (drill->name.empty() || drill->parts.empty()) fail("a drill without a name or parts");
    for (const kumite::DrillPart& part : drill->parts) {
        if (part.name.empty() || part.line < 1) fail("a part without a name or line");
        if (part.free_sparring == !part.attacks.empty()) fail("a part with both attacks and free sparring, or neither");
        if ((part.count > 0) == (part.duration_s > 0.0)) fail("a part with both or neither of count and duration_s");
        if (!(part.cadence_min_s >= 0.3 && part.cadence_min_s <= part.cadence_max_s && part.cadence_max_s <= 600.0)) fail("a cadence out of order or bounds");
        for (const kumite::DrillLine& attack : part.attacks) {
            if (attack.text.empty() || attack.line < 1) fail("an attack without text or line");
        }
    }
    return 0;
}
