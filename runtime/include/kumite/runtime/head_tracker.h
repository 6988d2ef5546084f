#pragma once
// The user's head, from whichever source the room has (ARCHITECTURE.md "Inputs from the room"), behind one
// interface: `dtrack:PORT[:HEAD[,LEFT,RIGHT]]` (A.R.T. DTrack UDP, live; the hands are 6d bodies or 3d markers
// by id), `replay:FILE` (a CSV of t,x,y,z[,lx,ly,lz,rx,ry,rz]), `capture:FILE.bvh[:DISTANCE[:START_S]]` (a recorded
// person: capture_user.h), or `simulate:still|wander|walk[:SPEED]|dodge|dodge-seen|punch|counter|FILE` (a simulated or scripted
// user, deterministic with the seed). The user's hands come with the head, when tracked.

#include "kumite/runtime/capture_user.h"
#include "kumite/runtime/dtrack_receiver.h"
#include "kumite/runtime/replay_track.h"
#include "kumite/runtime/simulated_user.h"

#include <array>
#include <memory>
#include <optional>
#include <string_view>

namespace kumite {

class HeadTracker {
public:
    // `config` is used by dtrack: its port and head body are replaced by those in the spec. Errors say what is
    // wrong with the spec (ErrorCode::invalid) or the file or socket (io, parse).
    static Result<std::unique_ptr<HeadTracker>> open(std::string_view spec, DtrackConfig config, std::uint64_t seed);
    // A user the caller feeds each frame (an engine's own tracking: the C API, the Python module): feed() before
    // each step; the head stays as fed until the next feed.
    static std::unique_ptr<HeadTracker> fed();
    // The head and hands for the next steps (head null: not tracked). Only for a fed tracker.
    void feed(const Eigen::Vector3d* head, const UserHands& hands);

    // The head this frame (world metres), or null when the source has none (untracked, silent, a replay gap).
    // A live source answers only when a fresh sample arrived, so silence reaches the fighter.
    const Eigen::Vector3d* head(double t_s);
    // The hands of the frame head(t) read (none present when the source tracks no hands).
    const UserHands& hands() const { return m_hands; }
    // Where the fighter's head and chest are, and whether it is in its guard (not striking or recovering):
    // simulated users punch at them, some in reply to the guard's return. Call before head(t).
    void set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding = true);
    // Where the fighter's hands and feet are ([left hand, right hand, left foot, right foot], world): what an
    // answering simulated user sees a blow come from (before set_opponent).
    void set_opponent_limbs(const std::array<Eigen::Vector3d, 4>& limbs);
    // A supervisor order went out at t: simulated users that dodge react to it.
    void on_order(double t_s);

    bool live() const { return m_receiver != nullptr; } // steps on the wall clock
    long long packets() const { return m_receiver ? m_receiver->stats().packets : 0; }
    long long rejected() const { return m_receiver ? m_receiver->stats().rejected() : 0; }
    // A message for the supervisor, once (then null): see DtrackReceiver::take_notice.
    const char* take_notice() { return m_receiver ? m_receiver->take_notice() : nullptr; }
    // The recorded person, when the source is `capture:` (else null).
    const CaptureUser* capture() const { return m_capture ? &*m_capture : nullptr; }

private:
    HeadTracker() = default;
    std::optional<SimulatedUser> m_simulated;
    std::optional<ScriptedUser> m_scripted;
    std::optional<ReplayTrack> m_replay;
    std::optional<CaptureUser> m_capture;
    std::unique_ptr<DtrackReceiver> m_receiver;
    bool m_fed = false, m_fed_head_present = false;
    Eigen::Vector3d m_fed_head = Eigen::Vector3d::Zero();
    UserHands m_fed_hands;
    HeadSample m_sample;
    Eigen::Vector3d m_head = Eigen::Vector3d::Zero();
    UserHands m_hands;
};

} // namespace kumite
