// MIR encode + decode cost per frame: for each source capture and each character, MirEncoder::encode and
// MirDecoder::decode on every frame (one MirFrame and one Pose reused, warmed up by one untimed pass), many
// repetitions, against a naive baseline measured in the same run (copy the source local rotation of each
// same-named target joint, identity otherwise, then forward_kinematics on the target).
//
// Heap allocations inside the timed encode/decode calls are counted by replacing the global operator new /
// delete in this executable (the encoder and decoder promise not to allocate). To find an allocating call,
// break on kumite_bench_allocation_in_measured_loop in gdb and ask for a backtrace.
//
// usage: mir_bench [CAPTURE.bvh ...] [--repeats N] [--character NAME ...] [--characters-dir DIR]
//        default captures: bandai-namco-1/dataset-1_walk_normal_001.bvh and dataset-1_kick_normal_001.bvh under
//        $KUMITE_MOCAP_ROOT or data/mocap; relative capture paths are also tried under that root.
//        default characters: every .bvh under $KUMITE_CHARACTERS_DIR or data/characters.
// Prints one JSON document.

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/mir.h"
#include "kumite/core/rest_anatomy.h"
#include "kumite/formats/body_map_file.h"
#include "kumite/formats/bvh_reader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

// ---- allocation counting (thread-unsafe on purpose: the measured loop is single-threaded) -----------------------

namespace {
bool g_counting = false;
std::uint64_t g_allocations = 0;
std::uint64_t g_deallocations = 0;
} // namespace

// A breakpoint target: called for every allocation made while counting.
extern "C" __attribute__((noinline)) void kumite_bench_allocation_in_measured_loop(std::size_t size) {
    asm volatile("" : : "r"(size) : "memory");
}

