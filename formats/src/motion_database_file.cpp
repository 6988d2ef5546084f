#include "kumite/formats/motion_database_file.h"

#include <cmath>
#include <cstring>
#include <type_traits>

namespace kumite {
namespace {

static_assert(sizeof(DbMeta) == 32 && sizeof(DbActor) == 24 && sizeof(DbClip) == 84 && sizeof(DbPose) == 60 &&
                  sizeof(DbCluster) == 16 && sizeof(DbMirFrame) == 4 * (4 + 4 * k_body_part_count + 10 * k_max_chain_joints + 2 + 4 * k_limb_count),
              "records have no padding: their bytes are the file's bytes");
static_assert(std::is_trivially_copyable_v<DbMirFrame> && std::is_trivially_copyable_v<DbClip>);

template <class T>
void add(DatabaseImageBuilder& builder, std::uint32_t tag, std::span<const T> items) {
    builder.add_section(tag, sizeof(T), std::as_bytes(items));
}

// Checks that run over one section's records, each failure at the byte of the offending record.
class Checker {
public:
    Checker(std::string_view source, const DatabaseImage& image) : m_source(source), m_image(image) {}

    // The section's records, or an error when it is missing or holds records of another size.
    template <class T>
    Result<std::span<const T>> records(std::uint32_t tag) {
        const DatabaseSection* section = m_image.find(tag);
        if (!section) return fail(0, "no " + section_tag_name(tag) + " section (not a motion database, or a damaged one)");
        if (section->element_size != sizeof(T)) {
            return fail(section->offset, section_tag_name(tag) + " records are " + std::to_string(section->element_size) +
                                             " bytes, this kumite reads " + std::to_string(sizeof(T)));
        }
        return std::span<const T>(reinterpret_cast<const T*>(section->bytes.data()), section->count);
    }

