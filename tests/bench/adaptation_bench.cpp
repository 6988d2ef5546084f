// Adaptation accuracy and per-frame cost: for each character standing in the guard at the origin, random targets
// inside its strike envelope (in front, between hip and head height, within arm reach of a shoulder — punches —
// or leg reach of a hip — kicks — plus `--lean` metres for one step of torso lean), each retrieved and adapted
// frame by frame, and a quarter as many targets 0.2-0.6 m out of reach ("far_punch", "far_kick"). Reports, per
// strike semantics and overall (targets in reach): contact error (rate within 1 cm), overshoot past the target after
// the contact (past the closest point reached, out of reach), the effector's speed arriving at the contact,
// joint-limit violations (core/joint_limits.h; with --no-keep-bends, the decoder's own swivels, for comparison),
// support feet lifted, foot drift, bone-length error; the per-frame cost of step() by regime (limb only / limb + trunk CCD /
// unreachable), measured in the same run as a baseline (a plain decode of the same frames, no adaptation); and
// heap allocations inside step() (must be 0); and the pop each blend mode leaves: the largest joint
// acceleration over the blend-in (from the guard, standing still), ramp against inertialization. One thread.
//
// usage: adaptation_bench DB.kdb [--targets N] [--seed S] [--lean M] [--characters-dir DIR] [--no-keep-bends].
// Prints one JSON document.

#include "kumite/core/character_rig.h"
#include "kumite/core/forward_kinematics.h"
#include "kumite/core/split_mix.h"
#include "kumite/core/strike_adaptation.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/motion_database_file.h"
#include "support/allocation_counter.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>

using namespace kumite;
using Clock = std::chrono::steady_clock;

namespace {

nlohmann::json summary(std::vector<double> values) {
    if (values.empty()) return {{"count", 0}};
    std::sort(values.begin(), values.end());
    auto at = [&](double q) { return values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))]; };
    return {{"count", values.size()}, {"median", at(0.5)}, {"p95", at(0.95)}, {"p99", at(0.99)}, {"max", values.back()}};
}

struct Tally {
    int strikes = 0, within_1cm = 0, lifted = 0, reached = 0, overshoot_within_3cm = 0, violations = 0;
    int arrives_towards_body = 0; // the hit point's last move before the contact points back at the limb's root
    // Before the contact, how much further from the limb's root the hit point got than it is at the contact: a
    // strike that reaches out past its target and is pulled back onto it (a loop) rather than extending to it.
    std::vector<double> reach_beyond_contact;
    std::vector<double> contact_errors, drifts, overshoots, speeds;
    double worst_bone = 0.0;
    void add(const Tally& other) {
        strikes += other.strikes, within_1cm += other.within_1cm, lifted += other.lifted, reached += other.reached;
        overshoot_within_3cm += other.overshoot_within_3cm, violations += other.violations;
        arrives_towards_body += other.arrives_towards_body;
        for (auto [to, from] : {std::pair{&contact_errors, &other.contact_errors}, {&drifts, &other.drifts}, {&overshoots, &other.overshoots},
                                {&speeds, &other.speeds}, {&reach_beyond_contact, &other.reach_beyond_contact}}) {
            to->insert(to->end(), from->begin(), from->end());
        }
        worst_bone = std::max(worst_bone, other.worst_bone);
    }
};

} // namespace

