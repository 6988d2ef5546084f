#pragma once
// A bout as its event lines tell it (the JSON lines `kumite play --events` writes): per fighter the orders, strikes,
// the user's strikes and the defences, character switches and tracker losses; for the room the user's head path and
// the fighters' positions; the lines that frame the bout. Built line by line, from a file or from a running bout.
//
// Reading is forgiving and never throws: a line that is not an event (not JSON, no time or type, a negative or
// absurd time, a fighter number out of range) stops the reading there, and `stopped` says where and why; what came before is kept.
// Lines of types it does not know are counted and skipped (newer writers, other tools).

#include "kumite/core/result.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace kumite::report {

struct RoomPoint {
    double t_s = 0.0;
    double x = 0.0, y = 0.0, z = 0.0; // world metres, Y up
};

struct OrderRecord {
    double t_s = 0.0;
    std::string command;
    bool queued = false; // it came while the fighter was busy and waited
};

struct OrderEnd {
    enum class How { performed, refused, expired };
    How how = How::performed;
    double t_s = 0.0;
    double waited_s = -1.0; // performed and expired orders: since the order came (-1: not said)
    std::string why;        // refused and expired orders
};

struct StrikeRecord {
    double t_s = 0.0; // the contact
    std::string command, kind, height, side, clip, aim;
    bool hit = false;
    std::string blocked_by; // the user's glove or forearm that blocked it (empty: none)
    bool impact = true;
    double contact_error_m = -1.0, effector_speed_mps = -1.0, prediction_error_m = -1.0, overshoot_m = -1.0; // -1: none
    std::optional<RoomPoint> target, aimed_point_at_contact;
};

struct UserStrikeRecord {
    double seen_s = -1.0, end_s = -1.0; // -1: that event is missing
    std::string hand, aimed_at, move, outcome; // outcome empty: the strike had not ended when the events did
    bool detected = true;
    // Blocked or slipped, and the hand would have landed without it (its course event, its unslipped clearance).
    bool kept_off = false;
    // How long the hand had been closing on what it met before it met it (user_strike_end's approach_s); -1: not told.
    double approach_s = -1.0;
};

// How the user answered one of the fighter's blows (a user_response line).
struct ResponseRecord {
    double t_s = 0.0, contact_s = -1.0;
    std::string attack;   // "punch straight", "kick front", ...
    std::string result;   // the blow: hit, blocked, miss
    std::string response; // block, parry, slip, duck, step_back, none
    std::string quality;  // in_time, late, none
    bool moved = false;
    double response_time_s = -1e9; // from the blow's visible start (negative: moved before it); -1e9: none
    bool countered = false, counter_landed = false;
};

struct TrackerLoss {
    double lost_s = 0.0, back_s = -1.0; // -1: still lost when the events ended
};

struct CharacterSwitch {
    double t_s = 0.0;
    std::string name;
};

struct FighterLog {
    std::vector<OrderRecord> orders;
    std::vector<OrderEnd> order_ends;
    std::vector<StrikeRecord> strikes;
    std::vector<UserStrikeRecord> user_strikes;
    std::vector<ResponseRecord> responses;
    std::vector<CharacterSwitch> characters;
    std::vector<TrackerLoss> tracker_losses;
    std::vector<RoomPoint> positions; // where the fighter stood (on the floor), when it moved
    long long joint_limit_violations = 0;
    // Its answers to the user's strikes that landed: reactions, from a captured clip, the landed strikes they answer.
    long long hit_reactions = 0, captured_hit_reactions = 0, hit_reaction_blows = 0;
};

class SessionLog {
public:
    static constexpr int k_max_fighters = 100000;

    // One event line. Returns false (and sets `stopped`) when it cannot be read; every later line is then ignored.
    bool add(const nlohmann::json& line);
    // One line of text; `line_number` from 1, for the message.
    bool add_text(std::string_view text, long long line_number);

    std::optional<std::string> stopped;      // "line N: why" when reading stopped before the end
    long long lines = 0;                     // lines taken
    long long unknown_lines = 0;             // lines of a type the log does not know
    double last_t_s = 0.0;                   // the latest time seen
    std::optional<nlohmann::json> start, end, tracker_source; // bout_start, bout_end, tracker_source lines
    std::vector<RoomPoint> head_path;        // the user's head (track lines)
    std::map<int, FighterLog> fighters;      // by fighter number

private:
    bool stop(std::string why);
    FighterLog& fighter(int index) { return fighters[index]; }
    std::map<int, std::vector<std::size_t>> m_open_user_strikes; // per fighter: user strikes seen, not yet ended
    // per fighter and hand (left, right): the user strike that ended last, as its index + 1 (0: none), for its course event
    std::map<int, std::array<std::size_t, 2>> m_last_ended;
};

// Reads an events file. An error only when the file cannot be opened; a bad line ends the reading (`stopped`, with
// the file's name).
Result<SessionLog> read_session_log(const std::filesystem::path& path);

} // namespace kumite::report