namespace {
inline void note_allocation(std::size_t size) {
    if (g_counting) {
        ++g_allocations;
        kumite_bench_allocation_in_measured_loop(size);
    }
}
inline void note_deallocation(void* pointer) {
    if (g_counting && pointer) ++g_deallocations;
}
void* allocate(std::size_t size) {
    note_allocation(size);
    if (void* pointer = std::malloc(size ? size : 1)) return pointer;
    throw std::bad_alloc();
}
void* allocate_aligned(std::size_t size, std::align_val_t alignment) {
    note_allocation(size);
    const std::size_t align = std::max(static_cast<std::size_t>(alignment), sizeof(void*));
    const std::size_t rounded = (std::max<std::size_t>(size, 1) + align - 1) / align * align;
    if (void* pointer = std::aligned_alloc(align, rounded)) return pointer;
    throw std::bad_alloc();
}
void deallocate(void* pointer) noexcept {
    note_deallocation(pointer);
    std::free(pointer);
}
} // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try { return allocate(size); } catch (...) { return nullptr; }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try { return allocate(size); } catch (...) { return nullptr; }
}
void* operator new(std::size_t size, std::align_val_t alignment) { return allocate_aligned(size, alignment); }
void* operator new[](std::size_t size, std::align_val_t alignment) { return allocate_aligned(size, alignment); }
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    try { return allocate_aligned(size, alignment); } catch (...) { return nullptr; }
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    try { return allocate_aligned(size, alignment); } catch (...) { return nullptr; }
}
void operator delete(void* pointer) noexcept { deallocate(pointer); }
void operator delete[](void* pointer) noexcept { deallocate(pointer); }
void operator delete(void* pointer, std::size_t) noexcept { deallocate(pointer); }
void operator delete[](void* pointer, std::size_t) noexcept { deallocate(pointer); }
void operator delete(void* pointer, const std::nothrow_t&) noexcept { deallocate(pointer); }
void operator delete[](void* pointer, const std::nothrow_t&) noexcept { deallocate(pointer); }
void operator delete(void* pointer, std::align_val_t) noexcept { deallocate(pointer); }
void operator delete[](void* pointer, std::align_val_t) noexcept { deallocate(pointer); }
void operator delete(void* pointer, std::size_t, std::align_val_t) noexcept { deallocate(pointer); }
void operator delete[](void* pointer, std::size_t, std::align_val_t) noexcept { deallocate(pointer); }
void operator delete(void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { deallocate(pointer); }
void operator delete[](void* pointer, std::align_val_t, const std::nothrow_t&) noexcept { deallocate(pointer); }

// ---- the benchmark -----------------------------------------------------------------------------------------------

namespace {

using Clock = std::chrono::steady_clock;

double us_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::micro>(b - a).count(); }

std::filesystem::path mocap_root() {
    const char* env = std::getenv("KUMITE_MOCAP_ROOT");
    return env && *env ? std::filesystem::path(env) : std::filesystem::path("data/mocap");
}

std::filesystem::path characters_dir() {
    const char* env = std::getenv("KUMITE_CHARACTERS_DIR");
    return env && *env ? std::filesystem::path(env) : std::filesystem::path("data/characters");
}

std::filesystem::path resolve_capture(const std::filesystem::path& path) {
    std::error_code error;
    if (std::filesystem::exists(path, error) || path.is_absolute()) return path;
    const std::filesystem::path under_root = mocap_root() / path;
    return std::filesystem::exists(under_root, error) ? under_root : path;
}

// Reads a BVH, applying a `.bodymap.json` sidecar when there is one (as the command-line tools do).
kumite::BvhFile load(const std::filesystem::path& path) {
    kumite::Result<kumite::BvhFile> file = kumite::bvh_read_file(path);
    if (!file) {
        std::cerr << "mir_bench: " << file.error().message << "\n";
        std::exit(1);
    }
    std::error_code error;
    if (const std::filesystem::path sidecar = kumite::body_map_sidecar_path(path); std::filesystem::exists(sidecar, error)) {
        kumite::Result<kumite::BodyMap> map = kumite::body_map_apply_override_file(file->body_map, file->clip.skeleton, sidecar);
        if (!map) {
            std::cerr << "mir_bench: " << map.error().message << "\n";
            std::exit(1);
        }
        file->body_map = *map;
    }
    return std::move(*file);
}

kumite::RestAnatomy anatomy_of(const kumite::BvhFile& file, const std::string& what) {
    kumite::Result<kumite::RestAnatomy> anatomy = kumite::rest_anatomy_build(file.clip, file.body_map);
    if (!anatomy) {
        std::cerr << "mir_bench: " << what << ": " << anatomy.error().message << "\n";
        std::exit(1);
    }
    return std::move(*anatomy);
}

struct Percentiles {
    double median = 0.0;
    double p99 = 0.0;
};

Percentiles percentiles(std::vector<double>& values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t p99 = std::min(values.size() - 1, static_cast<size_t>(std::ceil(0.99 * values.size())) - 1);
    return {values[values.size() / 2], values[p99]};
}

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) out += ' ';
        else out += c;
    }
    return out + "\"";
}

struct Character {
    std::string name;
    kumite::BvhFile file;
    kumite::RestAnatomy anatomy;
};

struct CharacterResult {
    std::string name;
    int joints = 0;
    Percentiles encode_decode;
    Percentiles encode;
    Percentiles decode;
    Percentiles baseline;
    std::uint64_t encode_allocations = 0;
    std::uint64_t decode_allocations = 0;
    std::uint64_t deallocations = 0;
    std::uint64_t calls = 0; // frames x repeats
    int baseline_matched_joints = 0;
};

