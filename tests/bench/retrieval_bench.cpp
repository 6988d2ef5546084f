// Retrieval cost and quality: for each database given and each character, random targets around the character
// standing in the guard at the origin, each with a random order (semantics the database holds, side any / left /
// right). Per query, one thread:
//   - the fast path (Retriever::query) and the exhaustive reference (query_exhaustive) in the same run, timed;
//   - agreement: the fast path's clip and start equal the reference's, or its score is within 1%;
//   - heap allocations during the fast path (must be 0);
//   - the index's options (one tree per order or per cluster and order, leaf sizes) on the same queries, each
//     with its own times, speed-up over the same exhaustive run and agreement ("options");
//   - the adaptation offset the choice leaves: the chosen start decoded onto the character at its contact frame,
//     aligned, and the hit joint's distance to the target; measured for both scalings of the actor's hit path
//     (leg length, striking limb's length), so the better one can be kept;
//   - the nearest centroid by brute-force Kovar distance and by a FLANN k-d tree over the heading-aligned
//     features (when FLANN is available), timed, and how often they pick the same cluster.
//
// Three orders in four also name a kind, a height or both (of a strike the database holds).
// usage: retrieval_bench DB.kdb... [--targets N] [--seed S] [--commands punch,kick,...] [--characters-dir DIR]
//        --commands limits the orders to those semantics (default: every strike semantics of the database,
//        equally often); the JSON also breaks the times down by semantics.
//        (bake the reference with `kumite bake data/annotations/reference.json -o ref.kdb` and a large one with
//        scripts/make_large_database.sh). Prints one JSON document.

#include "kumite/core/character_rig.h"
#include "kumite/core/pose_features.h"
#include "kumite/core/retrieval.h"
#include "kumite/core/split_mix.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"
#include "support/allocation_counter.h"

#ifdef KUMITE_BENCH_WITH_FLANN
#include <flann/flann.hpp>
#endif

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <tuple>

using namespace kumite;
using namespace kumite::test;
using Clock = std::chrono::steady_clock;

namespace {

struct Character {
    std::string name;
    BvhFile file;
    RestAnatomy anatomy;
};

double microseconds_since(Clock::time_point start) { return std::chrono::duration<double, std::micro>(Clock::now() - start).count(); }

nlohmann::json summary(std::vector<double> values) {
    if (values.empty()) return {{"median", 0.0}, {"p99", 0.0}, {"mean", 0.0}};
    std::sort(values.begin(), values.end());
    double sum = 0.0;
    for (double v : values) sum += v;
    auto at = [&](double q) { return values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))]; };
    return {{"median", at(0.5)}, {"p90", at(0.9)}, {"p99", at(0.99)}, {"max", values.back()}, {"mean", sum / values.size()}};
}

// Where the chosen strike's hit joint is at its contact frame when decoded onto the character and aligned.
double adaptation_offset(CharacterRig& rig, Pose& pose, const MotionDatabaseView& db, const RetrievalResult& result,
                         const Eigen::Vector3d& target) {
    const DbClip& clip = db.clips[result.clip];
    rig.decode(pose, db, clip.first_pose + result.contact_frame, result.clip_to_world);
    rig.measure(pose.view());
    const int joint = rig.anatomy().body_map.joint(static_cast<BodyPart>(clip.segment));
    return (rig.positions()[joint] - target).norm();
}

