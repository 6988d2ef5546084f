#pragma once
// Retrieval (ARCHITECTURE.md step 5): the strike clip and start pose that best suit the character's current pose
// and a target, from a mapped motion database.
//
// Scoring. A candidate is a start pose of a strike clip of the ordered semantics and side, at least
// `min_lead_frames` before its hit frame (or the clip's first pose, when its whole lead is shorter); a leg
// strike's start also needs the character's support foot planted, and the clip's planted there or before the
// hit. Its score is
//     d = w_pose * d_pose + w_target * d_target / leg_length_character
// where d_pose is Kovar's distance between the current pose's feature and the candidate's, as an RMS over the
// feature's points (leg lengths), and d_target the distance in metres between the target and the hit segment's
// point at the clip's contact frame, brought onto the character: expressed in the start's heading frame and
// scaled by size_character / size_actor (the paper's c_r = c * size_actor / size_character, applied to the point
// instead of the target so that distances are the character's). The paper's contact is the annotated hit, at full
// extension where the limb has stopped: a strike adapted there touches its target. Here the contact is a little
// earlier, where the hit point has covered `contact_extension` (0.9) of its way to the hit, or before it first slows
// under `contact_speed_share` (0.85) of its fastest on the way: it still travels fast: the strike arrives at speed and the impact stops it (the paper's d(t_c) = X - M(t_c) at that t_c),
// with the clip's own timing from the start to it.
//
// Search. Candidates are grouped by cluster and order, and each group is a k-d tree (box_tree.h) over two cheap
// lower bounds of a candidate's score: its pose key (pose_embedding.h: Euclidean distances between keys never exceed
// the RMS Kovar distance) and its hit point (d_target is exact and cheap, one point per start). sqrt of Kovar's
// distance is a metric (the minimum over isometries of a Euclidean distance), so |d(q, c) - d(m, c)| bounds d(q, m)
// from below too, for a member m of the cluster with centroid c. Groups are visited best bound first; inside one,
// a node whose box bounds every score below it above the best so far is skipped whole, and the search stops when a
// whole group's bound cannot win. This is the paper's "nearest cluster, then filter by the hit trajectory's
// bounding box (target inside, else nearest boxes)" made exact: the fast path returns what the exhaustive
// reference returns, unless two scores tie.
//
// Queries do not allocate (each thread brings its RetrievalWorkspace) and may run concurrently on one Retriever.

#include "kumite/core/box_tree.h"
#include "kumite/core/heading_frame.h"
#include "kumite/core/hit_trajectory.h"
#include "kumite/core/motion_database.h"
#include "kumite/core/pose_distance.h"
#include "kumite/core/pose_embedding.h"
#include "kumite/core/strike_labels.h"

#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace kumite {

// How a database actor's hit path is brought to a character's size.
enum class RetrievalScaling {
    leg_length,   // by the ratio of leg lengths (thigh + shin), for every strike
    limb_length,  // by the hit segment's limb: arms for hand/forearm strikes, legs for foot/shin strikes
};

struct RetrievalSettings {
    double pose_weight = 1.0;
    double target_weight = 1.0;
    int min_lead_frames = 3; // a start at least this many frames before the contact (0.1 s at 30 fps)
    // The contact: the first frame where the hit point has covered this share of its way to the annotated hit
    // (db_clip_contact_frame), where the limb still travels fast; 1: the annotated hit (full extension, stopped).
    double contact_extension = 0.9;
    // ... or earlier, the last frame before the hit point first slows under this share of its fastest on the way
    // (db_clip_contact_frame): a strike meets its target at speed, not as it stops. 0: by extension alone.
    double contact_speed_share = 0.85;
    // One tree per order (semantics, side, limb) over every cluster's candidates, or one per cluster and order
    // with the triangle inequality through the centroid as one more bound. One tree per order won at 220,000 poses
    // (fewer nodes visited: the upper levels are shared; tests/bench/retrieval_bench.cpp reports both).
    bool trees_per_cluster = false;
    // With trees per cluster, orders with at most this many candidate starts skip the centroid bound: below it,
    // computing every centroid distance costs more than it saves.
    int scan_below = 600;
    // Candidates per leaf: a leaf is read sequentially, a node is a jump in memory; 64 was fastest (8 to 128 measured).
    int leaf_size = 64;
    RetrievalScaling scaling = RetrievalScaling::leg_length;
};

// What the retrieval needs to know about the character.
struct CharacterSize {
    double leg_length_m = 1.0;
    double arm_length_m = 1.0;
};

