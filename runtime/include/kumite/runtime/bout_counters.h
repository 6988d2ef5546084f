#pragma once
// What a bout counts for its report: orders and how they ended, strikes and their measures, the user's strikes and
// how the fighter met them, hit reactions, frame costs. One BoutCounters per bout, fed every fighter's events in
// the order they are told (BoutCounters::tally). Summaries are histograms in fixed memory, so that a bout of hours
// stays flat; `by_clip` is sized once, at the bout's start.

#include "kumite/core/motion_database.h"
#include "kumite/runtime/combinations.h"
#include "kumite/runtime/fighter_event.h"
#include "kumite/runtime/value_histogram.h"

#include <array>
#include <vector>

namespace kumite {

// What the tally remembers of one fighter between its events (the bout keeps one per fighter): the frame of the
// order its next strike answers (-1: none waiting), and its state as its last state event told it.
struct FighterTally {
    long long order_frame = -1;
    FighterState state = FighterState::rest;
};

struct BoutCounters {
    long long frames = 0, missed_frames = 0;
    long long orders = 0, strikes = 0, hits = 0, misses = 0, ignored_orders = 0;
    long long blocked_by_user = 0; // of the misses: met the user's glove or forearm first (user_guard.h)
    long long own_attacks = 0;     // orders the fighter gave itself (free sparring), of `orders`
    // Combinations' strikes: [combination][blow] thrown and landed (combinations.h).
    std::array<std::array<long long, 2>, k_combination_count> combination_strikes{}, combination_hits{};
    long long orders_queued = 0, orders_performed = 0, orders_expired = 0; // how orders ended (ignored_orders: refused)
    // Summaries in fixed memory, so that a bout of hours stays flat.
    ValueHistogram frame_us{0.1, 1e7};          // every frame's cost
    ValueHistogram command_to_strike_frames{0.5, 1e6};
    ValueHistogram impact_overshoot_m{1e-5, 10.0}; // per strike that stopped at the target (impact): how far past it
    ValueHistogram impact_held_s{1e-3, 100.0};     // ... and how long it stayed on the target (FighterEvent::held_at_target_s)
    ValueHistogram contact_speed_mps{1e-3, 1e3};   // per strike: the hit point's speed arriving at the contact
    // ... by kind of strike: punch, kick, knee, elbow (MoveKind::punch + i)
    std::array<ValueHistogram, 4> contact_speed_by_kind_mps{ValueHistogram{1e-3, 1e3}, ValueHistogram{1e-3, 1e3}, ValueHistogram{1e-3, 1e3},
                                                            ValueHistogram{1e-3, 1e3}};
    long long joint_limit_violations = 0;       // summed over strikes and frames
    long long impacts = 0, follow_throughs = 0; // strikes that stopped at the target, strikes the user dodged
    ValueHistogram prediction_error_m{1e-4, 100.0}; // per strike: the head at the contact to the target aimed at
    long long latched_strikes = 0, latched_hits = 0, predicted_strikes = 0, predicted_hits = 0; // by aim
    // The user's strikes at the fighter: how each ended, and how close a blocked one's path came to the forearm.
    long long user_strikes = 0, blocked = 0, slipped = 0, hit_by_user = 0, user_missed = 0, blocks = 0, slips = 0;
    long long slipped_on_course = 0; // slipped strikes whose path passed within the hit radius of the part unslipped
    long long blocked_on_course = 0; // blocked strikes whose course went on to the head or chest
    long long block_clips = 0; // of the blocks, captured ones (block_clips.h); the rest synthesized
    std::array<std::array<long long, 4>, 2> user_outcomes_by_target{}; // [head, chest][UserStrikeOutcome]
    // ... by what the fighter was doing when each ended (FighterState: resting, stepping, striking, in a hit
    // reaction): where the blows that land get through (its own strikes and hit reactions, mostly).
    std::array<std::array<long long, 4>, k_fighter_state_count> user_outcomes_by_fighter_state{};
    ValueHistogram forearm_to_path_m{1e-4, 10.0};
    // Per blow the fighter moved against: from seeing it to the move's first frame (defence.reaction_delay_s, or 0).
    ValueHistogram defence_move_after_seen_s{1e-3, 10.0};
    long long not_defended = 0; // blows seen that defence.defend_share left undefended
    // Per block, the fastest the blocking wrist or elbow moved relative to the shoulder while the fist came: captured
    // and synthesized blocks, and a captured one's against the same move in its clip (no pop: at most 1).
    ValueHistogram block_clip_arm_from_shoulder_mps{1e-3, 1e3}, synthesized_arm_from_shoulder_mps{1e-3, 1e3}, block_clip_speed_ratio{1e-3, 1e3};
    ValueHistogram blocking_wrist_mps{1e-3, 1e3}, blocking_elbow_mps{1e-3, 1e3}; // world, as the motion meter measures
    long long defence_joint_limit_violations = 0;
    double defence_foot_shift_m = 0.0; // the largest
    // The fighter's answers to the blows that landed: how many, from a captured clip, the angle between the clip's
    // head course and the one the blow asked for, how long after the blow they began.
    long long hit_reactions = 0, captured_hit_reactions = 0, hit_reaction_blows = 0; // (blows: the landed strikes they answer)
    ValueHistogram hit_reaction_angle_deg{1e-2, 360.0}, hit_reaction_delay_s{1e-3, 100.0};
    // The user's answers to the fighter's blows (user_response events), by kind of strike: punch, kick, knee, elbow.
    struct Responses {
        long long blows = 0, moved = 0, countered = 0, counters_landed = 0;
        long long anticipated = 0; // moved before the blow was visible (a negative response time: not in time_s)
        std::array<long long, k_response_kind_count> kinds{};
        std::array<long long, k_response_quality_count> quality{};
        ValueHistogram time_s{1e-3, 10.0}; // response times from the blow's visible start
    };
    std::array<Responses, 4> responses_by_kind;
    std::vector<std::array<long long, 2>> by_clip; // [database clip] strikes, hits (sized once, at the bout's start)
    double last_contact_error_m = -1.0;         // of the last strike; -1 before any
    bool last_hit = false;

    // Counts one event of a fighter, told in the frame numbered `frame` (frames counted before it). `fighter`: what
    // the tally remembers of the fighter that told it; `database`: the clips its strikes name. Allocates nothing.
    void tally(const FighterEvent& event, long long frame, const MotionDatabaseView& database, FighterTally& fighter);
};

} // namespace kumite