CharacterResult run_character(const kumite::BvhFile& source, const kumite::RestAnatomy& source_anatomy, const Character& character,
                              int repeats, volatile double& sink) {
    const kumite::Clip& clip = source.clip;
    const kumite::Skeleton& target = character.file.clip.skeleton;
    const int frames = clip.frame_count();
    const size_t samples = static_cast<size_t>(frames) * repeats;
    CharacterResult result;
    result.name = character.name;
    result.joints = target.joint_count();
    result.calls = samples;

    kumite::MirEncoder encoder(clip.skeleton, source_anatomy);
    kumite::MirDecoder decoder(target, character.anatomy, clip.skeleton.names);
    kumite::MirFrame mir;
    kumite::Pose pose;
    std::vector<double> total_us(samples), encode_us(samples), decode_us(samples), baseline_us(samples);

    // Warm-up: one untimed pass sizes the MirFrame and the Pose and warms caches and branch predictors.
    for (int frame = 0; frame < frames; ++frame) {
        encoder.encode(mir, clip.pose(frame));
        decoder.decode(pose, mir);
    }

    size_t sample = 0;
    for (int repeat = 0; repeat < repeats; ++repeat) {
        for (int frame = 0; frame < frames; ++frame, ++sample) {
            const kumite::PoseView view = clip.pose(frame);
            const Clock::time_point t0 = Clock::now();
            g_counting = true;
            const std::uint64_t before_encode = g_allocations;
            encoder.encode(mir, view);
            const std::uint64_t after_encode = g_allocations;
            const Clock::time_point t1 = Clock::now();
            decoder.decode(pose, mir);
            const Clock::time_point t2 = Clock::now();
            g_counting = false;
            result.encode_allocations += after_encode - before_encode;
            result.decode_allocations += g_allocations - after_encode;
            encode_us[sample] = us_between(t0, t1);
            decode_us[sample] = us_between(t1, t2);
            total_us[sample] = us_between(t0, t2);
            sink = sink + pose.root_translation.x();
        }
    }
    result.deallocations = g_deallocations;
    g_deallocations = 0;

    // Baseline: rotation copy by joint name, then forward kinematics on the target. Set-up not timed.
    std::vector<int> same_name(target.joint_count(), -1);
    for (int joint = 0; joint < target.joint_count(); ++joint) {
        if (const std::optional<int> found = clip.skeleton.find(target.names[joint])) {
            same_name[joint] = *found;
            ++result.baseline_matched_joints;
        }
    }
    kumite::Pose copied;
    copied.local_rotations.assign(target.joint_count(), Eigen::Quaterniond::Identity());
    std::vector<Eigen::Vector3d> positions(target.joint_count());
    std::vector<Eigen::Quaterniond> rotations(target.joint_count());
    auto naive_retarget = [&](const kumite::PoseView& view) {
        for (int joint = 0; joint < target.joint_count(); ++joint) {
            copied.local_rotations[joint] = same_name[joint] >= 0 ? view.local_rotations[same_name[joint]] : Eigen::Quaterniond::Identity();
        }
        copied.root_translation = view.root_translation;
        kumite::forward_kinematics(positions, rotations, target, copied.view());
    };
    for (int frame = 0; frame < frames; ++frame) naive_retarget(clip.pose(frame));
    sample = 0;
    for (int repeat = 0; repeat < repeats; ++repeat) {
        for (int frame = 0; frame < frames; ++frame, ++sample) {
            const kumite::PoseView view = clip.pose(frame);
            const Clock::time_point t0 = Clock::now();
            naive_retarget(view);
            const Clock::time_point t1 = Clock::now();
            baseline_us[sample] = us_between(t0, t1);
            sink = sink + positions.back().x();
        }
    }

    result.encode_decode = percentiles(total_us);
    result.encode = percentiles(encode_us);
    result.decode = percentiles(decode_us);
    result.baseline = percentiles(baseline_us);
    return result;
}

