#pragma once
// How the user answered one of the fighter's blows (the user_response event, one per strike): when the blow became
// visible, when and how the user first moved against it, whether in time, what became of it, and whether the user
// struck back within a second.
//
// The blow becomes visible at the first frame its striking part (fist, foot, knee, elbow) moves on the fighter's body
// (from its pelvis) faster than ResponseSettings::blow_visible_mps, in any direction: the limb leaving the guard. From the strike's start on, the
// user's first defensive motion is the first frame over a speed threshold (never earlier) of
//   - the head moving back along the blow's line (head_mps): a step back or lean back;
//   - the head leaving the blow's line (head_mps): a slip, or a duck when mostly downwards;
//   - a glove moving towards the blow's path, relative to the head (glove_mps), or along it when already on it (within
//     15 cm of its line: into the face, or out to meet it): a block, or a parry when it is across the path as the
//     blow arrives (8-25 cm past its line on the other side from where it rose);
// that starts after the strike began (a motion already under way then is not an answer) and holds for two frames.
// A glove that was on the path all along and blocked it is a block the user did not have to move for.

namespace kumite {

enum class ResponseKind { none, block, parry, slip, duck, step_back };
const char* response_kind_name(ResponseKind kind);
inline constexpr int k_response_kind_count = 6;

enum class ResponseQuality { in_time, late, none };
const char* response_quality_name(ResponseQuality quality);
inline constexpr int k_response_quality_count = 3;

struct ResponseSettings {
    double blow_visible_mps = 0.5; // the striking part moving on the body this fast: the blow is under way
    double head_mps = 0.4;         // the head moving back, or off the blow's line, this fast: an answer
    double glove_mps = 0.5;        // a glove moving towards the blow's path this fast (relative to the head)
    double counter_window_s = 1.0; // a strike of the user's this long after the blow's contact is a counter
};

struct UserResponse {
    double began_s = 0.0;          // the strike began (the fighter left its guard)
    double visible_s = -1.0;       // its striking part first left the guard (blow_visible_mps); -1: never
    double contact_s = -1.0;       // its contact (blocked, hit or missed there)
    ResponseKind kind = ResponseKind::none;
    bool moved = false;            // false: no answer, or a guard held on the path that blocked it
    double response_s = -1.0;      // the user's first defensive motion (moved), else -1
    double response_time_s = -1.0; // response_s - visible_s (moved and visible), else -1
    ResponseQuality quality = ResponseQuality::none;
    bool countered = false;        // a strike of the user's within counter_window_s after the contact
    double counter_s = -1.0;
    bool counter_landed = false;   // it hit the fighter
};

} // namespace kumite
