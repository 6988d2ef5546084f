#pragma once
// A bout: what `kumite play` runs, headless or in the viewer. One or more fighters (side by side) against one
// user's head, driven by the supervisor's commands (a timed script, a stdin or TCP stream, or lines the window
// sends), stepped at a fixed rate. It counts what the report needs, keeps each step's events for the caller to
// log or show, and can record the first fighter on the starting character. After construction a step allocates
// nothing unless recording (the recording grows).

#include "kumite/core/skinned_mesh.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/runtime/value_histogram.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/head_tracker.h"
#include "kumite/runtime/motion_meter.h"
#include "kumite/runtime/planning_budget.h"
#include "kumite/runtime/supervisor.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace kumite {

struct BoutCharacter {
    std::string name;
    BvhFile file; // its first frame is the rest pose
    std::shared_ptr<const SkinnedMesh> body; // its skinned body on file's skeleton (character_body.h), or null
};

struct BoutOptions {
    int fighters = 1;
    int start_character = 0; // index into the characters
    double lead_s = 0.4;     // strikes start at least this long before their contact (a sparring partner telegraphs)
    double contact_extension = RetrievalSettings{}.contact_extension; // where strikes make contact (retrieval.h)
    double contact_speed_share = RetrievalSettings{}.contact_speed_share;
    double rate_hz = 60.0;
    bool record = false;
    // At most this many fighters plan a strike per frame (planning_budget.h); the others plan on the next frames.
    // 0: no limit. A plan (one retrieval, the adaptation's set-up) costs about half a millisecond: 14 keep a frame
    // of 200 fighters under 11 ms, and 200 fighters ordered at once are all served within 15 frames (250 ms).
    int plans_per_frame = 14;
    FighterSettings fighter;
};

struct BoutEvent {
    int fighter = 0;
    FighterEvent event;
};

struct BoutCounters {
    long long frames = 0, missed_frames = 0;
    long long orders = 0, strikes = 0, hits = 0, misses = 0, ignored_orders = 0;
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
    // reaction): where the blows that land get through (issue 44: its own strikes and hit reactions, mostly).
    std::array<std::array<long long, 4>, k_fighter_state_count> user_outcomes_by_fighter_state{};
    ValueHistogram forearm_to_path_m{1e-4, 10.0};
    // Per block, the fastest the blocking wrist or elbow moved relative to the shoulder while the fist came: captured
    // and synthesized blocks, and a captured one's against the same move in its clip (no pop: at most 1).
    ValueHistogram block_clip_arm_speed_mps{1e-3, 1e3}, synthesized_arm_speed_mps{1e-3, 1e3}, block_clip_speed_ratio{1e-3, 1e3};
    long long defence_joint_limit_violations = 0;
    double defence_foot_shift_m = 0.0; // the largest
    // The fighter's answers to the blows that landed: how many, from a captured clip, the angle between the clip's
    // head course and the one the blow asked for, how long after the blow they began.
    long long hit_reactions = 0, captured_hit_reactions = 0, hit_reaction_blows = 0; // (blows: the landed strikes they answer)
    ValueHistogram hit_reaction_angle_deg{1e-2, 360.0}, hit_reaction_delay_s{1e-3, 100.0};
    std::vector<std::array<long long, 2>> by_clip; // [database clip] strikes, hits (sized once, at the bout's start)
    double last_contact_error_m = -1.0;         // of the last strike; -1 before any
    bool last_hit = false;
};

class Bout {
public:
    static Result<std::unique_ptr<Bout>> create(const MotionDatabaseView& database, std::vector<BoutCharacter> characters,
                                                std::unique_ptr<HeadTracker> tracker, const BoutOptions& options);
    ~Bout();
    Bout(const Bout&) = delete;
    Bout& operator=(const Bout&) = delete;

    void set_script(CommandScript script) { m_script = std::move(script), m_has_script = true; }
    void set_stream(std::unique_ptr<CommandStream> stream) { m_stream = std::move(stream); }
    // Where messages go (bad command lines when there is no stream to answer); default: ignored.
    void set_message_handler(std::function<void(std::string_view)> handler) { m_message = std::move(handler); }

    // A supervisor line, applied at the next step. Returns the error (unknown verb or character) or nothing.
    Result<void> command(std::string_view line);

    // One frame at time t: commands due, the head, every fighter. Afterwards events() holds this frame's events.
    void step(double t_s);

    // Frames the caller could not step in time and skipped (a real-time loop that stalled).
    void count_missed_frames(long long frames) { m_counters.missed_frames += frames; }

    std::span<const BoutEvent> events() const { return m_events; }
    const BoutCounters& counters() const { return m_counters; }
    // The fighters' joint speeds by kind of move and the distance they keep (motion_meter.h).
    const MotionMeter& motion() const { return *m_motion; }
    bool quit_requested() const { return m_quit; }
    double now_s() const { return m_now_s; } // the time of the last step
    double rate_hz() const { return m_options.rate_hz; }
    bool live() const { return m_tracker->live(); }
    const HeadTracker& tracker() const { return *m_tracker; }
    HeadTracker& tracker() { return *m_tracker; } // to feed a fed tracker (HeadTracker::fed) before a step
    const Eigen::Vector3d* head() const { return m_have_head ? &m_head : nullptr; } // as of the last step
    const UserHands& hands() const { return m_tracker->hands(); }                    // as of the last step

    int fighter_count() const { return static_cast<int>(m_fighters.size()); }
    const Fighter& fighter(int index) const { return *m_fighters[index]; }
    // Fighters index characters from the starting one on; this names and shapes them in that order.
    const std::string& character_name(int fighter_character) const;
    const Skeleton& character_skeleton(int fighter_character) const;
    const RestAnatomy& character_anatomy(int fighter_character) const;
    // Its body (prepared once when the bout is created; shared by every fighter on it), or null.
    const std::shared_ptr<const SkinnedMesh>& character_body(int fighter_character) const;
    int character_count() const { return static_cast<int>(m_characters.size()); }
    const MotionDatabaseView& database() const { return m_db; }
    const Retriever& retriever() const { return *m_retriever; }

    // The first fighter on the starting character, one frame per step (when options.record).
    const Clip& recording() const { return m_recording; }
    const BvhFile& starting_character_file() const;

private:
    Bout() = default;
    struct Character;
    int fighter_character_of(const std::string& name) const;
    void apply(std::string_view line, const std::string& where);

    MotionDatabaseView m_db;
    BoutOptions m_options;
    std::vector<std::unique_ptr<Character>> m_characters;
    std::unique_ptr<Retriever> m_retriever;
    std::vector<std::unique_ptr<Fighter>> m_fighters;
    std::vector<Fighter*> m_fighter_pointers; // the same, for the planning budget
    std::unique_ptr<PlanningBudget> m_planning;
    std::unique_ptr<HeadTracker> m_tracker;
    CommandScript m_script;
    bool m_has_script = false;
    std::unique_ptr<CommandStream> m_stream;
    std::function<void(std::string_view)> m_message;
    std::vector<std::string> m_queued; // lines from command()
    std::vector<BoutEvent> m_events;
    std::vector<long long> m_order_frame;
    std::vector<FighterState> m_fighter_state; // each fighter's, as its state events say
    BoutCounters m_counters;
    std::unique_ptr<MotionMeter> m_motion;
    bool m_quit = false;
    bool m_have_head = false;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero();
    double m_now_s = 0.0;
    std::unique_ptr<MirDecoder> m_record_decoder;
    Pose m_record_pose;
    Clip m_recording;
};

} // namespace kumite
