#include "kumite/core/retrieval.h"

#include "kumite/core/pose_features.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace kumite {
namespace {

constexpr Side k_sides[] = {Side::none, Side::left, Side::right};
// Slack for float rounding in the bounds (distances are computed from float features): a bound never exceeds the
// exact value by more than this, in leg lengths.
constexpr double k_rounding_slack = 1e-3;

// Kovar's distance as an RMS over the feature's points: a metric (see the header), in leg lengths.
double rms_distance(std::span<const float> a, std::span<const float> b) {
    return std::sqrt(pose_feature_distance(a, b) / k_feature_cloud_size);
}

// A point of the clip world seen from a start's heading frame (yaw as cos/sin).
Eigen::Vector3d to_start_heading(const DbPose& start, float cos_yaw, float sin_yaw, const float (&point)[3]) {
    const double dx = point[0] - start.heading[0], dz = point[2] - start.heading[1];
    return {cos_yaw * dx - sin_yaw * dz, point[1], sin_yaw * dx + cos_yaw * dz};
}

} // namespace

Retriever::Retriever(const MotionDatabaseView& database, RetrievalSettings settings) : m_db(database), m_settings(settings) {
    for (const DbClip& clip : m_db.clips) {
        const std::string_view name = m_db.string(clip.semantics);
        if (std::find(m_semantics_names.begin(), m_semantics_names.end(), name) == m_semantics_names.end()) m_semantics_names.push_back(name);
    }
    m_order_keys = static_cast<int>(m_semantics_names.size()) * k_keys_per_semantics;

    m_clips.resize(m_db.clips.size());
    for (std::size_t c = 0; c < m_db.clips.size(); ++c) {
        const DbClip& clip = m_db.clips[c];
        ClipInfo& info = m_clips[c];
        info.semantics = semantics_id(m_db.string(clip.semantics));
        info.side = static_cast<Side>(std::min<std::uint32_t>(clip.side, 2));
        info.kind = static_cast<StrikeKind>(clip.kind % k_strike_kind_count);
        info.height = static_cast<StrikeHeight>(clip.height % k_strike_height_count);
        info.arm_strike = db_clip_is_arm_strike(clip);
        info.first_start = info.end_start = static_cast<int>(clip.first_pose);
        // Starts lead the contact by min_lead_frames; a strike whose whole wind-up is shorter (a snap elbow from
        // guard) starts at its first frame, never mid-flight.
        info.contact_frame = db_clip_contact_frame(m_db, clip, m_settings.contact_extension, m_settings.contact_speed_share);
        if (db_clip_is_strike(clip)) info.end_start += std::max(1, info.contact_frame - m_settings.min_lead_frames + 1);
        const DbActor& actor = m_db.actors[clip.actor];
        info.actor_leg_length = actor.leg_length_m;
        const bool by_arm = m_settings.scaling == RetrievalScaling::limb_length && info.arm_strike;
        info.actor_scale_length = by_arm ? actor.arm_length_m : actor.leg_length_m;
        info.support_foot = db_clip_support_foot(clip);
        if (const int down = db_clip_support_down_until(m_db, clip); down >= 0) info.support_down_until = int(clip.first_pose) + down;
    }

    // A pose's clip is the one whose range holds it: the clip table tiles the poses (checked at open), while the
    // pose record's own clip and frame are values only a verify checks, never followed here.
    m_poses.resize(m_db.poses.size());
    for (std::size_t c = 0; c < m_db.clips.size(); ++c) {
        const DbClip& clip = m_db.clips[c];
        for (std::uint32_t f = 0; f < clip.frame_count; ++f) m_poses[clip.first_pose + f].clip = static_cast<std::uint32_t>(c);
    }
    for (std::size_t p = 0; p < m_db.poses.size(); ++p) {
        m_poses[p].heading_cos = std::cos(m_db.poses[p].heading[2]);
        m_poses[p].heading_sin = std::sin(m_db.poses[p].heading[2]);
    }
    const int clusters = static_cast<int>(m_db.clusters.size());
    m_cluster_radius.resize(clusters);
    for (int c = 0; c < clusters; ++c) {
        const DbCluster& cluster = m_db.clusters[c];
        double radius = 0.0;
        for (std::uint32_t m = 0; m < cluster.member_count; ++m) {
            const std::uint32_t pose = m_db.members[cluster.first_member + m];
            if (pose >= m_poses.size()) continue; // a corrupt member (verify names it): never followed
            const double distance = rms_distance(m_db.centroid(c), m_db.feature(pose));
            m_poses[pose].distance_to_centroid = static_cast<float>(distance);
            radius = std::max(radius, distance);
        }
        m_cluster_radius[c] = static_cast<float>(radius);
    }
    // Groups: one per order key, or one per cluster and order key (trees_per_cluster). Candidates are made in
    // cluster order, then sorted by group (stable, so members keep their order inside a group).
    m_group_clusters = m_settings.trees_per_cluster ? std::max(1, clusters) : 1;
    const std::size_t group_count = std::size_t(m_group_clusters) * m_order_keys;
    std::vector<std::pair<std::uint32_t, Candidate>> grouped;
    for (int c = 0; c < clusters; ++c) {
        const DbCluster& cluster = m_db.clusters[c];
        const int group_cluster = m_settings.trees_per_cluster ? c : 0;
        for (std::uint32_t m = 0; m < cluster.member_count; ++m) {
            const std::uint32_t pose = m_db.members[cluster.first_member + m];
            if (pose >= m_poses.size()) continue;
            const std::uint32_t clip_index = m_poses[pose].clip;
            const ClipInfo& clip = m_clips[clip_index];
            if (int(pose) < clip.first_start || int(pose) >= clip.end_start) continue;
            const int key = order_key(clip.semantics, clip.side, clip.arm_strike, clip.kind, clip.height);
            const DbPose& start = m_db.poses[pose];
            const DbPose& hit = m_db.poses[m_db.clips[clip_index].first_pose + clip.contact_frame];
            const Eigen::Vector3d hit_in_start =
                to_start_heading(start, m_poses[pose].heading_cos, m_poses[pose].heading_sin, hit.hit_point) / clip.actor_scale_length;
            Candidate candidate{};
            for (int axis = 0; axis < 3; ++axis) candidate.hit_in_start[axis] = static_cast<float>(hit_in_start[axis]);
            candidate.distance_to_centroid = m_poses[pose].distance_to_centroid;
            candidate.pose = pose;
            candidate.support_foot = clip.support_foot;
            candidate.start_flags = start_flags(clip, int(pose));
            grouped.emplace_back(static_cast<std::uint32_t>(std::size_t(group_cluster) * m_order_keys + key), candidate);
        }
    }
    std::stable_sort(grouped.begin(), grouped.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    m_group_begin.assign(group_count + 1, 0);
    for (const auto& [group, candidate] : grouped) ++m_group_begin[group + 1];
    for (std::size_t group = 0; group < group_count; ++group) m_group_begin[group + 1] += m_group_begin[group];
    m_candidates.reserve(grouped.size());
    for (const auto& [group, candidate] : grouped) m_candidates.push_back(candidate);
    m_group_begin.back() = static_cast<std::uint32_t>(m_candidates.size());
    build_trees();
    m_order_counts.assign(m_order_keys, 0);
    for (std::size_t group = 0; group + 1 < m_group_begin.size(); ++group) {
        m_order_counts[group % m_order_keys] += static_cast<int>(m_group_begin[group + 1] - m_group_begin[group]);
    }
}

void Retriever::build_trees() {
    std::vector<std::uint32_t> poses(m_candidates.size());
    for (std::size_t k = 0; k < m_candidates.size(); ++k) poses[k] = m_candidates[k].pose;
    std::sort(poses.begin(), poses.end()); // samples evenly spread over the database, not over the groups
    m_key_projection = PoseKeyProjection::learn(m_db.features, poses);
    std::vector<float> points(m_candidates.size() * k_tree_dimensions);
    for (std::size_t k = 0; k < m_candidates.size(); ++k) {
        Candidate& candidate = m_candidates[k];
        m_key_projection.project(m_db.feature(candidate.pose), candidate.pose_key);
        float* point = points.data() + k * k_tree_dimensions;
        std::copy_n(candidate.hit_in_start, 3, point);
        std::copy_n(candidate.pose_key, k_pose_key_dimensions, point + 3);
    }
    // Split widths in score units: a target gap weighs target_weight, a key gap pose_weight (both in leg lengths).
    std::array<float, k_tree_dimensions> split_scale;
    std::fill_n(split_scale.begin(), 3, static_cast<float>(m_settings.target_weight));
    std::fill(split_scale.begin() + 3, split_scale.end(), static_cast<float>(m_settings.pose_weight));
    std::vector<std::uint32_t> order(m_candidates.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
    m_group_root.assign(m_group_begin.size() - 1, -1);
    for (std::size_t group = 0; group + 1 < m_group_begin.size(); ++group) {
        m_group_root[group] = m_trees.add(points, split_scale, order, m_group_begin[group], m_group_begin[group + 1], m_settings.leaf_size);
    }
    std::vector<Candidate> in_tree_order(m_candidates.size());
    for (std::size_t k = 0; k < order.size(); ++k) in_tree_order[k] = m_candidates[order[k]];
    m_candidates = std::move(in_tree_order);
}

template <class Visit>
void Retriever::for_each_order_key(int semantics, Side side, StrikeKind kind, StrikeHeight height, Visit visit) {
    for (Side each : k_sides) {
        if (side != Side::none && each != side) continue;
        for (bool arm : {false, true}) {
            for (int k = 0; k < k_strike_kind_count; ++k) {
                if (!label_matches(static_cast<int>(kind), k)) continue;
                for (int h = 0; h < k_strike_height_count; ++h) {
                    if (label_matches(static_cast<int>(height), h)) visit(order_key(semantics, each, arm, static_cast<StrikeKind>(k), static_cast<StrikeHeight>(h)));
                }
            }
        }
    }
}

int Retriever::candidate_count(int semantics, Side side, StrikeKind kind, StrikeHeight height) const {
    if (semantics < 0 || semantics >= static_cast<int>(m_semantics_names.size())) return 0;
    int count = 0;
    for_each_order_key(semantics, side, kind, height, [&](int key) { count += m_order_counts[key]; });
    return count;
}

int Retriever::semantics_id(std::string_view semantics) const {
    const auto found = std::find(m_semantics_names.begin(), m_semantics_names.end(), semantics);
    return found == m_semantics_names.end() ? -1 : static_cast<int>(found - m_semantics_names.begin());
}

FloorAlignment clip_alignment(const MotionDatabaseView& db, int clip, int frame, double character_leg_m, const HeadingFrame& heading) {
    // The decoded clip's world is the clip's scaled by the leg-length ratio (the MIR stores the hip centre in leg
    // lengths), so its heading sits at the scaled origin, with the same yaw.
    const DbClip& record = db.clips[clip];
    const DbPose& start = db.poses[record.first_pose + frame];
    const double decoded_scale = character_leg_m / db.actors[record.actor].leg_length_m;
    FloorAlignment alignment{heading.yaw_rad - start.heading[2], 0.0, 0.0};
    const Eigen::Vector3d turned = alignment.apply(Eigen::Vector3d(start.heading[0] * decoded_scale, 0.0, start.heading[1] * decoded_scale));
    alignment.x = heading.origin.x() - turned.x();
    alignment.z = heading.origin.z() - turned.z();
    return alignment;
}

RetrievalWorkspace Retriever::make_workspace() const {
    RetrievalWorkspace workspace;
    workspace.group_order.resize(std::size_t(m_group_clusters) * k_keys_per_semantics); // every key of one semantics
    workspace.centroid_distance.resize(m_db.clusters.size());
    return workspace;
}

bool Retriever::obeys(const ClipInfo& clip, const RetrievalQuery& query) const {
    return clip.semantics == query.semantics && (query.side == Side::none || clip.side == query.side) &&
           label_matches(static_cast<int>(query.kind), static_cast<int>(clip.kind)) &&
           label_matches(static_cast<int>(query.height), static_cast<int>(clip.height));
}

bool Retriever::excluded(std::uint32_t pose, const RetrievalQuery& query) const {
    const int clip = static_cast<int>(m_poses[pose].clip);
    return std::find(query.excluded_clips.begin(), query.excluded_clips.end(), clip) != query.excluded_clips.end();
}

double Retriever::character_scale_length(bool arm, const CharacterSize& character) const {
    return m_settings.scaling == RetrievalScaling::limb_length && arm ? character.arm_length_m : character.leg_length_m;
}

double Retriever::scale_to_character(const ClipInfo& clip, const CharacterSize& character) const {
    return character_scale_length(clip.arm_strike, character) / clip.actor_scale_length;
}

bool Retriever::score_start(int pose_index, const RetrievalQuery& query, double d_pose, RetrievalResult& best) const {
    const DbPose& start = m_db.poses[pose_index];
    const std::uint32_t clip_index = m_poses[pose_index].clip;
    const ClipInfo& clip = m_clips[clip_index];
    const DbClip& record = m_db.clips[clip_index];
    const double scale = scale_to_character(clip, query.character);
    const Eigen::Vector3d target_in_start = query.heading.to_heading(query.target_world) / scale; // the paper's c_r
    const PoseInfo& info = m_poses[pose_index];
    const DbPose& hit = m_db.poses[record.first_pose + clip.contact_frame];
    const double d_target_m = (to_start_heading(start, info.heading_cos, info.heading_sin, hit.hit_point) - target_in_start).norm() * scale;
    const double score = m_settings.pose_weight * d_pose + m_settings.target_weight * d_target_m / query.character.leg_length_m;
    if (!(score < best.score)) return false;
    best.found = true;
    best.clip = static_cast<int>(clip_index);
    best.start_pose = pose_index;
    best.start_frame = pose_index - static_cast<int>(record.first_pose);
    best.contact_frame = clip.contact_frame;
    best.d_pose = d_pose;
    best.d_target_m = d_target_m;
    best.score = score;
    return true;
}

void Retriever::finish(RetrievalResult& result, const RetrievalQuery& query) const {
    if (!result.found) return;
    const DbClip& record = m_db.clips[result.clip];
    const ClipInfo& clip = m_clips[result.clip];
    const DbPose& start = m_db.poses[result.start_pose];
    result.time_to_contact_s = (result.contact_frame - result.start_frame) * static_cast<double>(m_db.meta.frame_time_s);
    result.clip_to_world = clip_alignment(m_db, result.clip, result.start_frame, query.character.leg_length_m, query.heading);
    const PoseInfo& info = m_poses[result.start_pose];
    const Eigen::Vector3d contact_in_start =
        to_start_heading(start, info.heading_cos, info.heading_sin, m_db.poses[record.first_pose + result.contact_frame].hit_point);
    result.contact_point_world = query.heading.to_world(contact_in_start * scale_to_character(clip, query.character));
}

namespace {

// A pose key's floats: three four-float packets.
using KeyValues = Eigen::Map<const Eigen::Array<float, k_pose_key_dimensions, 1>>;

// The distance from `value` to the interval [low, high], 0 inside.
inline float gap(float value, float low, float high) { return std::max(0.0f, std::max(low - value, value - high)); }

} // namespace

Retriever::GroupQuery Retriever::group_query(int group, double centroid_distance, std::span<const float> query_key, const RetrievalQuery& query,
                                             const Eigen::Vector3d& target_in_heading) const {
    // In the group's units (scale lengths) the target is one point for every actor, and a hit-point distance times
    // to_score is the target part of a candidate's score.
    const bool arm = key_is_arm(group % m_order_keys);
    const double length = character_scale_length(arm, query.character);
    GroupQuery group_query;
    group_query.group = group;
    group_query.key = query_key;
    group_query.target = (target_in_heading / length).cast<float>();
    group_query.to_score = m_settings.target_weight * length / query.character.leg_length_m;
    group_query.centroid_distance = centroid_distance;
    // Every member's pose distance is at least the query's distance to the centroid less the cluster's radius.
    if (centroid_distance >= 0.0) {
        group_query.pose_bound = std::max(0.0, centroid_distance - m_cluster_radius[group / m_order_keys] - k_rounding_slack);
    }
    return group_query;
}

double Retriever::node_bound(int node, const GroupQuery& group) const {
    // The hit box's and the key box's distances to the query. The float distances may differ from the exact ones
    // by rounding; the slack keeps the bound a bound.
    const float* low = m_trees.low(node);
    const float* high = m_trees.high(node);
    float target_squared = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
        const float along = gap(group.target[axis], low[axis], high[axis]);
        target_squared += along * along;
    }
    const KeyValues key(group.key.data()), key_low(low + 3), key_high(high + 3);
    const float key_squared = (key_low - key).max(key - key_high).max(0.0f).square().sum();
    const double pose_bound = std::max(group.pose_bound, std::sqrt(static_cast<double>(key_squared)) - k_rounding_slack);
    return m_settings.pose_weight * pose_bound + group.to_score * std::max(0.0, std::sqrt(static_cast<double>(target_squared)) - k_rounding_slack);
}

void Retriever::visit_leaf(const BoxTree::Node& leaf, const GroupQuery& group, const RetrievalQuery& query, RetrievalResult& best) const {
    const double pose_weight = m_settings.pose_weight;
    const KeyValues query_key(group.key.data());
    // pose_weight * (|key gap| - slack) < best.score, squared: most candidates fail it, and need no square root.
    auto key_limit = [&] {
        if (!(pose_weight > 0.0)) return std::numeric_limits<double>::infinity();
        const double gap_limit = best.score / pose_weight + k_rounding_slack;
        return gap_limit > 0.0 ? gap_limit * gap_limit : 0.0;
    };
    double key_squared_limit = key_limit();
    for (std::uint32_t k = leaf.begin; k < leaf.end; ++k) {
        const Candidate& candidate = m_candidates[k];
        if (candidate.support_foot && !support_planted(candidate.support_foot, candidate.start_flags, query)) continue;
        if (!query.excluded_clips.empty() && excluded(candidate.pose, query)) continue;
        ++best.counts.candidates_seen;
        const float key_squared = (KeyValues(candidate.pose_key) - query_key).square().sum();
        if (!(key_squared < key_squared_limit)) continue; // the cluster's bound below only raises pose_bound
        double pose_bound = std::sqrt(static_cast<double>(key_squared));
        if (group.centroid_distance >= 0.0) pose_bound = std::max(pose_bound, std::abs(group.centroid_distance - candidate.distance_to_centroid));
        const double pose_part = pose_weight * std::max(0.0, pose_bound - k_rounding_slack);
        if (!(pose_part < best.score)) continue;
        float squared = 0.0f;
        for (int axis = 0; axis < 3; ++axis) {
            const float along = candidate.hit_in_start[axis] - group.target[axis];
            squared += along * along;
        }
        best.counts.inside_box += squared < 0.01f;
        const double target_part = group.to_score * std::max(0.0, std::sqrt(static_cast<double>(squared)) - k_rounding_slack);
        if (!(pose_part + target_part < best.score)) continue;
        ++best.counts.pose_scored;
        const double d_pose = rms_distance(query.pose_feature, m_db.feature(candidate.pose));
        if (!(pose_weight * d_pose + target_part < best.score)) continue;
        ++best.counts.target_scored;
        if (score_start(static_cast<int>(candidate.pose), query, d_pose, best)) key_squared_limit = key_limit();
    }
}

void Retriever::visit_group(const GroupQuery& group, double root_bound, const RetrievalQuery& query, RetrievalResult& best) const {
    // Depth first, the nearer child first, each node's bound checked again when it is popped (the best may have
    // improved meanwhile). Trees are balanced, so the stack never holds more than one node per level.
    std::pair<int, double> stack[BoxTree::max_depth + 1];
    int depth = 0;
    stack[depth++] = {m_group_root[group.group], root_bound};
    while (depth > 0) {
        const auto [index, bound] = stack[--depth];
        if (!(bound < best.score)) continue;
        ++best.counts.nodes_visited;
        const BoxTree::Node& node = m_trees.node(index);
        if (node.leaf()) {
            visit_leaf(node, group, query, best);
            continue;
        }
        const int left = index + 1, right = static_cast<int>(node.right);
        const double left_bound = node_bound(left, group), right_bound = node_bound(right, group);
        const bool left_first = left_bound <= right_bound;
        const std::pair<int, double> near{left_first ? left : right, left_first ? left_bound : right_bound};
        const std::pair<int, double> far{left_first ? right : left, left_first ? right_bound : left_bound};
        if (far.second < best.score) stack[depth++] = far;
        if (near.second < best.score) stack[depth++] = near;
    }
}

RetrievalResult Retriever::query(const RetrievalQuery& query, RetrievalWorkspace& workspace) const {
    assert(query.pose_feature.size() == std::size_t(k_feature_dimensions));
    RetrievalResult best;
    best.score = query.score_limit;
    if (query.semantics < 0 || query.semantics >= static_cast<int>(m_semantics_names.size())) return best;
    const Eigen::Vector3d target_in_heading = query.heading.to_heading(query.target_world);
    std::array<float, k_pose_key_dimensions> query_key;
    m_key_projection.project(query.pose_feature, query_key);
    // The cluster bound needs the query's distance to every centroid: worth it only with trees per cluster, and
    // then not for small orders (measured with tests/bench/retrieval_bench.cpp).
    const bool cluster_bounds =
        m_settings.trees_per_cluster && candidate_count(query.semantics, query.side, query.kind, query.height) > m_settings.scan_below;
    // The groups of the order with their roots' bounds, visited best bound first.
    std::size_t groups = 0;
    for (int c = 0; c < m_group_clusters; ++c) {
        double centroid_distance = -1.0;
        if (cluster_bounds) centroid_distance = workspace.centroid_distance[c] = rms_distance(m_db.centroid(c), query.pose_feature);
        for_each_order_key(query.semantics, query.side, query.kind, query.height, [&](int key) {
            const int group = c * m_order_keys + key;
            if (m_group_root[group] < 0) return;
            const GroupQuery prepared = group_query(group, centroid_distance, query_key, query, target_in_heading);
            const double bound = node_bound(m_group_root[group], prepared);
            // A NaN bound (NaN in a feature or the query) is never below the best score, like infinity; as infinity it
            // also sorts.
            workspace.group_order[groups++] = {std::isnan(bound) ? std::numeric_limits<double>::infinity() : bound, group};
        });
    }
    std::sort(workspace.group_order.begin(), workspace.group_order.begin() + groups);
    int last_cluster = -1;
    for (std::size_t g = 0; g < groups; ++g) {
        const auto [bound, group] = workspace.group_order[g];
        if (!(bound < best.score)) break; // no candidate of this or a later group can do better
        const int cluster = group / m_order_keys;
        best.counts.clusters_visited += cluster_bounds && cluster != last_cluster;
        last_cluster = cluster;
        const double centroid_distance = cluster_bounds ? workspace.centroid_distance[cluster] : -1.0;
        visit_group(group_query(group, centroid_distance, query_key, query, target_in_heading), bound, query, best);
    }
    finish(best, query);
    return best;
}

RetrievalResult Retriever::query_exhaustive(const RetrievalQuery& query) const {
    RetrievalResult best;
    best.score = query.score_limit;
    for (const ClipInfo& clip : m_clips) {
        if (!obeys(clip, query)) continue;
        for (int pose = clip.first_start; pose < clip.end_start; ++pose) {
            if (clip.support_foot && !support_planted(clip.support_foot, start_flags(clip, pose), query)) continue;
            if (!query.excluded_clips.empty() && excluded(static_cast<std::uint32_t>(pose), query)) continue;
            ++best.counts.candidates_seen;
            ++best.counts.pose_scored;
            ++best.counts.target_scored;
            score_start(pose, query, rms_distance(query.pose_feature, m_db.feature(pose)), best);
        }
    }
    finish(best, query);
    return best;
}

} // namespace kumite