int main(int argc, char** argv) {
    std::string database_path;
    int targets = 200;
    std::uint64_t seed = 1;
    double lean = 0.1;
    bool keep_bends = true;
    OffsetRamp offset_ramp = OffsetRamp::progress;
    std::filesystem::path characters_dir = std::getenv("KUMITE_CHARACTERS_DIR") ? std::getenv("KUMITE_CHARACTERS_DIR") : "data/characters";
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--targets" && i + 1 < argc) targets = std::max(1, std::atoi(argv[++i]));
        else if (argument == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (argument == "--lean" && i + 1 < argc) lean = std::atof(argv[++i]);
        else if (argument == "--characters-dir" && i + 1 < argc) characters_dir = argv[++i];
        else if (argument == "--no-keep-bends") keep_bends = false;
        else if (argument == "--offset-ramp" && i + 1 < argc) offset_ramp = std::string(argv[++i]) == "time" ? OffsetRamp::time : OffsetRamp::progress;
        else if (!argument.starts_with("--") && database_path.empty()) database_path = argument;
        else {
            std::cerr << "usage: adaptation_bench DB.kdb [--targets N] [--seed S] [--lean M] [--characters-dir DIR] [--no-keep-bends]\n";
            return 2;
        }
    }
    if (database_path.empty()) {
        std::cerr << "usage: adaptation_bench DB.kdb [--targets N] [--seed S] [--lean M] [--characters-dir DIR] [--no-keep-bends]\n";
        return 2;
    }
    Result<MotionDatabase> database = MotionDatabase::open(database_path);
    if (!database) {
        std::cerr << "adaptation_bench: " << database.error().message << "\n";
        return 1;
    }
    const MotionDatabaseView& db = database->view();
    const Retriever retriever(db);
    RetrievalWorkspace workspace = retriever.make_workspace();

    std::map<std::string, Tally> tallies;
    std::map<std::string, std::vector<double>> cost_by_regime, least_cost_by_regime;
    std::map<std::string, std::vector<double>> blend_pop; // per blend mode: largest joint acceleration, m/s^2
    std::vector<double> baseline_decode_us, least_baseline_decode_us;
    std::array<int, 5> violations_by_joint{}; // elbow l, elbow r, knee l, knee r, trunk: frames
    long allocations = 0, frames_stepped = 0;
    SplitMix64 random{seed};
    for (const char* name : {"kid", "scout", "brawler", "runner", "giant"}) {
        Result<BvhFile> file = bvh_read_file(characters_dir / (std::string(name) + ".bvh"));
        if (!file) {
            std::cerr << "adaptation_bench: " << file.error().message << "\n";
            return 1;
        }
        Result<RestAnatomy> anatomy = rest_anatomy_build(file->clip, file->body_map);
        if (!anatomy) return 1;
        const Skeleton& skeleton = file->clip.skeleton;
        CharacterRig rig(skeleton, *anatomy);
        Pose standing;
        rig.stand_at_origin(standing, db);
        std::array<float, k_feature_dimensions> feature;
        rig.still_feature(feature);
        const auto positions = rig.positions();
        const double hip_y = positions[anatomy->body_map.joint(BodyPart::pelvis)].y();
        const double head_y = positions[anatomy->body_map.joint(BodyPart::head)].y();
        const std::array<Eigen::Vector3d, 2> ankles = {positions[anatomy->limbs[int(Limb::leg_l)].extremity],
                                                       positions[anatomy->limbs[int(Limb::leg_r)].extremity]};
        MirEncoder encoder(skeleton, *anatomy);
        MirFrame current;
        encoder.encode(current, standing.view());
        MirDecoder plain_decoder(skeleton, *anatomy, {});
        AdaptationSettings settings;
        settings.keep_clip_bends = keep_bends;
        settings.offset_ramp = offset_ramp;
        StrikeAdapter adapter(rig, db, settings);
        Pose pose;
        rig.decode(pose, db, 0); // sizes the reused pose: the measured steps must not
        MirFrame plain_frame;
        db_mir_frame_load(plain_frame, db.mir_frames[0]);

        // Targets inside the reach, then a quarter as many far out of it (tallied apart: "far_punch", "far_kick").
        for (int t = 0; t < targets + targets / 4; ++t) {
            const bool kick = t % 2 == 1, far = t >= targets;
            const int limb = kick ? int(Limb::leg_l) + int(random.next() % 2) : int(Limb::arm_l) + int(random.next() % 2);
            const LimbChain& chain = anatomy->limbs[limb];
            // A target in front, between hip and head height, within the limb's reach (+ lean) of its root; a far
            // one 0.2 to 0.6 m beyond that.
            Eigen::Vector3d target;
            for (int attempt = 0; attempt < 1000; ++attempt) {
                target = Eigen::Vector3d(random.uniform(-0.4, 0.4), random.uniform(hip_y, head_y), random.uniform(0.2, 1.2));
                if ((target - positions[chain.root]).norm() <= chain.length() + lean && target.z() > positions[chain.root].z() + 0.15) break;
            }
            if (far) {
                const Eigen::Vector3d out = (target - positions[chain.root]).normalized();
                target = positions[chain.root] + out * (chain.length() + lean + random.uniform(0.2, 0.6));
            }
            RetrievalQuery query;
            query.pose_feature = feature;
            query.heading = rig.heading();
            query.character = rig.size();
            query.semantics = retriever.semantics_id(kick ? "kick" : "punch");
            query.side = limb % 2 == 0 ? Side::left : Side::right;
            query.target_world = target;
            const RetrievalResult retrieved = retriever.query(query, workspace);
            if (!retrieved.found) continue;
            adapter.begin({retrieved.clip, retrieved.start_frame, retrieved.contact_frame, retrieved.clip_to_world, target}, current,
                          {true, true}, ankles);
            Tally& tally = tallies[std::string(far ? "far_" : "") + (kick ? "kick" : "punch")];
            ++tally.strikes;
            double drift = 0.0, lift = 0.0, overshoot = 0.0;
            AdaptedFrame at_contact;
            Eigen::Vector3d before_contact = Eigen::Vector3d::Zero(), root_at_contact = Eigen::Vector3d::Zero();
            std::vector<double> extensions;
            for (int i = 0; i < adapter.frame_count(); ++i) {
                kumite::test::allocation_count_reset();
                kumite::test::allocation_counting(true);
                const auto started = Clock::now();
                const AdaptedFrame frame = adapter.step(i, pose);
                const double elapsed = std::chrono::duration<double, std::micro>(Clock::now() - started).count();
                kumite::test::allocation_counting(false);
                allocations += kumite::test::allocations_counted();
                ++frames_stepped;
                const char* regime = frame.reach == Reach::limb ? "limb_only" : frame.reach == Reach::torso ? "limb_and_trunk" : "unreachable";
                cost_by_regime[regime].push_back(elapsed);
                // The same frame twice more (a step is a function of its index): the least of the three is the
                // frame's cost without the scheduler's interruptions, which on a shared machine reach 50 us.
                double least = elapsed;
                for (int repeat = 0; repeat < 2; ++repeat) {
                    const auto again = Clock::now();
                    adapter.step(i, pose);
                    least = std::min(least, std::chrono::duration<double, std::micro>(Clock::now() - again).count());
                }
                least_cost_by_regime[regime].push_back(least);
                const int limb_root = skeleton.parents[skeleton.parents[adapter.effector_joint()]];
                if (i <= adapter.contact_index()) extensions.push_back((frame.effector - adapter.positions()[limb_root]).norm());
                if (frame.contact) {
                    at_contact = frame;
                    root_at_contact = adapter.positions()[skeleton.parents[skeleton.parents[adapter.effector_joint()]]];
                }
                if (i + 1 == adapter.contact_index()) before_contact = frame.effector;
                overshoot = std::max(overshoot, frame.past_target_m);
                tally.violations += joint_violation_count(frame.joint_violations);
                for (int joint = 0; joint < 5; ++joint) violations_by_joint[joint] += (frame.joint_violations >> joint) & 1u;
                tally.worst_bone = std::max(tally.worst_bone, bone_length_error(skeleton, adapter.positions()));
                for (int foot = 0; foot < 2; ++foot) {
                    if (!adapter.support_feet()[foot]) continue;
                    const Eigen::Vector3d ankle = adapter.positions()[anatomy->limbs[2 + foot].extremity];
                    const Eigen::Vector3d pin = adapter.support_pins()[foot];
                    drift = std::max(drift, Eigen::Vector2d(ankle.x() - pin.x(), ankle.z() - pin.z()).norm());
                    lift = std::max(lift, ankle.y() - pin.y());
                }
                // Baseline: the same clip frame decoded plainly, no blend, no pins, no IK.
                double base_least = 1e300;
                for (int repeat = 0; repeat < 3; ++repeat) {
                    const auto base_started = Clock::now();
                    db_mir_frame_load(plain_frame, db.mir_frames[db.clips[retrieved.clip].first_pose + retrieved.start_frame + i]);
                    plain_decoder.decode(pose, plain_frame);
                    const double base_us = std::chrono::duration<double, std::micro>(Clock::now() - base_started).count();
                    if (repeat == 0) baseline_decode_us.push_back(base_us);
                    base_least = std::min(base_least, base_us);
                }
                least_baseline_decode_us.push_back(base_least);
            }
            // The pop of each blend mode: joint accelerations from the still guard into the first frames.
            const double dt = db.meta.frame_time_s;
            for (BlendMode mode : {BlendMode::ramp, BlendMode::inertialization}) {
                adapter.settings().blend = mode;
                std::vector<Eigen::Vector3d> before(positions.begin(), positions.end()), previous = before;
                double worst = 0.0;
                for (int i = 0; i < std::min(adapter.frame_count(), adapter.settings().blend_frames + 3); ++i) {
                    adapter.step(i, pose);
                    for (int joint = 0; joint < skeleton.joint_count(); ++joint) {
                        const Eigen::Vector3d& now = adapter.positions()[joint];
                        worst = std::max(worst, (now - 2.0 * previous[joint] + before[joint]).norm() / (dt * dt));
                    }
                    before = previous;
                    previous.assign(adapter.positions().begin(), adapter.positions().end());
                }
                blend_pop[mode == BlendMode::ramp ? "ramp" : "inertialization"].push_back(worst);
            }
            adapter.settings().blend = BlendMode::ramp;
            const double error = (at_contact.effector - target).norm();
            tally.contact_errors.push_back(error);
            tally.within_1cm += error <= 0.01;
            tally.reached += at_contact.reach != Reach::unreachable;
            tally.lifted += lift > 0.02;
            tally.drifts.push_back(drift);
            tally.overshoots.push_back(overshoot);
            tally.overshoot_within_3cm += overshoot <= 0.03;
            tally.speeds.push_back((at_contact.effector - before_contact).norm() / dt);
            const Eigen::Vector3d arriving = at_contact.effector - before_contact;
            if (!extensions.empty()) tally.reach_beyond_contact.push_back(*std::max_element(extensions.begin(), extensions.end()) - extensions.back());
            tally.arrives_towards_body += arriving.norm() > 0.01 && arriving.dot(at_contact.effector - root_at_contact) < 0.0;
        }
    }
    nlohmann::json report = {{"benchmark", "adaptation"}, {"database", database_path}, {"targets_per_character", targets}, {"lean_m", lean},
                             {"keep_clip_bends", keep_bends},
                             {"offset_ramp", offset_ramp == OffsetRamp::time ? "time" : "progress"}};
    auto tally_json = [](const Tally& tally) {
        return nlohmann::json{{"strikes", tally.strikes},
                              {"contact_within_1cm_rate", double(tally.within_1cm) / std::max(1, tally.strikes)},
                              {"reached_rate", double(tally.reached) / std::max(1, tally.strikes)},
                              {"overshoot_within_3cm_rate", double(tally.overshoot_within_3cm) / std::max(1, tally.strikes)},
                              {"support_foot_lifted", tally.lifted},
                              {"arrives_towards_body", tally.arrives_towards_body},
                              {"reach_beyond_contact_m", summary(tally.reach_beyond_contact)},
                              {"joint_limit_violations", tally.violations},
                              {"contact_error_m", summary(tally.contact_errors)},
                              {"overshoot_m", summary(tally.overshoots)},
                              {"effector_speed_at_contact_mps", summary(tally.speeds)},
                              {"foot_drift_m", summary(tally.drifts)},
                              {"bone_length_error_m_max", tally.worst_bone}};
    };
    Tally all;
    for (const auto& [semantics, tally] : tallies) {
        report["strikes"][semantics] = tally_json(tally);
        if (!semantics.starts_with("far_")) all.add(tally);
    }
    report["overall"] = tally_json(all);
    report["overall"]["joint_limit_violation_frames"] = {{"elbow_l", violations_by_joint[0]}, {"elbow_r", violations_by_joint[1]},
                                                         {"knee_l", violations_by_joint[2]}, {"knee_r", violations_by_joint[3]},
                                                         {"trunk", violations_by_joint[4]}};
    for (const auto& [regime, costs] : cost_by_regime) report["frame_cost_us"][regime] = summary(costs);
    report["frame_cost_us"]["baseline_plain_decode"] = summary(baseline_decode_us);
    // The least of three runs of each frame: the work itself, without the machine's interruptions.
    for (const auto& [regime, costs] : least_cost_by_regime) report["frame_cost_us_least_of_3"][regime] = summary(costs);
    report["frame_cost_us_least_of_3"]["baseline_plain_decode"] = summary(least_baseline_decode_us);
    report["allocations_per_frame"] = double(allocations) / std::max(1L, frames_stepped);
    for (const auto& [mode, values] : blend_pop) report["blend_pop_m_s2"][mode] = summary(values);
    report["frames"] = frames_stepped;
    std::cout << report.dump(2) << "\n";
    return 0;
}
