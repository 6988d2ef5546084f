#pragma once
// A bout: what `kumite play` runs, headless or in the viewer. One or more fighters (side by side) against one
// user's head, driven by the supervisor's commands (a timed script, a stdin or TCP stream, or lines the window
// sends), stepped at a fixed rate. It counts what the report needs, keeps each step's events for the caller to
// log or show, and can record the first fighter on the starting character. After construction a step allocates
// nothing unless recording (the recording grows).

#include "kumite/core/skinned_mesh.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/runtime/attack_settings.h"
#include "kumite/runtime/bout_counters.h"
#include "kumite/runtime/drill_run.h"
#include "kumite/runtime/fighter.h"
#include "kumite/runtime/head_tracker.h"
#include "kumite/runtime/motion_meter.h"
#include "kumite/runtime/planning_budget.h"
#include "kumite/runtime/supervisor.h"

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kumite {

class OwnAttacks;


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
    AttackSettings attacks;          // the fighter's own attacks (free sparring), off by default
    std::uint64_t attack_seed = 1;   // their random stream
    FighterSettings fighter;
};

struct BoutEvent {
    int fighter = 0;
    FighterEvent event;
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
    // A drill to run from t = 0 (drill_run.h): each part sets its difficulty (or the bout's own) and its free
    // sparring, its attacks come with the frame's other commands, and its end ends the bout (quit_requested).
    void set_drill(DrillRun drill) { m_drill = std::move(drill); }
    const DrillRun* drill() const { return m_drill ? &*m_drill : nullptr; }
    // The fighters' difficulty level now (difficulty.h), or "custom".
    const char* difficulty() const;
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
    void apply(std::string_view line, const std::string& where, bool own = false); // own: the fighter's own attack
    void apply_drill_line(const DrillRun::Line& line);
    // The reaction, defence share and own attacks of a level (or of the bout's options) for every fighter.
    void set_pace(const DefenceSettings& defence, const AttackSettings& attacks);
    void tell(std::string_view message); // to the stream, else the message handler
    // The frame's parts, in the order step() calls them.
    void take_head(double t_s);
    void apply_commands(double t_s);
    void take_events(std::size_t fighter_index, Fighter& fighter);
    void record_first_fighter();
    void count_frame(std::chrono::steady_clock::time_point started);

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
    std::optional<DrillRun> m_drill;
    std::function<void(std::string_view)> m_message;
    std::vector<std::string> m_queued; // lines from command()
    std::vector<BoutEvent> m_events;
    std::vector<FighterTally> m_tallies; // what the counters remember of each fighter between its events
    BoutCounters m_counters;
    std::unique_ptr<MotionMeter> m_motion;
    std::unique_ptr<OwnAttacks> m_own_attacks;
    bool m_quit = false;
    bool m_have_head = false;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero();
    double m_now_s = 0.0;
    std::unique_ptr<MirDecoder> m_record_decoder;
    Pose m_record_pose;
    Clip m_recording;
};

} // namespace kumite
