// kumite adapt: the retrieved strike played on a character from its guard, adapted so that the hit segment meets
// the target at the contact frame (core/strike_adaptation.h), written as BVH with a report.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"
#include "strike_reports.h"
#include "fighter_setup.h"

#include "kumite/runtime/strike_playback.h"
#include "strike_filmstrip.h"
#include "kumite/formats/atomic_file.h"

#include <algorithm>
#include <iostream>

namespace kumite::cli {

const CommandSpec& adapt_spec() {
    static const CommandSpec spec{
        "adapt",
        "[DB.kdb] --character NAME --target X,Y,Z --command punch|kick [--side left|right|any] [--kind KIND] [--height H] --record OUT.bvh|OUT.glb --report OUT.json [--verify]",
        "Plays the strike the retrieval picks for a character standing at the origin (facing +Z, in the guard):\n"
        "a short guard hold, then the clip blended in, decoded onto the character, its hit segment driven onto\n"
        "the target at the clip's annotated hit frame by the constraint ramp (limb IK, then CCD over the trunk when\n"
        "out of reach), stopped at the target after the contact (impact) and recovered along the clip's own\n"
        "retraction, elbows and knees bending as the clip bends them, support feet planted. Writes the motion as\n"
        "BVH on the character's skeleton and a JSON report.",
        0, 1,
        {{"character", "NAME", "a character of data/characters (see kumite characters)"},
         {"target", "X,Y,Z", "the target, world metres"},
         {"command", "SEMANTICS", "punch, kick, or any strike semantics the database holds"},
         {"side", "left|right|any", "which side strikes (default any)"},
         kind_flag(),
         height_flag(),
         {"record", "OUT.bvh|OUT.glb", "the adapted motion: BVH, or glTF with the character's body"},
         {"report", "OUT.json", "contact error, hit frame, overshoot, speed at contact, joint-limit violations, bone-length error,\n"
                                "foot drift, support foot, per-frame cost"},
         {"filmstrip", "OUT.png", "the frames around the contact from the side and the front: target, hit path, contact marked"},
         {"lead", "FRAMES", "guard frames before the strike (default 6)"},
         characters_dir_flag(), verify_flag(), json_flag()}};
    return spec;
}

int run_adapt(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(adapt_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> target_text = arguments.value("target");
    const std::optional<std::string> record = arguments.value("record");
    const std::optional<std::string> report_path = arguments.value("report");
    if (!target_text) return usage_error(adapt_spec(), "--target X,Y,Z is required");
    if (!record) return usage_error(adapt_spec(), "--record OUT.bvh (or OUT.glb) is required");
    if (std::optional<std::string> problem = recording_path_problem(*record)) return usage_error(adapt_spec(), "--record " + *problem);
    Result<Eigen::Vector3d> target = parse_point(*target_text, "--target");
    if (!target) return usage_error(adapt_spec(), target.error().message);
    const Result<long long> lead = arguments.integer("lead", 0, 1000, 6);
    if (!lead) return usage_error(adapt_spec(), lead.error().message);

    FighterSetup setup;
    if (std::optional<int> status = fighter_setup(setup, adapt_spec(), arguments)) return *status;
    const MotionDatabaseView& db = setup.database.view();
    RetrievalQuery query = setup.stage->query;
    query.target_world = *target;
    RetrievalWorkspace workspace = setup.stage->retriever->make_workspace();
    const RetrievalResult retrieved = setup.stage->retriever->query(query, workspace);
    if (!retrieved.found) {
        return input_error(setup.database_path + ": no " + strike_order_description(*arguments.value("command"), query.side, query.kind, query.height) +
                           " can start from the guard");
    }

    const StrikePlan plan{retrieved.clip, retrieved.start_frame, retrieved.contact_frame, retrieved.clip_to_world, *target};
    const StrikePlayback playback = strike_playback_run(*setup.stage->rig, db, setup.stage->standing, plan, int(*lead));
    const Skeleton& skeleton = setup.stage->character.clip.skeleton;

    const Result<void> written = write_recording(*record, playback.motion, setup.stage->character, characters_folder(arguments), *arguments.value("character"));
    if (!written) return input_error(written.error().message);
    const DbClip& clip = db.clips[retrieved.clip];
    if (const std::optional<std::string> filmstrip = arguments.value("filmstrip")) {
        const QString title = QString::fromStdString(std::string(db.string(clip.name)) + " on " + *arguments.value("character") + ", " +
                                                     *arguments.value("command") + " at " + *target_text);
        const Result<void> drawn = view::strike_filmstrip_save(playback, title, *filmstrip);
        if (!drawn) return input_error(drawn.error().message);
    }
    const nlohmann::json report = adapt_report_json(playback, retrieved, db, skeleton, *target);
    if (report_path) {
        if (Result<void> saved = write_file_atomically(*report_path, report.dump(2) + "\n"); !saved) return input_error(saved.error().message);
    }
    if (arguments.has("json")) {
        print_json(report);
    } else {
        std::cout << "wrote " << *record << ": " << playback.motion.frame_count() << " frames, " << db.string(clip.name) << " from frame "
                  << retrieved.start_frame << "; contact at frame " << playback.contact_frame << " (" << report["reach"].get<std::string>()
                  << "), error " << playback.contact_error_m << " m, overshoot " << playback.overshoot_m << " m, "
                  << playback.joint_limit_violations << " joint-limit violations, foot drift " << playback.foot_drift_m << " m, "
                  << report["frame_cost_us"]["median"] << " us/frame\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
