// kumite adapt: the retrieved strike played on a character from its guard, adapted so that the hit segment meets
// the target at the contact frame (core/strike_adaptation.h), written as BVH with a report.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"
#include "fighter_setup.h"

#include "kumite/core/forward_kinematics.h"
#include "kumite/core/strike_adaptation.h"
#include "kumite/formats/atomic_file.h"
#include "kumite/formats/bvh_writer.h"

#include <algorithm>
#include <chrono>
#include <iostream>

namespace kumite::cli {

const CommandSpec& adapt_spec() {
    static const CommandSpec spec{
        "adapt",
        "DB.kdb --character NAME --target X,Y,Z --command punch|kick [--side left|right|any] --record OUT.bvh --report OUT.json",
        "Plays the strike the retrieval picks for a character standing at the origin (facing +Z, in the guard):\n"
        "a short guard hold, then the clip blended in, decoded onto the character, its hit segment driven onto\n"
        "the target at the clip's annotated hit frame by the constraint ramp (limb IK, then CCD over the trunk when\n"
        "out of reach), stopped at the target after the contact (impact) and recovered along the clip's own\n"
        "retraction, elbows and knees bending as the clip bends them, support feet planted. Writes the motion as\n"
        "BVH on the character's skeleton and a JSON report.",
        1, 1,
        {{"character", "NAME", "a character of data/characters (see kumite characters)"},
         {"target", "X,Y,Z", "the target, world metres"},
         {"command", "SEMANTICS", "punch, kick, or any strike semantics the database holds"},
         {"side", "left|right|any", "which side strikes (default any)"},
         {"record", "OUT.bvh", "the adapted motion"},
         {"report", "OUT.json", "contact error, hit frame, overshoot, speed at contact, joint-limit violations, bone-length error,\n"
                                "foot drift, support foot, per-frame cost"},
         {"lead", "FRAMES", "guard frames before the strike (default 6)"},
         characters_dir_flag(), json_flag()}};
    return spec;
}

namespace {

const char* reach_name(Reach reach) { return reach == Reach::limb ? "limb" : reach == Reach::torso ? "torso" : "unreachable"; }

nlohmann::json cost_json(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    auto at = [&](double q) { return values.empty() ? 0.0 : values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))]; };
    return {{"median", at(0.5)}, {"p99", at(0.99)}, {"max", values.empty() ? 0.0 : values.back()}};
}

} // namespace

