#include "bake_sources.h"

#include "parallel_for.h"

#include "kumite/core/root_from_feet.h"
#include "kumite/formats/capture_file.h"

#include <cstdio>

#include <map>
#include <mutex>

namespace kumite::bake {
namespace {

std::filesystem::path resolve(const std::string& source, const std::filesystem::path& mocap_root) {
    const std::filesystem::path path(source);
    return path.is_absolute() ? path : mocap_root / path;
}

bool same_skeleton(const Skeleton& a, const Skeleton& b) {
    if (a.joint_count() != b.joint_count()) return false;
    for (int joint = 0; joint < a.joint_count(); ++joint) {
        if (a.names[joint] != b.names[joint] || a.parents[joint] != b.parents[joint]) return false;
        if ((a.rest_offsets[joint] - b.rest_offsets[joint]).norm() > 1e-6) return false;
    }
    return true;
}

std::string first_clip_using(const RawAnnotations& annotations, const std::string& source) {
    for (size_t index = 0; index < annotations.clips.size(); ++index) {
        if (annotations.clips[index].source == source) return "clip " + std::to_string(index) + " (" + annotations.clips[index].name + ")";
    }
    return "a clip";
}

} // namespace

Result<std::vector<BakeSource>> bake_read_sources(const RawAnnotations& annotations, std::string_view annotations_name,
                                                  const BakeOptions& options, int jobs, const std::function<void(int, int)>& on_done) {
    std::vector<BakeSource> sources;
    std::map<std::string, int> index_of;
    std::vector<bool> mirrored;
    for (const RawAnnotatedClip& clip : annotations.clips) {
        auto [it, inserted] = index_of.emplace(clip.source, static_cast<int>(sources.size()));
        if (inserted) {
            sources.push_back({clip.source, resolve(clip.source, options.mocap_root), {}, {}, {}, -1, {}});
            mirrored.push_back(false);
        }
        if (clip.mirror) mirrored[it->second] = true;
    }
    const int total = static_cast<int>(sources.size());
    std::vector<std::optional<Error>> errors(total);
    std::mutex mutex;
    int done = 0;
    parallel_for(total, jobs, [&](int index) {
        BakeSource& source = sources[index];
        const std::string where = std::string(annotations_name) + ": " + first_clip_using(annotations, source.name) + ": ";
        auto fail = [&](const std::string& what) { errors[index] = make_error(ErrorCode::invalid, where + what); };
        BvhReadOptions read;
        if (const auto rate = annotations.capture_fps.find(source.name); rate != annotations.capture_fps.end()) read.frame_rate_hz = rate->second;
        Result<BvhFile> file = capture_read_file(source.path, read);
        if (!file) return fail(file.error().message);
        if (!file->clip.has_frame_rate() && options.capture_fps) {
            read.frame_rate_hz = options.capture_fps;
            file = capture_read_file(source.path, read);
            if (!file) return fail(file.error().message);
        }
        if (!file->clip.has_frame_rate()) {
            return fail(source.path.string() + ": the capture does not say its frame rate (its 'Frame Time' is 0 or missing): set it in the "
                                               "annotation file (\"captures\": {\"" + source.name + "\": {\"fps\": N}}, or in kumite-annotate), "
                                               "or give it to the bake with --fps N");
        }
        source.file = std::move(*file);
        Result<RestAnatomy> anatomy = rest_anatomy_build(source.file.clip, source.file.body_map);
        if (!anatomy) return fail(source.path.string() + ": " + anatomy.error().message);
        source.anatomy = std::move(*anatomy);
        if (root_is_pinned(source.file.clip)) {
            const RootFromFeetReport moved = root_motion_from_feet(source.file.clip, source.anatomy.limbs[int(Limb::leg_l)].extremity,
                                                                    source.anatomy.limbs[int(Limb::leg_r)].extremity);
            if (moved.support_slide_before_m > 0.0) {
                char line[256];
                std::snprintf(line, sizeof line,
                              "the root never moves (the foot it stands on slid %.0f cm); the root now follows the lower foot "
                              "(moving up to %.0f cm)", 100.0 * moved.support_slide_before_m, 100.0 * moved.root_travel_m);
                source.notes.push_back({source.path.string(), line});
            }
        }
        if (mirrored[index]) {
            std::vector<bool> animated;
            for (const BvhJointChannels& joint : source.file.layout.joints) animated.push_back(joint.has_position());
            // Real skeletons are not exact mirror images: CMU subject 14's arms leave the chest 8 degrees apart
            // from their mirror images, its spine leans 4 degrees off the mirror plane. Offsets pair up within
            // 0.15 (about 8.6 degrees of direction); the mirrored clip keeps the skeleton's own small asymmetry.
            Result<MirrorSymmetry> symmetry = mirror_symmetry_find(source.file.clip.skeleton, 1e-3, 0.15, animated);
            if (!symmetry) return fail("cannot mirror " + source.path.string() + ": " + symmetry.error().message);
            source.symmetry = std::move(*symmetry);
        }
        std::lock_guard lock(mutex);
        if (on_done) on_done(++done, total);
    });
    for (const std::optional<Error>& error : errors) {
        if (error) return *error;
    }
    return sources;
}

std::vector<BakeActor> bake_find_actors(std::vector<BakeSource>& sources) {
    std::vector<BakeActor> actors;
    std::map<std::string, int> folder_uses;
    for (int index = 0; index < static_cast<int>(sources.size()); ++index) {
        BakeSource& source = sources[index];
        for (int actor = 0; actor < static_cast<int>(actors.size()); ++actor) {
            if (same_skeleton(sources[actors[actor].first_source].file.clip.skeleton, source.file.clip.skeleton)) {
                source.actor = actor;
                break;
            }
        }
        if (source.actor >= 0) continue;
        std::string folder = std::filesystem::path(source.name).parent_path().filename().string();
        if (folder.empty()) folder = std::filesystem::path(source.name).stem().string();
        const int uses = ++folder_uses[folder];
        source.actor = static_cast<int>(actors.size());
        actors.push_back({uses == 1 ? folder : folder + "-" + std::to_string(uses), index});
    }
    return actors;
}

DbActor bake_actor_record(const BakeSource& source) {
    const RestAnatomy& anatomy = source.anatomy;
    DbActor actor;
    actor.leg_length_m = static_cast<float>(anatomy.leg_length);
    actor.arm_length_m = static_cast<float>(0.5 * (anatomy.limbs[int(Limb::arm_l)].length() + anatomy.limbs[int(Limb::arm_r)].length()));
    actor.height_m = static_cast<float>(source.file.height_m);
    actor.ankle_height_m = static_cast<float>(anatomy.ankle_height);
    return actor;
}

} // namespace kumite::bake
