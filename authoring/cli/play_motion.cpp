#include "play_motion.h"

namespace kumite::cli {
namespace {

nlohmann::json speeds_json(const JointSpeeds& speeds) {
    return {{"wrist_mps", speeds.wrist_mps}, {"ankle_mps", speeds.ankle_mps}, {"elbow_radps", speeds.elbow_radps}, {"knee_radps", speeds.knee_radps},
            {"elbow_mps", speeds.elbow_mps}};
}

// Over the library's: the ratio of each joint's speed to the library's for the kind (0 when the library has none).
nlohmann::json ratios_json(const JointSpeeds& speeds, const JointSpeeds& library) {
    auto ratio = [](double value, double bar) { return bar > 0.0 ? value / bar : 0.0; };
    return {{"wrist", ratio(speeds.wrist_mps, library.wrist_mps)}, {"ankle", ratio(speeds.ankle_mps, library.ankle_mps)},
            {"elbow", ratio(speeds.elbow_radps, library.elbow_radps)}, {"knee", ratio(speeds.knee_radps, library.knee_radps)},
            {"elbow_travel", ratio(speeds.elbow_mps, library.elbow_mps)}};
}

} // namespace

nlohmann::json play_motion_json(const Bout& bout) {
    const MotionMeter& meter = bout.motion();
    const auto library = library_joint_speeds(bout.database(), bout.character_skeleton(0), bout.character_anatomy(0));
    nlohmann::json by_move = nlohmann::json::object();
    for (int k = 0; k < k_move_kind_count; ++k) {
        const long long frames = meter.frames()[std::size_t(k)];
        if (frames == 0) continue;
        nlohmann::json entry = speeds_json(meter.fastest()[std::size_t(k)]);
        entry["frames"] = frames;
        entry["fastest_wrist_at_s"] = meter.peak_times()[std::size_t(k)].wrist_at_s;
        entry["fastest_ankle_at_s"] = meter.peak_times()[std::size_t(k)].ankle_at_s;
        // The bar the fighter's speed limit holds the kind to (speed_bar: a hold against the guard's clips, a recovery
        // against the fastest strike's, wrists and ankles never above the human limit).
        const JointSpeeds bar = speed_bar(library, MoveKind(k));
        entry["library"] = speeds_json(bar);
        entry["over_library"] = ratios_json(meter.fastest()[std::size_t(k)], bar);
        long long held = 0;
        for (int f = 0; f < bout.fighter_count(); ++f) held += bout.fighter(f).held_back_frames()[std::size_t(k)];
        entry["held_back_frames"] = held; // the speed limit showed the pose short of the one asked for
        by_move[move_kind_name(MoveKind(k))] = entry;
    }
    nlohmann::json library_by_move = nlohmann::json::object();
    for (int k = 0; k < k_move_kind_count; ++k) {
        const JointSpeeds& speeds = library[std::size_t(k)];
        if (speeds.wrist_mps > 0.0 || speeds.ankle_mps > 0.0) library_by_move[move_kind_name(MoveKind(k))] = speeds_json(speeds);
    }
    const ValueHistogram& metres = meter.distance_m();
    const ValueHistogram& legs = meter.distance_legs();
    nlohmann::json contact = nlohmann::json::object();
    for (int k = 0; k < 4; ++k) {
        const ValueHistogram& speeds = bout.counters().contact_speed_by_kind_mps[std::size_t(k)];
        if (!speeds.empty()) {
            contact[move_kind_name(MoveKind(int(MoveKind::punch) + k))] = {{"median", speeds.quantile(0.5)}, {"max", speeds.max()}, {"count", speeds.count()}};
        }
    }
    double lag_m = 0.0;
    for (int f = 0; f < bout.fighter_count(); ++f) lag_m = std::max(lag_m, bout.fighter(f).held_back_lag_m());
    return {{"by_move", by_move},
            {"held_back_lag_max_m", lag_m},
            {"speed_at_contact_by_kind_mps", contact},
            {"fastest", speeds_json(meter.fastest_overall())},
            {"library", library_by_move},
            {"library_character", bout.character_name(0)},
            {"distance_between_strikes",
             {{"frames", metres.count()},
              {"median_m", metres.quantile(0.5)}, {"p5_m", metres.quantile(0.05)}, {"p95_m", metres.quantile(0.95)},
              {"median_legs", legs.quantile(0.5)}, {"p5_legs", legs.quantile(0.05)}, {"p95_legs", legs.quantile(0.95)}}}};
}

} // namespace kumite::cli