    Error fail(std::uint64_t byte, const std::string& what) const {
        return make_error(ErrorCode::invalid, std::string(m_source) + ": byte " + std::to_string(byte) + ": " + what);
    }
    template <class T>
    Error fail_at(std::uint32_t tag, std::size_t index, const std::string& what) const {
        const DatabaseSection* section = m_image.find(tag);
        return fail(section->offset + index * sizeof(T), section_tag_name(tag) + " " + std::to_string(index) + ": " + what);
    }

private:
    std::string_view m_source;
    const DatabaseImage& m_image;
};

bool finite(std::span<const float> values) {
    for (float v : values) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}
template <std::size_t N>
bool finite(const float (&values)[N]) {
    return finite(std::span<const float>(values, N));
}

std::string range(std::uint64_t value, std::uint64_t count, const char* what) {
    return std::to_string(value) + " is out of range (" + std::to_string(count) + " " + what + ")";
}

Result<void> check_content(const MotionDatabaseView& db, const Checker& check) {
    const auto string_ok = [&](DbString s) { return std::uint64_t(s.offset) + s.length <= db.strings.size(); };
    const DbMeta& meta = db.meta;
    if (!(meta.frame_time_s > 0.0f && meta.frame_time_s <= 1.0f) || meta.feature_dimensions != k_feature_dimensions ||
        meta.feature_parts != k_feature_point_count || meta.feature_stride < 1 || meta.feature_stride > 1000) {
        return check.fail_at<DbMeta>(k_section_meta, 0, "frame time, feature layout or stride is not one this kumite reads");
    }
    for (std::size_t a = 0; a < db.actors.size(); ++a) {
        const DbActor& actor = db.actors[a];
        if (!string_ok(actor.name)) return check.fail_at<DbActor>(k_section_actors, a, "name is outside the string table");
        const float sizes[] = {actor.leg_length_m, actor.arm_length_m, actor.height_m, actor.ankle_height_m};
        if (!finite(sizes) || actor.leg_length_m <= 0.0f || actor.arm_length_m <= 0.0f) {
            return check.fail_at<DbActor>(k_section_actors, a, "sizes must be finite and positive");
        }
    }
    std::uint64_t next_pose = 0;
    for (std::size_t c = 0; c < db.clips.size(); ++c) {
        const DbClip& clip = db.clips[c];
        auto fail = [&](const std::string& what) { return check.fail_at<DbClip>(k_section_clips, c, what); };
        if (!string_ok(clip.name) || !string_ok(clip.semantics) || !string_ok(clip.source)) return fail("a name is outside the string table");
        if (clip.actor >= db.actors.size()) return fail("actor " + range(clip.actor, db.actors.size(), "actors"));
        if (clip.frame_count == 0 || clip.first_pose != next_pose || next_pose + clip.frame_count > db.poses.size()) {
            return fail("its poses must follow the previous clip's within the " + std::to_string(db.poses.size()) + " poses");
        }
        next_pose += clip.frame_count;
        if (clip.segment < -1 || clip.segment >= k_body_part_count) return fail("segment " + std::to_string(clip.segment) + " is not a body part");
        if (clip.side > 2) return fail("side " + std::to_string(clip.side) + " is not none, left or right");
        if (clip.hit_frame < -1 || clip.hit_frame >= static_cast<std::int64_t>(clip.frame_count)) {
            return fail("hit frame " + range(std::uint64_t(std::int64_t(clip.hit_frame)), clip.frame_count, "frames"));
        }
        if (db_clip_is_strike(clip) && (clip.hit_frame < 0 || clip.segment < 0)) return fail("a strike without hit frame or segment");
        if (!finite(clip.box_min) || !finite(clip.box_max)) return fail("its box is not finite");
        if (clip.kind >= k_strike_kind_count) return fail("kind " + std::to_string(clip.kind) + " is not a strike kind");
        if (clip.height >= k_strike_height_count) return fail("height " + std::to_string(clip.height) + " is not low, middle or high");
        if (clip.reserved != 0) return fail("its reserved bytes are not 0");
    }
    if (next_pose != db.poses.size()) return check.fail_at<DbClip>(k_section_clips, db.clips.size() - (db.clips.empty() ? 0 : 1),
                                                                    "clips cover " + std::to_string(next_pose) + " of " +
                                                                        std::to_string(db.poses.size()) + " poses");
    for (std::size_t p = 0; p < db.poses.size(); ++p) {
        const DbPose& pose = db.poses[p];
        if (pose.clip >= db.clips.size() || db.clips[pose.clip].first_pose + pose.frame != p) {
            return check.fail_at<DbPose>(k_section_poses, p, "clip and frame do not match the clip table");
        }
        if (!finite(pose.heading) || !finite(pose.hit_point) || !finite(pose.start_box_min) || !finite(pose.start_box_max)) {
            return check.fail_at<DbPose>(k_section_poses, p, "a value is not finite");
        }
    }
    if (db.mir_frames.size() != db.poses.size()) {
        return check.fail_at<DbMirFrame>(k_section_mir_frames, 0, std::to_string(db.mir_frames.size()) + " frames for " +
                                                                      std::to_string(db.poses.size()) + " poses");
    }
    for (std::size_t p = 0; p < db.mir_frames.size(); ++p) {
        const DbMirFrame& frame = db.mir_frames[p];
        if (frame.spine_count > k_max_chain_joints || frame.neck_count > k_max_chain_joints) {
            return check.fail_at<DbMirFrame>(k_section_mir_frames, p, "a trunk chain is longer than " + std::to_string(k_max_chain_joints));
        }
        if (!finite(frame.hip_centre) || !finite(std::span<const float>(&frame.part_frames[0][0], sizeof(frame.part_frames) / 4)) ||
            !finite(std::span<const float>(&frame.spine[0][0], sizeof(frame.spine) / 4)) ||
            !finite(std::span<const float>(&frame.neck[0][0], sizeof(frame.neck) / 4)) ||
            !finite(std::span<const float>(&frame.extremity[0][0], sizeof(frame.extremity) / 4)) || !finite(frame.swivel)) {
            return check.fail_at<DbMirFrame>(k_section_mir_frames, p, "a value is not finite");
        }
    }
    if (db.features.size() != db.poses.size() * k_feature_dimensions) {
        return check.fail_at<float>(k_section_features, 0, "holds " + std::to_string(db.features.size()) + " values, not " +
                                                               std::to_string(db.poses.size()) + " poses x " + std::to_string(k_feature_dimensions));
    }
    if (db.centroids.size() != db.clusters.size() * k_feature_dimensions) {
        return check.fail_at<float>(k_section_centroids, 0, "holds " + std::to_string(db.centroids.size()) + " values, not " +
                                                                std::to_string(db.clusters.size()) + " clusters x " + std::to_string(k_feature_dimensions));
    }
    for (auto [tag, values] : {std::pair{k_section_features, db.features}, std::pair{k_section_centroids, db.centroids}}) {
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!std::isfinite(values[i])) return check.fail_at<float>(tag, i, "not a finite number");
        }
    }
    std::uint64_t next_member = 0;
    for (std::size_t c = 0; c < db.clusters.size(); ++c) {
        const DbCluster& cluster = db.clusters[c];
        if (cluster.first_member != next_member || next_member + cluster.member_count > db.members.size() || !std::isfinite(cluster.radius)) {
            return check.fail_at<DbCluster>(k_section_clusters, c, "members must follow the previous cluster's within the " +
                                                                       std::to_string(db.members.size()) + " members");
        }
        next_member += cluster.member_count;
    }
    if (next_member != db.members.size() || db.members.size() != db.poses.size()) {
        return check.fail_at<DbCluster>(k_section_clusters, 0, "clusters hold " + std::to_string(next_member) + " members for " +
                                                                   std::to_string(db.poses.size()) + " poses");
    }
    for (std::size_t m = 0; m < db.members.size(); ++m) {
        if (db.members[m] >= db.poses.size()) {
            return check.fail_at<std::uint32_t>(k_section_members, m, "pose " + range(db.members[m], db.poses.size(), "poses"));
        }
    }
    if (db.poses.empty() || db.clusters.empty()) return check.fail(0, "the database holds no poses or no clusters");
    return {};
}

} // namespace

