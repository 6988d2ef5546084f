#pragma once
// The baked motion database as the runtime sees it: fixed-size records in spans, over a mapped `.kdb` file or
// over the vectors a bake fills. Records hold only 32-bit floats and integers (little-endian on disk), indices
// into other spans and string references into one table; no pointers. formats/motion_database_file.h writes and
// opens the file: opening checks the structure (every span size, string reference, actor index, clip pose range and
// cluster member range), verify() the per-pose values (a pose record's clip and frame, members, finite floats), which
// readers of an unverified view bound where they use them. Layout byte by byte: formats/README.md.
//
// Lengths are the actor's metres (each clip's actor is recorded with its sizes) except where a name says
// `normalised` (divided by the actor's leg length). "Clip world" is the capture's world with its floor moved to
// y = 0 (heading frames have their origin on it). Poses are numbered across the whole database: clip c owns
// poses first_pose .. first_pose + frame_count - 1, all sampled at the database's frame time.

#include "kumite/core/body_map.h"
#include "kumite/core/mir.h"
#include "kumite/core/strike_labels.h"

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace kumite {

// Feature points: the body parts whose positions make a pose's point cloud (Kovar's distance and the clusters).
inline constexpr std::array<BodyPart, 13> k_feature_parts = {
    BodyPart::pelvis,      BodyPart::chest,     BodyPart::head,      BodyPart::upper_arm_l, BodyPart::forearm_l,
    BodyPart::hand_l,      BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r,    BodyPart::shin_l,
    BodyPart::foot_l,      BodyPart::shin_r,    BodyPart::foot_r};
inline constexpr int k_feature_point_count = static_cast<int>(k_feature_parts.size());
inline constexpr int k_feature_window = 3; // frames per feature: t - 2 stride, t - stride, t
inline constexpr int k_feature_cloud_size = k_feature_point_count * k_feature_window; // 39 points
// A feature is planar, for SIMD: 40 x values (the 39 points, point = sample * 13 + part, then a 0), 40 y, 40 z.
inline constexpr int k_feature_axis_stride = 40;
inline constexpr int k_feature_dimensions = 3 * k_feature_axis_stride;
static_assert(k_feature_axis_stride >= k_feature_cloud_size && k_feature_axis_stride % 8 == 0);

struct DbString {
    std::uint32_t offset = 0; // into the string table
    std::uint32_t length = 0;
};

// META: one record.
struct DbMeta {
    float frame_time_s = 0.0f;          // of every clip
    std::uint32_t feature_stride = 0;   // frames between the window's samples
    std::uint32_t feature_dimensions = k_feature_dimensions;
    std::uint32_t feature_parts = k_feature_point_count;
    std::uint64_t cluster_seed = 0;
    std::uint32_t kmeans_iterations = 0;
    float cluster_inertia = 0.0f;       // sum over poses of the Kovar distance to their centroid
};

// ACTR: the captured performers, one per distinct skeleton.
struct DbActor {
    DbString name;
    float leg_length_m = 0.0f;          // mean thigh + shin
    float arm_length_m = 0.0f;          // mean upper arm + forearm
    float height_m = 0.0f;              // standing height
    float ankle_height_m = 0.0f;        // flat-footed ankle above the floor
};

enum DbClipFlags : std::uint32_t {
    db_clip_mirrored = 1u << 0, // the annotated motion reflected left <-> right
    db_clip_strike = 1u << 1,   // a strike: segment, side and hit frame are meaningful
};

// CLIP
struct DbClip {
    DbString name;
    DbString semantics;                 // punch, kick, reach, rest, step_forward, ...
    DbString source;                    // the capture, as annotated
    std::uint32_t actor = 0;
    std::uint32_t first_pose = 0;
    std::uint32_t frame_count = 0;
    std::int32_t segment = -1;          // BodyPart of the hit segment, -1 for non-strikes
    std::uint32_t side = 0;             // Side
    std::uint32_t flags = 0;            // DbClipFlags
    std::int32_t hit_frame = -1;        // clip frame of the hit, -1 for non-strikes
    std::uint32_t source_first_frame = 0; // capture frame of clip frame 0
    float box_min[3] = {0, 0, 0};       // the hit trajectory's box over every start, start's heading frame, metres
    float box_max[3] = {0, 0, 0};
    std::uint8_t kind = 0;              // StrikeKind (strike_labels.h), 0: unlabelled
    std::uint8_t height = 0;            // StrikeHeight, 0: unlabelled
    std::uint16_t reserved = 0;

    StrikeKind strike_kind() const { return static_cast<StrikeKind>(kind); }
    StrikeHeight strike_height() const { return static_cast<StrikeHeight>(height); }
};

enum DbPoseFlags : std::uint32_t {
    db_pose_left_foot_planted = 1u << 0,
    db_pose_right_foot_planted = 1u << 1,
};

// POSE: per pose, where it is and, for strike clips, where the hit segment goes from here.
struct DbPose {
    std::uint32_t clip = 0;
    std::uint32_t frame = 0;            // in its clip
    std::uint32_t flags = 0;            // DbPoseFlags
    float heading[3] = {0, 0, 0};       // origin x, origin z and yaw of the pose's heading frame, clip world
    float hit_point[3] = {0, 0, 0};     // the hit segment's joint, clip world, metres (strikes)
    float start_box_min[3] = {0, 0, 0}; // box of the hit path from this pose to the hit frame, in this pose's
    float start_box_max[3] = {0, 0, 0}; // heading frame; empty (min > max) at and after the hit frame
};

// MIRF: per pose, the morphology-independent representation (mir.h), float.
struct DbMirFrame {
    float hip_centre[3] = {0, 0, 0};
    std::uint32_t part_mask = 0;        // bit p: part p present
    float part_frames[k_body_part_count][4] = {}; // x y z w
    float spine[k_max_chain_joints][4] = {};
    float neck[k_max_chain_joints][4] = {};
    float spine_fractions[k_max_chain_joints] = {};
    float neck_fractions[k_max_chain_joints] = {};
    std::uint32_t spine_count = 0;
    std::uint32_t neck_count = 0;
    float extremity[k_limb_count][3] = {};
    float swivel[k_limb_count] = {};
};

// CLUS: cluster c owns members first_member .. first_member + member_count - 1 of MEMB.
struct DbCluster {
    std::uint32_t first_member = 0;
    std::uint32_t member_count = 0;
    float radius = 0.0f;                // largest Kovar distance of a member to the centroid
    float reserved = 0.0f;
};

// A view of a whole database. Spans index each other. Opened from a file, the clip table's and cluster table's
// indices are in range; a pose record's clip and frame and the members are in range only once verified: take a
// pose's clip from the clip table (clips tile the poses) and bound a member before following it.
struct MotionDatabaseView {
    DbMeta meta;
    std::span<const char> strings;
    std::span<const DbActor> actors;
    std::span<const DbClip> clips;
    std::span<const DbPose> poses;
    std::span<const DbMirFrame> mir_frames;   // [pose]
    std::span<const float> features;          // [pose * k_feature_dimensions], normalised, heading frame
    std::span<const float> centroids;         // [cluster * k_feature_dimensions]
    std::span<const DbCluster> clusters;
    std::span<const std::uint32_t> members;   // pose indices grouped by cluster

    std::string_view string(DbString reference) const { return {strings.data() + reference.offset, reference.length}; }
    std::span<const float> feature(std::uint32_t pose) const {
        return features.subspan(std::size_t(pose) * k_feature_dimensions, k_feature_dimensions);
    }
    std::span<const float> centroid(std::uint32_t cluster) const {
        return centroids.subspan(std::size_t(cluster) * k_feature_dimensions, k_feature_dimensions);
    }
};

// What a bake produces, owned; view() is what gets written and what the runtime would map.
struct MotionDatabaseContent {
    DbMeta meta;
    std::vector<char> strings;
    std::vector<DbActor> actors;
    std::vector<DbClip> clips;
    std::vector<DbPose> poses;
    std::vector<DbMirFrame> mir_frames;
    std::vector<float> features;
    std::vector<float> centroids;
    std::vector<DbCluster> clusters;
    std::vector<std::uint32_t> members;

    DbString add_string(std::string_view text);
    MotionDatabaseView view() const;
};

// MIR frames in and out of their stored form. The decoded frame has no source local rotations (joints outside
// the body map keep their rest rotation on the character).
void db_mir_frame_store(DbMirFrame& out, const MirFrame& frame);
void db_mir_frame_load(MirFrame& out, const DbMirFrame& stored);

// The first clip whose semantics is `semantics` ("rest", "step_forward", ...), or -1.
int db_first_clip_of(const MotionDatabaseView& db, std::string_view semantics);

// Strike counts by semantics and side, for summaries.
bool db_clip_is_strike(const DbClip& clip);
// Whether a strike clip strikes with an arm (clavicle to hand) rather than a leg.
bool db_clip_is_arm_strike(const DbClip& clip);
// A leg strike's support foot: the DbPoseFlags bit of the other leg's foot, which it stands on; 0 for arm strikes
// and clips that are not strikes.
std::uint32_t db_clip_support_foot(const DbClip& clip);
// Where a strike makes contact (strikes that hit): the first frame, from the farthest its hit point is
// from the annotated hit, where it has covered `extension` of that way (0.9: the limb still travels fast there; the
// hit is annotated at full extension, where it has stopped). 1 or more: the hit frame itself. With `speed_share` > 0,
// earlier still when the hit point slows before that: the last frame, after its fastest on the way, before it
// first moves slower than `speed_share` of that fastest (a punch that decelerates early meets its target while it
// still travels at speed; a knee or elbow, whose joint carries the body behind it, by extension only). -1 for
// non-strikes.
int db_clip_contact_frame(const MotionDatabaseView& db, const DbClip& clip, double extension, double speed_share = 0.0);
// The last frame of a leg strike, up to its hit, where its support foot is planted; -1 when it never is.
int db_clip_support_down_until(const MotionDatabaseView& db, const DbClip& clip);

} // namespace kumite
