// libFuzzer target for the BVH reader and writer.
//
// Every input is parsed with bvh_parse. Inputs that parse must survive a round trip: written back with
// bvh_write_string in the unit the reader detected, the text must parse again with the same joint count and
// frame count. Structural invariants of the parsed file (array sizes, topological parents, End Site joints)
// are checked on both parses. A failed check prints what failed to stderr and traps, so libFuzzer saves the
// input as a crash-* reproducer.
//
// Set KUMITE_FUZZ_STRICT=1 to also require the round trip to keep joint names, channel layouts, the unit and
// the frame time (to 1e-9 relative); these are stronger than the reader's documented guarantees.

#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/bvh_writer.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

constexpr std::size_t k_max_input_bytes = std::size_t(1) << 20; // 1 MB: the reader is linear, bigger adds nothing

[[noreturn]] void fail(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "bvh_reader_fuzz: check failed: %s\n", what);
    if (!detail.empty()) std::fprintf(stderr, "%s\n", detail.c_str());
    std::fflush(stderr);
    __builtin_trap();
}

#define FUZZ_CHECK(condition, ...)                                                                                     \
    do {                                                                                                               \
        if (!(condition)) fail(#condition __VA_OPT__(, ) __VA_ARGS__);                                                 \
    } while (false)

bool strict_mode() {
    static const bool strict = [] {
        const char* value = std::getenv("KUMITE_FUZZ_STRICT");
        return value != nullptr && *value != '\0' && *value != '0';
    }();
    return strict;
}

void check_invariants(const kumite::BvhFile& file) {
    const kumite::Clip& clip = file.clip;
    const kumite::Skeleton& skeleton = clip.skeleton;
    const std::size_t joints = static_cast<std::size_t>(skeleton.joint_count());
    const std::size_t frames = static_cast<std::size_t>(clip.frame_count());
    FUZZ_CHECK(joints >= 1);
    FUZZ_CHECK(joints <= static_cast<std::size_t>(kumite::k_bvh_max_joints));
    FUZZ_CHECK(skeleton.parents.size() == joints);
    FUZZ_CHECK(skeleton.rest_offsets.size() == joints);
    FUZZ_CHECK(file.layout.joints.size() == joints);
    FUZZ_CHECK(skeleton.parents[0] == -1);
    for (std::size_t joint = 1; joint < joints; ++joint) {
        FUZZ_CHECK(skeleton.parents[joint] >= 0 && static_cast<std::size_t>(skeleton.parents[joint]) < joint);
    }
    for (const kumite::EndSite& end_site : skeleton.end_sites) {
        FUZZ_CHECK(end_site.joint >= 0 && static_cast<std::size_t>(end_site.joint) < joints);
    }
    for (const kumite::BvhJointChannels& channels : file.layout.joints) {
        FUZZ_CHECK(channels.count >= 0 && channels.count <= 6);
    }
    FUZZ_CHECK(clip.local_rotations.size() == frames * joints);
    FUZZ_CHECK(clip.local_translations.empty() || clip.local_translations.size() == frames * joints);
    FUZZ_CHECK(std::isfinite(clip.frame_time_s) && (clip.frame_time_s > 0.0 || (clip.frame_time_s == 0.0 && !file.frame_rate_in_file)));
    FUZZ_CHECK(file.unit.metres > 0.0);
}

std::string describe(const kumite::BvhFile& file) {
    return std::to_string(file.clip.skeleton.joint_count()) + " joints, " + std::to_string(file.clip.frame_count()) +
           " frames, unit " + file.unit.name;
}

void check_strict(const kumite::BvhFile& first, const kumite::BvhFile& second, const std::string& written) {
    const kumite::Skeleton& a = first.clip.skeleton;
    const kumite::Skeleton& b = second.clip.skeleton;
    for (int joint = 0; joint < a.joint_count(); ++joint) {
        FUZZ_CHECK(a.names[joint] == b.names[joint], "'" + a.names[joint] + "' became '" + b.names[joint] + "'");
        FUZZ_CHECK(a.parents[joint] == b.parents[joint]);
        const kumite::BvhJointChannels& ca = first.layout.joints[joint];
        const kumite::BvhJointChannels& cb = second.layout.joints[joint];
        FUZZ_CHECK(ca.count == cb.count);
        for (int i = 0; i < ca.count; ++i) FUZZ_CHECK(ca.channels[i] == cb.channels[i]);
    }
    FUZZ_CHECK(a.end_sites.size() == b.end_sites.size());
    FUZZ_CHECK(first.unit.name == second.unit.name, first.unit.name + " became " + second.unit.name + "\n" + written);
    FUZZ_CHECK(std::abs(first.clip.frame_time_s - second.clip.frame_time_s) <= 1e-9 * first.clip.frame_time_s);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > k_max_input_bytes) return -1; // -1: libFuzzer keeps it out of the corpus
    const std::string_view text(reinterpret_cast<const char*>(data), size);

    kumite::Result<kumite::BvhFile> first = kumite::bvh_parse(text, "fuzz-input");
    if (!first) {
        FUZZ_CHECK(!first.error().message.empty());
        return 0;
    }
    check_invariants(*first);

    const std::string written = kumite::bvh_write_string(first->clip, first->layout, first->unit);
    kumite::Result<kumite::BvhFile> second = kumite::bvh_parse(written, "fuzz-rewrite");
    FUZZ_CHECK(second.has_value(), "re-parse of the written file failed: " + second.error().message + "\n" +
                                       "first parse: " + describe(*first) + "\n--- written ---\n" + written.substr(0, 4096));
    check_invariants(*second);
    FUZZ_CHECK(second->clip.skeleton.joint_count() == first->clip.skeleton.joint_count(),
               describe(*first) + " became " + describe(*second));
    FUZZ_CHECK(second->clip.frame_count() == first->clip.frame_count(), describe(*first) + " became " + describe(*second));
    if (strict_mode()) check_strict(*first, *second, written.substr(0, 4096));
    return 0;
}