namespace {

DatabaseImageBuilder image_builder(const MotionDatabaseView& db) {
    DatabaseImageBuilder builder;
    add(builder, k_section_meta, std::span<const DbMeta>(&db.meta, 1));
    add(builder, k_section_strings, db.strings);
    add(builder, k_section_actors, db.actors);
    add(builder, k_section_clips, db.clips);
    add(builder, k_section_poses, db.poses);
    add(builder, k_section_mir_frames, db.mir_frames);
    add(builder, k_section_features, db.features);
    add(builder, k_section_centroids, db.centroids);
    add(builder, k_section_clusters, db.clusters);
    add(builder, k_section_members, db.members);
    return builder;
}

} // namespace

std::vector<std::byte> motion_database_bytes(const MotionDatabaseView& db) { return image_builder(db).build(); }

Result<void> motion_database_write(const std::filesystem::path& path, const MotionDatabaseView& db) {
    return image_builder(db).write_file(path);
}

Result<MotionDatabase> MotionDatabase::open(const std::filesystem::path& path, bool verify_hash) {
    Result<DatabaseImage> image = DatabaseImage::open(path, verify_hash);
    if (!image) return image.error();
    return from_image(std::move(*image), path.string());
}

Result<MotionDatabase> MotionDatabase::from_image(DatabaseImage image, std::string_view source_name) {
    MotionDatabase database;
    database.m_image = std::move(image);
    Checker check(source_name, database.m_image);
    MotionDatabaseView& view = database.m_view;
    auto meta = check.records<DbMeta>(k_section_meta);
    if (!meta) return meta.error();
    if (meta->size() != 1) return check.fail_at<DbMeta>(k_section_meta, 0, "expected one META record, found " + std::to_string(meta->size()));
    view.meta = (*meta)[0];
    auto load = [&]<class T>(std::span<const T>& out, std::uint32_t tag) -> std::optional<Error> {
        auto records = check.records<T>(tag);
        if (!records) return records.error();
        out = *records;
        return std::nullopt;
    };
    if (auto e = load(view.strings, k_section_strings)) return *e;
    if (auto e = load(view.actors, k_section_actors)) return *e;
    if (auto e = load(view.clips, k_section_clips)) return *e;
    if (auto e = load(view.poses, k_section_poses)) return *e;
    if (auto e = load(view.mir_frames, k_section_mir_frames)) return *e;
    if (auto e = load(view.features, k_section_features)) return *e;
    if (auto e = load(view.centroids, k_section_centroids)) return *e;
    if (auto e = load(view.clusters, k_section_clusters)) return *e;
    if (auto e = load(view.members, k_section_members)) return *e;
    if (Result<void> content = check_content(view, check); !content) return content.error();
    return database;
}

} // namespace kumite