// The cost of one Clock::now() pair, included in every sample above.
double timer_overhead_us() {
    std::vector<double> values(100000);
    for (double& value : values) {
        const Clock::time_point t0 = Clock::now();
        const Clock::time_point t1 = Clock::now();
        value = us_between(t0, t1);
    }
    return percentiles(values).median;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> captures;
    std::vector<std::string> only;
    std::filesystem::path characters_folder = characters_dir();
    int repeats = 200;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
        else if (argument == "--character" && i + 1 < argc) only.emplace_back(argv[++i]);
        else if (argument == "--characters-dir" && i + 1 < argc) characters_folder = argv[++i];
        else if (argument == "--help") {
            std::cout << "usage: mir_bench [CAPTURE.bvh ...] [--repeats N] [--character NAME ...] [--characters-dir DIR]\n"
                         "  default captures: bandai-namco-1/dataset-1_{walk,kick}_normal_001.bvh under $KUMITE_MOCAP_ROOT or data/mocap\n"
                         "  default characters: every .bvh under $KUMITE_CHARACTERS_DIR or data/characters\n"
                         "  prints one JSON document; times in microseconds per frame\n";
            return 0;
        } else if (!argument.empty() && argument[0] == '-') {
            std::cerr << "mir_bench: unknown option " << argument << " (see --help)\n";
            return 2;
        } else captures.push_back(resolve_capture(argument));
    }
    if (captures.empty()) {
        captures.push_back(mocap_root() / "bandai-namco-1/dataset-1_walk_normal_001.bvh");
        captures.push_back(mocap_root() / "bandai-namco-1/dataset-1_kick_normal_001.bvh");
    }
    for (const std::filesystem::path& capture : captures) {
        std::error_code error;
        if (!std::filesystem::exists(capture, error)) {
            std::cerr << "mir_bench: no capture at " << capture.string() << " (set KUMITE_MOCAP_ROOT or pass a path)\n";
            return 1;
        }
    }

    std::vector<std::filesystem::path> character_files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(characters_folder, error)) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".bvh" && (only.empty() || std::find(only.begin(), only.end(), stem) != only.end())) {
            character_files.push_back(entry.path());
        }
    }
    std::sort(character_files.begin(), character_files.end());
    if (character_files.empty()) {
        std::cerr << "mir_bench: no characters found in " << characters_folder.string() << " (set KUMITE_CHARACTERS_DIR)\n";
        return 1;
    }
    std::vector<Character> characters;
    for (const std::filesystem::path& path : character_files) {
        kumite::BvhFile file = load(path);
        kumite::RestAnatomy anatomy = anatomy_of(file, "character " + path.stem().string());
        characters.push_back({path.stem().string(), std::move(file), std::move(anatomy)});
    }

    volatile double sink = 0.0;
    std::ostringstream out;
    out << std::fixed << std::setprecision(3);
    out << "{\"benchmark\": \"mir_encode_decode\", \"unit\": \"us_per_frame\", \"repeats\": " << repeats
        << ", \"timer_overhead_us\": " << timer_overhead_us() << ", \"sources\": [";
    for (size_t s = 0; s < captures.size(); ++s) {
        const kumite::BvhFile source = load(captures[s]);
        const kumite::RestAnatomy source_anatomy = anatomy_of(source, captures[s].string());
        out << (s ? ", " : "") << "{\"source\": " << json_string(captures[s].string()) << ", \"frames\": " << source.clip.frame_count()
            << ", \"joints\": " << source.clip.skeleton.joint_count() << ", \"characters\": [";
        for (size_t c = 0; c < characters.size(); ++c) {
            const CharacterResult r = run_character(source, source_anatomy, characters[c], repeats, sink);
            const double calls = static_cast<double>(std::max<std::uint64_t>(r.calls, 1));
            out << (c ? ", " : "") << "{\"name\": " << json_string(r.name) << ", \"joints\": " << r.joints
                << ", \"encode_decode_us\": {\"median\": " << r.encode_decode.median << ", \"p99\": " << r.encode_decode.p99
                << "}, \"encode_us_median\": " << r.encode.median << ", \"decode_us_median\": " << r.decode.median
                << ", \"allocations_per_frame\": " << std::defaultfloat
                << static_cast<double>(r.encode_allocations + r.decode_allocations) / calls << std::fixed
                << ", \"allocations\": {\"encode\": " << r.encode_allocations << ", \"decode\": " << r.decode_allocations
                << ", \"frees\": " << r.deallocations << ", \"frames_timed\": " << r.calls << "}"
                << ", \"baseline_us\": {\"name\": \"rotation copy by joint name + forward_kinematics\", \"median\": " << r.baseline.median
                << ", \"p99\": " << r.baseline.p99 << ", \"matched_joints\": " << r.baseline_matched_joints
                << "}, \"ratio_to_baseline\": " << (r.baseline.median > 0.0 ? r.encode_decode.median / r.baseline.median : 0.0) << "}";
        }
        out << "]}";
    }
    out << "]}\n";
    std::cout << out.str();
    return 0;
}