nlohmann::json bench_database(const std::filesystem::path& path, const std::vector<Character>& characters, int targets_per_character,
                              std::uint64_t seed, const std::vector<std::string>& commands) {
    Result<MotionDatabase> database = MotionDatabase::open(path);
    if (!database) {
        std::cerr << "retrieval_bench: " << database.error().message << "\n";
        std::exit(1);
    }
    const MotionDatabaseView& db = database->view();
    RetrievalSettings by_limb;
    by_limb.scaling = RetrievalScaling::limb_length;
    const auto build_started = Clock::now();
    const Retriever retriever(db);
    const double retriever_build_ms = microseconds_since(build_started) / 1000.0;
    const Retriever limb_retriever(db, by_limb);
    RetrievalWorkspace workspace = retriever.make_workspace();
    // The index's options, measured on the same queries (the default above is one of them).
    struct Option {
        std::string name;
        std::unique_ptr<Retriever> retriever;
        RetrievalWorkspace workspace;
        double build_ms = 0.0;
        std::vector<double> fast_us;
        int agreed = 0;
    };
    std::vector<Option> options;
    for (const auto& [name, per_cluster, leaf] : {std::tuple{"order_trees_leaf_8", false, 8}, std::tuple{"cluster_trees_leaf_8", true, 8},
                                                  std::tuple{"cluster_trees_leaf_64", true, 64}}) {
        RetrievalSettings settings;
        settings.trees_per_cluster = per_cluster;
        settings.leaf_size = leaf;
        const auto started = Clock::now();
        auto option_retriever = std::make_unique<Retriever>(db, settings);
        const double build_ms = microseconds_since(started) / 1000.0;
        RetrievalWorkspace option_workspace = option_retriever->make_workspace();
        options.push_back({name, std::move(option_retriever), std::move(option_workspace), build_ms, {}, 0});
    }
    std::vector<int> strike_semantics;
    for (const DbClip& clip : db.clips) {
        const int id = retriever.semantics_id(db.string(clip.semantics));
        const bool wanted = commands.empty() || std::find(commands.begin(), commands.end(), db.string(clip.semantics)) != commands.end();
        if (wanted && db_clip_is_strike(clip) && std::find(strike_semantics.begin(), strike_semantics.end(), id) == strike_semantics.end()) {
            strike_semantics.push_back(id);
        }
    }

    std::map<int, std::vector<const DbClip*>> labelled_strikes; // by semantics id
    for (const DbClip& clip : db.clips) {
        if (db_clip_is_strike(clip)) labelled_strikes[retriever.semantics_id(db.string(clip.semantics))].push_back(&clip);
    }
    if (strike_semantics.empty()) {
        std::cerr << "retrieval_bench: " << path.string() << " holds none of the strike semantics asked for\n";
        std::exit(1);
    }
#ifdef KUMITE_BENCH_WITH_FLANN
    std::vector<float> centroid_copy(db.centroids.begin(), db.centroids.end());
    flann::Matrix<float> centroid_matrix(centroid_copy.data(), db.clusters.size(), k_feature_dimensions);
    flann::Index<flann::L2<float>> flann_index(centroid_matrix, flann::KDTreeSingleIndexParams(4));
    flann_index.buildIndex();
    std::vector<int> flann_indices(1);
    std::vector<float> flann_distances(1);
#endif

    std::vector<double> fast_us, exhaustive_us, brute_centroid_us, flann_centroid_us, leg_offsets, limb_offsets;
    std::vector<double> visited, candidates, nodes, pose_scored, scored;
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> by_semantics; // fast, exhaustive
    int agreed = 0, same_start = 0, total = 0, same_cluster = 0, not_found = 0;
    long allocations = 0;
    SplitMix64 random{seed};
    for (const Character& character : characters) {
        CharacterRig rig(character.file.clip.skeleton, character.anatomy);
        Pose pose;
        rig.stand_at_origin(pose, db);
        std::array<float, k_feature_dimensions> feature;
        rig.still_feature(feature);
        const double pelvis_y = rig.positions()[character.anatomy.body_map.joint(BodyPart::pelvis)].y();
        const double head_y = rig.positions()[character.anatomy.body_map.joint(BodyPart::head)].y();
        const double leg = character.anatomy.leg_length;
        RetrievalQuery query;
        query.pose_feature = feature;
        query.heading = rig.heading();
        query.character = rig.size();

        // Nearest centroid, both ways, on this character's pose.
        for (int repeat = 0; repeat < 200; ++repeat) {
            auto started = Clock::now();
            int best = 0;
            double best_distance = 1e300;
            for (std::size_t c = 0; c < db.clusters.size(); ++c) {
                const double d = pose_feature_distance(db.centroid(static_cast<std::uint32_t>(c)), feature);
                if (d < best_distance) best_distance = d, best = static_cast<int>(c);
            }
            brute_centroid_us.push_back(microseconds_since(started));
#ifdef KUMITE_BENCH_WITH_FLANN
            started = Clock::now();
            flann::Matrix<float> query_matrix(feature.data(), 1, k_feature_dimensions);
            flann::Matrix<int> index_matrix(flann_indices.data(), 1, 1);
            flann::Matrix<float> distance_matrix(flann_distances.data(), 1, 1);
            flann_index.knnSearch(query_matrix, index_matrix, distance_matrix, 1, flann::SearchParams(flann::FLANN_CHECKS_UNLIMITED));
            flann_centroid_us.push_back(microseconds_since(started));
            same_cluster += flann_indices[0] == best;
#else
            (void)best;
#endif
        }

        for (int i = 0; i < targets_per_character; ++i) {
            query.semantics = strike_semantics[random.next() % strike_semantics.size()];
            query.side = static_cast<Side>(random.next() % 3);
            // A quarter of the orders name nothing more, the others a kind, a height or both, taken from a strike of
            // that semantics the database holds.
            query.kind = StrikeKind::none;
            query.height = StrikeHeight::none;
            const std::vector<const DbClip*>& labelled = labelled_strikes[query.semantics];
            if (const std::uint64_t ask = random.next() % 4; ask > 0 && !labelled.empty()) {
                const DbClip& example = *labelled[random.next() % labelled.size()];
                if (ask != 2) query.kind = example.strike_kind();
                if (ask != 1) query.height = example.strike_height();
            }
            query.target_world = Eigen::Vector3d(random.uniform(-0.5, 0.5) * leg, random.uniform(pelvis_y, head_y + 0.1),
                                                 random.uniform(0.4, 1.4) * leg);
            allocation_count_reset();
            allocation_counting(true);
            auto started = Clock::now();
            const RetrievalResult fast = retriever.query(query, workspace);
            const double elapsed_us = microseconds_since(started);
            allocation_counting(false);
            fast_us.push_back(elapsed_us);
            allocations += allocations_counted();
            started = Clock::now();
            const RetrievalResult exhaustive = retriever.query_exhaustive(query);
            exhaustive_us.push_back(microseconds_since(started));
            auto& [fast_of, exhaustive_of] = by_semantics[std::string(retriever.semantics_name(query.semantics))];
            fast_of.push_back(fast_us.back());
            exhaustive_of.push_back(exhaustive_us.back());
            ++total;
            for (Option& option : options) {
                const auto option_started = Clock::now();
                const RetrievalResult found = option.retriever->query(query, option.workspace);
                option.fast_us.push_back(microseconds_since(option_started));
                option.agreed += found.found == exhaustive.found &&
                                 (!found.found || (found.clip == exhaustive.clip && found.start_frame == exhaustive.start_frame) ||
                                  found.score <= exhaustive.score * 1.01);
            }
            if (!fast.found || !exhaustive.found) {
                not_found += !exhaustive.found;
                agreed += fast.found == exhaustive.found;
                continue;
            }
            const bool same = fast.clip == exhaustive.clip && fast.start_frame == exhaustive.start_frame;
            same_start += same;
            agreed += same || fast.score <= exhaustive.score * 1.01;
            visited.push_back(fast.counts.clusters_visited);
            candidates.push_back(fast.counts.candidates_seen);
            nodes.push_back(fast.counts.nodes_visited);
            pose_scored.push_back(fast.counts.pose_scored);
            scored.push_back(fast.counts.target_scored);
            leg_offsets.push_back(adaptation_offset(rig, pose, db, fast, query.target_world));
            const RetrievalResult by_limb_result = limb_retriever.query(query, workspace);
            limb_offsets.push_back(adaptation_offset(rig, pose, db, by_limb_result, query.target_world));
        }
    }
    const nlohmann::json fast = summary(fast_us), exhaustive = summary(exhaustive_us);
    const nlohmann::json leg_offset = summary(leg_offsets), limb_offset = summary(limb_offsets);
    nlohmann::json result = {
        {"database", path.string()},
        {"clips", db.clips.size()},
        {"poses", db.poses.size()},
        {"clusters", db.clusters.size()},
        {"queries", total},
        {"retriever_build_ms", retriever_build_ms},
        {"fast_us", fast},
        {"exhaustive_us", exhaustive},
        {"baseline", "exhaustive search (every start of every clip of the order, exact distances), same run"},
        {"speedup_median", exhaustive["median"].get<double>() / std::max(1e-9, fast["median"].get<double>())},
        {"agreement", static_cast<double>(agreed) / std::max(1, total)},
        {"same_clip_and_start", static_cast<double>(same_start) / std::max(1, total)},
        {"orders_without_candidates", not_found},
        {"fast_path_allocations", allocations},
        {"fast_path_counts_mean",
         {{"clusters_visited", summary(visited)["mean"]}, {"candidates_seen", summary(candidates)["mean"]},
          {"nodes_visited", summary(nodes)["mean"]}, {"pose_scored", summary(pose_scored)["mean"]},
          {"target_scored", summary(scored)["mean"]}}},
        {"adaptation_offset_m",
         {{"leg_length_scaling", leg_offset},
          {"limb_length_scaling", limb_offset},
          {"smaller_median", leg_offset["median"].get<double>() <= limb_offset["median"].get<double>() ? "leg_length" : "limb_length"}}},
        {"nearest_centroid_us", {{"brute_force_kovar", summary(brute_centroid_us)}}}};
    result["options"]["order_trees_leaf_64 (default)"] = {
        {"build_ms", retriever_build_ms}, {"fast_us", fast}, {"speedup_median", result["speedup_median"]}, {"agreement", result["agreement"]}};
    for (const Option& option : options) {
        const nlohmann::json option_fast = summary(option.fast_us);
        result["options"][option.name] = {
            {"build_ms", option.build_ms},
            {"fast_us", option_fast},
            {"speedup_median", exhaustive["median"].get<double>() / std::max(1e-9, option_fast["median"].get<double>())},
            {"agreement", static_cast<double>(option.agreed) / std::max(1, total)}};
    }
    for (const auto& [semantics, times] : by_semantics) {
        const nlohmann::json fast_of = summary(times.first), exhaustive_of = summary(times.second);
        result["by_semantics"][semantics] = {
            {"queries", times.first.size()},
            {"fast_us", fast_of},
            {"exhaustive_us", exhaustive_of},
            {"speedup_median", exhaustive_of["median"].get<double>() / std::max(1e-9, fast_of["median"].get<double>())}};
    }
#ifdef KUMITE_BENCH_WITH_FLANN
    result["nearest_centroid_us"]["flann_kdtree_euclidean"] = summary(flann_centroid_us);
    result["nearest_centroid_us"]["same_cluster_rate"] = static_cast<double>(same_cluster) / std::max<std::size_t>(1, brute_centroid_us.size());
#else
    (void)same_cluster;
    result["nearest_centroid_us"]["flann_kdtree_euclidean"] = "not built (libflann-dev missing)";
#endif
    return result;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> databases;
    int targets = 1000;
    std::vector<std::string> commands;
    std::uint64_t seed = 1;
    std::filesystem::path characters_dir = std::getenv("KUMITE_CHARACTERS_DIR") ? std::getenv("KUMITE_CHARACTERS_DIR") : "data/characters";
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--targets" && i + 1 < argc) targets = std::max(1, std::atoi(argv[++i]));
        else if (argument == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (argument == "--characters-dir" && i + 1 < argc) characters_dir = argv[++i];
        else if (argument == "--commands" && i + 1 < argc) {
            std::string list = argv[++i];
            for (std::size_t start = 0; start <= list.size();) {
                const std::size_t comma = std::min(list.find(',', start), list.size());
                if (comma > start) commands.push_back(list.substr(start, comma - start));
                start = comma + 1;
            }
        }
        else if (argument.starts_with("--")) {
            std::cerr << "usage: retrieval_bench DB.kdb... [--targets N] [--seed S] [--commands LIST] [--characters-dir DIR]\n";
            return 2;
        } else databases.emplace_back(argument);
    }
    if (databases.empty()) {
        std::cerr << "usage: retrieval_bench DB.kdb... [--targets N] [--seed S] [--characters-dir DIR]\n";
        return 2;
    }
    std::vector<Character> characters;
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) {
        Result<BvhFile> file = bvh_read_file(characters_dir / (std::string(name) + ".bvh"));
        if (!file) {
            std::cerr << "retrieval_bench: " << file.error().message << "\n";
            return 1;
        }
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        if (!anatomy) return 1;
        characters.push_back({name, std::move(*file), std::move(*anatomy)});
    }
    nlohmann::json report = {{"benchmark", "retrieval"}, {"targets_per_character", targets}, {"characters", characters.size()},
                             {"threads", 1}, {"databases", nlohmann::json::array()}};
    for (const std::filesystem::path& path : databases) report["databases"].push_back(bench_database(path, characters, targets, seed, commands));
    std::cout << report.dump(2) << "\n";
    return 0;
}