int run_adapt(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(adapt_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> target_text = arguments.value("target");
    const std::optional<std::string> record = arguments.value("record");
    const std::optional<std::string> report_path = arguments.value("report");
    if (!target_text) return usage_error(adapt_spec(), "--target X,Y,Z is required");
    if (!record) return usage_error(adapt_spec(), "--record OUT.bvh is required");
    Result<Eigen::Vector3d> target = parse_point(*target_text, "--target");
    if (!target) return usage_error(adapt_spec(), target.error().message);
    const Result<long long> lead = arguments.integer("lead", 0, 1000, 6);
    if (!lead) return usage_error(adapt_spec(), lead.error().message);

    FighterSetup setup;
    if (std::optional<int> status = fighter_setup(setup, adapt_spec(), arguments)) return *status;
    const MotionDatabaseView& db = setup.database.view();
    RetrievalQuery query = setup.query;
    query.target_world = *target;
    RetrievalWorkspace workspace = setup.retriever->make_workspace();
    const RetrievalResult retrieved = setup.retriever->query(query, workspace);
    if (!retrieved.found) {
        return input_error(arguments.positionals[0] + ": no " + *arguments.value("command") + " with side " + side_name(query.side) +
                           " can start from the guard");
    }

    // Where the character is now: the guard, encoded, with both feet planted.
    const Skeleton& skeleton = setup.character.clip.skeleton;
    const RestAnatomy& anatomy = setup.anatomy;
    MirEncoder encoder(skeleton, anatomy);
    MirFrame current;
    encoder.encode(current, setup.standing.view());
    const std::array<Eigen::Vector3d, 2> ankles = {setup.rig->positions()[anatomy.limbs[int(Limb::leg_l)].extremity],
                                                   setup.rig->positions()[anatomy.limbs[int(Limb::leg_r)].extremity]};

    StrikeAdapter adapter(*setup.rig, db);
    StrikePlan plan{retrieved.clip, retrieved.start_frame, retrieved.contact_frame, retrieved.clip_to_world, *target};
    adapter.begin(plan, current, {true, true}, ankles);

    Clip output;
    output.skeleton = skeleton;
    output.frame_time_s = db.meta.frame_time_s;
    auto append = [&](const Pose& pose) {
        output.root_translations.push_back(pose.root_translation);
        output.local_rotations.insert(output.local_rotations.end(), pose.local_rotations.begin(), pose.local_rotations.end());
    };
    for (int i = 0; i < *lead; ++i) append(setup.standing);

    std::vector<double> costs;
    Pose pose;
    AdaptedFrame at_contact;
    std::vector<Reach> reaches;
    double bone_error = 0.0, drift = 0.0, lift = 0.0, overshoot = 0.0;
    int violations = 0;
    Eigen::Vector3d before_contact = Eigen::Vector3d::Zero();
    adapter.step(0, pose); // sizes the pose
    for (int i = 0; i < adapter.frame_count(); ++i) {
        const auto started = std::chrono::steady_clock::now();
        const AdaptedFrame frame = adapter.step(i, pose);
        costs.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count());
        if (frame.contact) at_contact = frame;
        if (i + 1 == adapter.contact_index()) before_contact = frame.effector;
        overshoot = std::max(overshoot, frame.past_target_m);
        violations += joint_violation_count(frame.joint_violations);
        reaches.push_back(frame.reach);
        bone_error = std::max(bone_error, bone_length_error(skeleton, adapter.positions()));
        for (int foot = 0; foot < 2; ++foot) {
            if (!adapter.support_feet()[foot]) continue;
            const Eigen::Vector3d ankle = adapter.positions()[anatomy.limbs[2 + foot].extremity];
            const Eigen::Vector3d pin = adapter.support_pins()[foot];
            drift = std::max(drift, Eigen::Vector2d(ankle.x() - pin.x(), ankle.z() - pin.z()).norm());
            lift = std::max(lift, ankle.y() - pin.y());
        }
        append(pose);
    }
    const double contact_error = (at_contact.effector - *target).norm();
    const double speed_at_contact = adapter.contact_index() > 0 ? (at_contact.effector - before_contact).norm() / db.meta.frame_time_s : 0.0;
    const bool support_lifted = lift > 0.02;

    const Result<void> written = bvh_write_file(*record, output, setup.character.layout, setup.character.unit);
    if (!written) return input_error(written.error().message);
    const DbClip& clip = db.clips[retrieved.clip];
    nlohmann::json report = {
        {"effector", skeleton.names[adapter.effector_joint()]},
        {"contact_frame", *lead + adapter.contact_index()},
        {"effector_at_contact", json_vec3(at_contact.effector)},
        {"target", json_vec3(*target)},
        {"contact_error_m", contact_error},
        {"hit_frame", *lead + (db.clips[retrieved.clip].hit_frame - retrieved.start_frame)},
        {"overshoot_m", overshoot},
        {"effector_speed_at_contact_mps", speed_at_contact},
        {"approach_direction", json_vec3(adapter.approach_direction())},
        {"joint_limit_violations", violations},
        {"reachable", at_contact.reach != Reach::unreachable},
        {"reach", reach_name(at_contact.reach)},
        {"bone_length_error_m", bone_error},
        {"foot_drift_m", drift},
        {"support_foot_lifted", support_lifted},
        {"support_foot_lift_m", lift},
        {"support_feet", {{"left", adapter.support_feet()[0]}, {"right", adapter.support_feet()[1]}}},
        {"frame_cost_us", cost_json(costs)},
        {"frames", output.frame_count()},
        {"clip", db.string(clip.name)},
        {"start_frame", retrieved.start_frame},
        {"retrieval_contact_frame", retrieved.contact_frame},
        {"offset_to_fix_m", (retrieved.contact_point_world - *target).norm()}};
    if (report_path) {
        if (Result<void> saved = write_file_atomically(*report_path, report.dump(2) + "\n"); !saved) return input_error(saved.error().message);
    }
    if (arguments.has("json")) {
        print_json(report);
    } else {
        std::cout << "wrote " << *record << ": " << output.frame_count() << " frames, " << db.string(clip.name) << " from frame "
                  << retrieved.start_frame << "; contact at frame " << report["contact_frame"] << " (" << reach_name(at_contact.reach)
                   << "), error " << contact_error << " m, overshoot " << overshoot << " m, " << violations << " joint-limit violations, foot drift " << drift << " m, " << report["frame_cost_us"]["median"]
                  << " us/frame\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