struct RetrievalQuery {
    std::span<const float> pose_feature; // the current pose (pose_feature_build with the character's leg length)
    HeadingFrame heading;                // the character's current heading frame, world
    Eigen::Vector3d target_world = Eigen::Vector3d::Zero();
    int semantics = -1;                  // Retriever::semantics_id
    Side side = Side::none;              // none: either side
    StrikeKind kind = StrikeKind::none;      // none: any kind (labelled or not)
    StrikeHeight height = StrikeHeight::none; // none: any height
    // Variety: clips not to return (e.g. the last few strikes), and a score the answer must beat (infinity: none).
    // A second query with these finds the best other clip within a margin of the first answer.
    std::span<const int> excluded_clips;
    double score_limit = std::numeric_limits<double>::infinity();
    CharacterSize character;
    // The current motion's planted feet (DbPoseFlags). Support-foot rule: a leg strike is a candidate only when
    // its support foot (the other one) is planted both now and in the clip's start pose, so a kick never starts
    // while its kicking leg carries the weight.
    std::uint32_t planted_feet = db_pose_left_foot_planted | db_pose_right_foot_planted;
};

struct RetrievalCounts {
    int clusters_visited = 0;   // clusters whose members were looked at
    int candidates_seen = 0;    // members of those clusters that obey the order
    int inside_box = 0;         // of those, starts whose hit point is within a tenth of a leg (or arm) of the target
    int nodes_visited = 0;      // tree nodes whose bound was low enough to open
    int pose_scored = 0;        // exact pose distances computed
    int target_scored = 0;      // candidates scored in full
};

struct RetrievalResult {
    bool found = false;
    int clip = -1;
    int start_frame = 0;
    int contact_frame = 0;     // the clip's contact frame (RetrievalSettings::contact_extension)
    double time_to_contact_s = 0.0;
    double d_pose = 0.0;       // RMS over the feature's points, leg lengths
    double d_target_m = 0.0;   // character metres
    double score = 0.0;
    int start_pose = -1;       // database pose index of the start
    // Puts the clip, decoded onto the character, on the current pose: a point p of the decoded clip (character
    // metres, the clip's world scaled to the character) goes to clip_to_world.apply(p).
    FloorAlignment clip_to_world;
    Eigen::Vector3d contact_point_world = Eigen::Vector3d::Zero(); // the scaled, aligned hit point at the contact frame
    RetrievalCounts counts;
};

// Per-thread scratch space of a query (sized once by Retriever::make_workspace; queries then never allocate).
struct RetrievalWorkspace {
    std::vector<std::pair<double, int>> group_order; // (lower bound, group) of the groups a query may visit
    std::vector<double> centroid_distance;           // [cluster] sqrt(Kovar / points)
};

// The floor motion that puts frame `frame` of clip `clip`, decoded on a character of leg length
// `character_leg_m`, onto `heading` (world): its heading frame lands on `heading`. A point p of the decoded clip
// goes to the result's apply(p).
FloorAlignment clip_alignment(const MotionDatabaseView& database, int clip, int frame, double character_leg_m, const HeadingFrame& heading);

class Retriever {
public:
    explicit Retriever(const MotionDatabaseView& database, RetrievalSettings settings = {});

    // The id of a semantics the database holds ("punch"), or -1.
    int semantics_id(std::string_view semantics) const;
    // How many candidate starts the database holds for an order (none: any side, kind or height); 0 means the
    // order cannot be served.
    int candidate_count(int semantics, Side side, StrikeKind kind = StrikeKind::none, StrikeHeight height = StrikeHeight::none) const;
    std::string_view semantics_name(int id) const { return m_semantics_names[id]; }

    RetrievalWorkspace make_workspace() const;

    RetrievalResult query(const RetrievalQuery& query, RetrievalWorkspace& workspace) const;
    // The reference: every start of every clip of the order, scored exactly; no clusters, no bounds.
    RetrievalResult query_exhaustive(const RetrievalQuery& query) const;

    const MotionDatabaseView& database() const { return m_db; }
    const RetrievalSettings& settings() const { return m_settings; }

private:
    struct ClipInfo {
        int semantics = -1;
        Side side = Side::none;
        StrikeKind kind = StrikeKind::none;
        StrikeHeight height = StrikeHeight::none;
        bool arm_strike = false;
        int contact_frame = -1; // clip frame of the contact (strikes)
        int first_start = 0; // pose indices of its candidate starts: [first_start, end_start)
        int end_start = 0;
        double actor_leg_length = 1.0;
        double actor_scale_length = 1.0; // the actor length that scaling divides by (leg, or the striking limb)
        std::uint32_t support_foot = 0;  // DbPoseFlags bit of a leg strike's support foot, 0 for arm strikes
        int support_down_until = -1;     // the last pose up to the hit where the support foot is planted, -1: none
    };
    struct PoseInfo {
        float distance_to_centroid = 0.0f; // sqrt(Kovar / points), leg lengths
        float heading_cos = 1.0f, heading_sin = 0.0f;
        std::uint32_t clip = 0; // from the clip table, which the opener checked (not the pose record's, a value it did not)
    };
    // A group is the candidate starts of one order key (semantics, side, arm or leg strike, kind, height), or of one
    // cluster for one order key: m_candidates[m_group_begin[g] .. m_group_begin[g + 1]), g = cluster * m_order_keys +
    // key (cluster 0 when not per cluster), in its tree's order.
    static constexpr int k_keys_per_semantics = 3 * 2 * k_strike_kind_count * k_strike_height_count;
    static int order_key(int semantics, Side side, bool arm, StrikeKind kind, StrikeHeight height) {
        return (((semantics * 3 + static_cast<int>(side)) * 2 + arm) * k_strike_kind_count + static_cast<int>(kind)) * k_strike_height_count +
               static_cast<int>(height);
    }
    static bool key_is_arm(int key) { return (key / (k_strike_kind_count * k_strike_height_count)) % 2 == 1; }
    static bool label_matches(int wanted, int label) { return wanted == 0 || wanted == label; } // 0: any
    bool excluded(std::uint32_t pose, const RetrievalQuery& query) const;
    // Calls visit(side, arm, kind, height) for every order key an order covers.
    template <class Visit>
    static void for_each_order_key(int semantics, Side side, StrikeKind kind, StrikeHeight height, Visit visit);
    double character_scale_length(bool arm, const CharacterSize& character) const;

    bool obeys(const ClipInfo& clip, const RetrievalQuery& query) const;
    static bool support_planted(std::uint32_t support_foot, std::uint32_t start_flags, const RetrievalQuery& query) {
        return (support_foot & start_flags & query.planted_feet) == support_foot;
    }
    // A start's flags, with a leg strike's support foot counted planted when it comes down before the hit (a
    // fighter who starts on the ball of that foot: the adaptation keeps it on the floor).
    std::uint32_t start_flags(const ClipInfo& clip, int pose) const {
        const std::uint32_t flags = m_db.poses[pose].flags;
        return pose <= clip.support_down_until ? flags | clip.support_foot : flags;
    }
    double scale_to_character(const ClipInfo& clip, const CharacterSize& character) const;
    // Scores one start exactly; returns false when its score cannot beat `best` (left untouched then).
    bool score_start(int pose_index, const RetrievalQuery& query, double d_pose, RetrievalResult& best) const;
    // What a group's search needs of the query, prepared once per group.
    struct GroupQuery {
        int group = 0;
        std::span<const float> key;     // the query's pose key
        Eigen::Vector3f target;         // in the group's scale lengths
        double to_score = 1.0;          // a target distance in scale lengths -> score
        double centroid_distance = -1;  // the query's to the group's cluster centroid; < 0: no cluster bound
        double pose_bound = 0.0;        // a pose distance bound for every member (from the cluster)
    };
    GroupQuery group_query(int group, double centroid_distance, std::span<const float> query_key, const RetrievalQuery& query,
                           const Eigen::Vector3d& target_in_heading) const;
    double node_bound(int node, const GroupQuery& group) const; // a lower bound of the score of every candidate below
    void visit_group(const GroupQuery& group, double root_bound, const RetrievalQuery& query, RetrievalResult& best) const;
    void visit_leaf(const BoxTree::Node& leaf, const GroupQuery& group, const RetrievalQuery& query, RetrievalResult& best) const;
    void finish(RetrievalResult& result, const RetrievalQuery& query) const;

    MotionDatabaseView m_db;
    RetrievalSettings m_settings;
    std::vector<std::string_view> m_semantics_names;
    std::vector<ClipInfo> m_clips;
    std::vector<PoseInfo> m_poses;
    std::vector<float> m_cluster_radius;     // sqrt(radius / points)
    // A candidate start as the search's inner loop reads it: contiguous per group in its tree's order, its clip's
    // hit point at the hit frame in the start's heading frame divided by its actor's scale length, its pose key,
    // its distance to its centroid.
    struct Candidate {
        float hit_in_start[3];
        float pose_key[k_pose_key_dimensions];
        float distance_to_centroid;
        std::uint32_t pose;
        std::uint32_t support_foot; // DbPoseFlags bit a leg strike needs planted, 0 for arm strikes
        std::uint32_t start_flags;  // the start pose's DbPoseFlags (read here, not from the mapped file)
    };
    static constexpr int k_tree_dimensions = 3 + k_pose_key_dimensions; // hit point, then pose key
    // The candidates' tree order, and where each group's tree starts.
    void build_trees();

    PoseKeyProjection m_key_projection;
    int m_group_clusters = 1;                 // clusters with groups of their own: 1, or every cluster (trees_per_cluster)
    std::vector<Candidate> m_candidates;      // grouped by cluster (when per cluster), then order key
    std::vector<std::uint32_t> m_group_begin; // [group], one more entry at the end
    BoxTree m_trees{k_tree_dimensions};       // over (hit_in_start, pose_key)
    std::vector<int> m_group_root;            // [group] its tree's root node, -1 when empty
    std::vector<int> m_order_counts;         // [order key] candidates over every cluster
    int m_order_keys = 0;
};

} // namespace kumite
