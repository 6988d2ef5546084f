#include "kumite/runtime/fighter.h"

#include "fighter_body.h"

#include "kumite/core/hit_trajectory.h"
#include "kumite/core/joint_limits.h"
#include "kumite/core/mir_edit.h"
#include "kumite/core/smoothstep.h"

#include <algorithm>
#include <limits>
#include <cmath>

namespace kumite {
namespace {

int first_clip_of(const MotionDatabaseView& db, std::string_view semantics) {
    for (std::size_t c = 0; c < db.clips.size(); ++c) {
        if (db.string(db.clips[c].semantics) == semantics) return static_cast<int>(c);
    }
    return -1;
}

} // namespace

const char* fighter_state_name(FighterState state) {
    switch (state) {
    case FighterState::rest: return "rest";
    case FighterState::approach: return "approach";
    case FighterState::strike: return "strike";
    case FighterState::recover: return "recover";
    case FighterState::hold: return "hold";
    }
    return "?";
}

const char* fighter_aim_name(FighterAim aim) { return aim == FighterAim::predicted ? "predicted" : "latched"; }

std::optional<FighterAim> fighter_aim_from_name(std::string_view name) {
    if (name == "latched") return FighterAim::latched;
    if (name == "predicted") return FighterAim::predicted;
    return std::nullopt;
}

const char* target_part_name(TargetPart part) {
    switch (part) {
    case TargetPart::head: return "head";
    case TargetPart::chin: return "chin";
    case TargetPart::chest: return "chest";
    case TargetPart::solar_plexus: return "solar_plexus";
    }
    return "?";
}

const char* fighter_event_name(FighterEvent::Type type) {
    switch (type) {
    case FighterEvent::Type::order: return "order";
    case FighterEvent::Type::ignored_order: return "ignored_order";
    case FighterEvent::Type::state: return "state";
    case FighterEvent::Type::strike: return "strike";
    case FighterEvent::Type::strike_end: return "strike_end";
    case FighterEvent::Type::tracker_lost: return "tracker_lost";
    case FighterEvent::Type::tracker_back: return "tracker_back";
    case FighterEvent::Type::character: return "character";
    case FighterEvent::Type::user_strike: return "user_strike";
    case FighterEvent::Type::user_strike_end: return "user_strike_end";
    case FighterEvent::Type::order_queued: return "order_queued";
    case FighterEvent::Type::order_performed: return "order_performed";
    case FighterEvent::Type::order_expired: return "order_expired";
    }
    return "?";
}

Fighter::Fighter(const MotionDatabaseView& database, const Retriever& retriever, std::vector<CharacterRig*> characters,
                 FighterSettings settings)
    : m_db(database), m_retriever(retriever), m_settings(settings), m_head_motion(settings.head_motion), m_defence(settings.defence),
      m_block_clips(m_db),
      m_workspace(retriever.make_workspace()) {
    for (CharacterRig* character : characters) m_bodies.push_back(std::make_unique<Body>(character, database));
    m_guard_clip = first_clip_of(database, "rest");
    if (m_guard_clip < 0) m_guard_clip = 0; // a database without a guard: its first clip stands in
    const char* steps[] = {"step_forward", "step_back", "step_left", "step_right"};
    for (int i = 0; i < 4; ++i) m_step_clips[i] = first_clip_of(database, steps[i]);
    // Size every buffer the frames reuse, so that step() never allocates.
    for (auto& body : m_bodies) {
        body->rig->stand_at_origin(m_pose, database);
        body->encoder.encode(m_mir, m_pose.view());
        body->decoder.decode(m_pose, m_mir);
        m_shown_by_adapter = false;
        m_defended_frame = m_shown_mir = m_mir;
        body->adapter.begin({first_clip_of(database, "punch") >= 0 ? first_clip_of(database, "punch") : 0, 0, 0, {}, {}}, m_mir,
                            {true, true}, {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
    }
    Body& body = *m_bodies[0];
    body.rig->stand_at_origin(m_pose, database);
    body.encoder.encode(m_mir, m_pose.view());
    m_clip_frame = m_next_frame = m_blend_from = m_strike_start = m_mir;
    m_heading = body.rig->heading();
    m_heading.origin.x() += settings.start_x_m;
}

Fighter::~Fighter() = default;

std::span<const Eigen::Vector3d> Fighter::positions() const {
    const Body& body = *m_bodies[m_character];
    return m_shown_by_adapter ? body.adapter.positions() : body.decoder.model_positions();
}

std::span<const Eigen::Quaterniond> Fighter::rotations() const {
    const Body& body = *m_bodies[m_character];
    return m_shown_by_adapter ? body.adapter.rotations() : body.decoder.model_rotations();
}

Eigen::Vector3d Fighter::part_position(BodyPart part) const {
    const int joint = m_bodies[m_character]->rig->anatomy().body_map.joint(part);
    return joint >= 0 ? positions()[joint] : m_heading.origin;
}

void Fighter::push_event(const FighterEvent& event) {
    if (m_event_count < static_cast<int>(m_events.size())) m_events[m_event_count++] = event;
}

void Fighter::enter(FighterState state, double t_s) {
    if (state == m_state && m_started) return;
    m_state = state;
    m_state_since_s = t_s;
    FighterEvent event;
    event.type = FighterEvent::Type::state;
    event.t_s = t_s;
    event.state = state;
    push_event(event);
}

void Fighter::remember_strike(int clip) {
    m_recent_clips[m_recent_next] = clip;
    m_recent_next = (m_recent_next + 1) % k_max_variety_recent;
    m_recent_count = std::min(m_recent_count + 1, k_max_variety_recent);
}

RetrievalResult Fighter::query_with_variety(RetrievalQuery& query, bool& varied) {
    varied = false;
    query.excluded_clips = {};
    query.score_limit = std::numeric_limits<double>::infinity();
    RetrievalResult best = m_retriever.query(query, m_workspace);
    const int recent = std::min({m_settings.variety_recent, m_recent_count, k_max_variety_recent});
    if (!best.found || recent <= 0 || m_settings.variety_margin <= 0.0) return best;
    // The last `recent` clips, newest first: m_recent_clips is a ring.
    std::array<int, k_max_variety_recent> excluded{};
    for (int k = 0; k < recent; ++k) excluded[k] = m_recent_clips[(m_recent_next - 1 - k + k_max_variety_recent) % k_max_variety_recent];
    if (std::find(excluded.begin(), excluded.begin() + recent, best.clip) == excluded.begin() + recent) return best;
    query.excluded_clips = std::span<const int>(excluded.data(), recent);
    query.score_limit = best.score + m_settings.variety_margin;
    RetrievalResult other = m_retriever.query(query, m_workspace);
    query.excluded_clips = {};
    query.score_limit = std::numeric_limits<double>::infinity();
    if (!other.found) return best;
    varied = true;
    return other;
}

void Fighter::set_character(int index) {
    if (index < 0 || index >= static_cast<int>(m_bodies.size()) || index == m_character) return;
    m_character = index;
    m_defence.reset();
    m_block_lagging = false; // the last arm shown was the other body's
    FighterEvent event;
    event.type = FighterEvent::Type::character;
    event.t_s = m_now_s;
    event.character = index;
    push_event(event);
    if (m_state == FighterState::strike) { // the strike carries on, on the new skeleton
        m_bodies[m_character]->decoder.decode(m_pose, m_strike_start);
        m_shown_by_adapter = false;
        begin_strike();
    }
}

double Fighter::leg_length() const { return m_bodies[m_character]->rig->anatomy().leg_length; }

double Fighter::distance_to_user() const {
    const Eigen::Vector3d to_user = m_head - m_heading.origin;
    return Eigen::Vector2d(to_user.x(), to_user.z()).norm();
}

HeadingFrame Fighter::heading_towards_user() const {
    HeadingFrame heading = m_heading;
    if (m_tracking) {
        const Eigen::Vector3d to_user = m_head - heading.origin;
        // At most k_max_turn_rad (90 degrees) per clip: a user who walks round (or, recorded, through) the fighter is followed
        // over a few clips. A larger turn at once, blended over blend_s, twists the trunk (hips and chest slerped
        // separately take different ways round near 180 degrees) and reads as a spin.
        constexpr double k_max_turn_rad = 90.0 * 3.14159265358979 / 180.0;
        if (Eigen::Vector2d(to_user.x(), to_user.z()).norm() > 0.05) {
            const double wanted = std::atan2(to_user.x(), to_user.z());
            const double turn = std::remainder(wanted - heading.yaw_rad, 2.0 * 3.14159265358979);
            heading.yaw_rad += std::clamp(turn, -k_max_turn_rad, k_max_turn_rad);
        }
    }
    return heading;
}

void Fighter::start_clip(int clip, double t_s, bool face_user, double step_scale) {
    m_blend_from = m_mir;
    m_blend_start_s = t_s;
    m_clip = clip;
    m_clip_start_s = t_s;
    m_clip_scale = step_scale;
    MirFrame& first = m_next_frame; // scratch
    db_mir_frame_load(first, m_db.mir_frames[m_db.clips[clip].first_pose]);
    m_clip_hip_start = first.hip_centre;
    m_foot_pinned = {false, false};
    m_foot_release_s = {-1e9, -1e9};
    const double leg = m_bodies[m_character]->rig->anatomy().leg_length;
    m_clip_to_world = clip_alignment(m_db, clip, 0, leg, face_user ? heading_towards_user() : m_heading);
}

double Fighter::clip_stride_m(int clip) const {
    if (clip < 0) return 0.0;
    const DbClip& c = m_db.clips[clip];
    const DbMirFrame& first = m_db.mir_frames[c.first_pose];
    const DbMirFrame& last = m_db.mir_frames[c.first_pose + c.frame_count - 1];
    const double dx = last.hip_centre[0] - first.hip_centre[0], dz = last.hip_centre[2] - first.hip_centre[2];
    return std::hypot(dx, dz) * leg_length();
}

void Fighter::play_clip(double t_s) {
    const DbClip& clip = m_db.clips[m_clip];
    const double index = std::min((t_s - m_clip_start_s) / m_db.meta.frame_time_s, double(clip.frame_count - 1));
    const int whole = static_cast<int>(index);
    const double leg = m_bodies[m_character]->rig->anatomy().leg_length;
    db_mir_frame_load(m_clip_frame, m_db.mir_frames[clip.first_pose + whole]);
    if (index - whole > 1e-9) {
        db_mir_frame_load(m_next_frame, m_db.mir_frames[clip.first_pose + std::min<int>(whole + 1, clip.frame_count - 1)]);
        mir_frame_blend(m_mir, m_clip_frame, m_next_frame, index - whole);
        m_clip_frame = m_mir;
    }
    if (m_clip_scale < 0.999) { // a shortened step: the hips travel less, the feet stay locked while planted
        m_clip_frame.hip_centre.x() = m_clip_hip_start.x() + m_clip_scale * (m_clip_frame.hip_centre.x() - m_clip_hip_start.x());
        m_clip_frame.hip_centre.z() = m_clip_hip_start.z() + m_clip_scale * (m_clip_frame.hip_centre.z() - m_clip_hip_start.z());
    }
    mir_frame_move_on_floor(m_clip_frame, m_clip_to_world, leg);
    const double blend = m_settings.blend_s > 0.0 ? smoothstep((t_s - m_blend_start_s) / m_settings.blend_s) : 1.0;
    if (blend < 1.0) {
        mir_frame_blend(m_mir, m_blend_from, m_clip_frame, blend);
    } else {
        m_mir = m_clip_frame;
    }
    Body& body = *m_bodies[m_character];
    body.decoder.decode(m_pose, m_mir);
    m_shown_by_adapter = false;
    if (m_clip_scale < 0.999) lock_feet(t_s, clip.first_pose + whole);
    else m_pins = {};
    apply_defence();
}

void Fighter::lock_feet(double t_s, int pose) {
    // A planted foot is pinned where it was when it landed; a foot that lifts carries the difference between its
    // pin and the shortened step's path and sheds it over 0.3 s, so nothing jumps.
    Body& body = *m_bodies[m_character];
    const RestAnatomy& anatomy = body.rig->anatomy();
    const auto positions = body.decoder.model_positions();
    const std::uint32_t flags = m_db.poses[pose].flags;
    const bool planted[2] = {(flags & db_pose_left_foot_planted) != 0, (flags & db_pose_right_foot_planted) != 0};
    const int legs[2] = {int(Limb::leg_l), int(Limb::leg_r)};
    m_pins = {};
    for (int foot = 0; foot < 2; ++foot) {
        const Eigen::Vector3d free_position = positions[anatomy.limbs[legs[foot]].extremity];
        const double fade = 1.0 - smoothstep((t_s - m_foot_release_s[foot]) / 0.3);
        const Eigen::Vector3d shown = free_position + fade * m_foot_release_offset[foot];
        if (planted[foot] && !m_foot_pinned[foot]) {
            m_foot_pinned[foot] = true;
            m_foot_pin[foot] = shown;
        } else if (!planted[foot] && m_foot_pinned[foot]) {
            m_foot_pinned[foot] = false;
            m_foot_release_offset[foot] = m_foot_pin[foot] - free_position;
            m_foot_release_s[foot] = t_s;
        }
        if (m_foot_pinned[foot]) {
            m_pins.pinned[legs[foot]] = true;
            m_pins.extremity_world[legs[foot]] = m_foot_pin[foot];
        } else {
            m_pins.extremity_offset_world[legs[foot]] = (1.0 - smoothstep((t_s - m_foot_release_s[foot]) / 0.3)) * m_foot_release_offset[foot];
        }
    }
    body.decoder.decode(m_pose, m_mir, m_pins);
    m_shown_by_adapter = false;
    body.encoder.encode(m_mir, m_pose.view()); // the next blend starts from what is shown
}

void Fighter::begin_strike() {
    // The feet stay where the last decoded pose (the strike's start) has them.
    Body& body = *m_bodies[m_character];
    const auto positions = body.decoder.model_positions();
    const RestAnatomy& anatomy = body.rig->anatomy();
    body.adapter.begin(m_plan, m_strike_start, {true, true},
                       {positions[anatomy.limbs[int(Limb::leg_l)].extremity], positions[anatomy.limbs[int(Limb::leg_r)].extremity]});
    body.adapter.set_impact(m_strike_impact); // a switch after the contact keeps the strike's outcome
}

FighterEvent Fighter::strike_event(FighterEvent::Type type, double t_s) const {
    FighterEvent event = order_event(type, t_s, m_strike_order);
    event.varied = m_strike_varied;
    event.clip = m_plan.clip;
    event.impact = m_strike_impact;
    event.aim = m_strike_aim;
    event.target = m_plan.target_world;
    event.head_speed_mps = m_strike_head_speed_mps;
    event.retrieval_offset_m = m_strike_offset_m;
    event.target_part = m_strike_part;
    event.reachable = m_strike_reachable;
    event.steered_m = (m_plan.target_world - m_planned_target).norm();
    return event;
}

void Fighter::steer_strike(double to_contact_s) {
    if (m_settings.steer_until_s <= 0.0 || m_strike_aim != FighterAim::predicted || !m_tracking || !m_head_motion.ready()) return;
    if (m_contact_done || to_contact_s <= m_settings.steer_until_s) return;
    const Eigen::Vector3d target = m_head_motion.predict(to_contact_s) - Eigen::Vector3d(0.0, m_strike_drop_m, 0.0);
    m_bodies[m_character]->adapter.retarget(target);
    m_plan.target_world = target;
}

void Fighter::play_strike(double t_s) {
    Body& body = *m_bodies[m_character];
    StrikeAdapter& adapter = body.adapter;
    // Frames of the database's rate, as a fractional index; the contact frame is played exactly.
    double index = (t_s - m_strike_start_s) / m_db.meta.frame_time_s;
    const double contact = adapter.contact_index();
    // The database's frame time is a float: a frame landing on the contact can come out a few 1e-7 short of it.
    if (!m_contact_done && index >= contact - 1e-4) index = contact;
    index = std::min(index, double(adapter.frame_count() - 1));
    // At the contact: a head still at the latched target takes the impact (the strike stops there); a dodged
    // strike follows through from this frame on.
    const bool at_contact = !m_contact_done && index >= contact;
    steer_strike((contact - index) * m_db.meta.frame_time_s);
    if (at_contact) {
        m_strike_impact = m_tracking && (aimed_point_now() - m_plan.target_world).norm() <= m_settings.hit_radius_m;
        adapter.set_impact(m_strike_impact);
    }
    const AdaptedFrame frame = adapter.step(index, m_pose);
    m_shown_by_adapter = true;
    m_strike_overshoot_m = std::max(m_strike_overshoot_m, frame.past_target_m);
    m_strike_violations += joint_violation_count(frame.joint_violations);
    if (at_contact) {
        m_contact_done = true;
        FighterEvent event = strike_event(FighterEvent::Type::strike, t_s);
        event.contact_error_m = (frame.effector - m_plan.target_world).norm();
        event.head_distance_m = m_tracking ? (frame.effector - aimed_point_now()).norm() : 1e9;
        event.hit = event.head_distance_m <= m_settings.hit_radius_m;
        event.prediction_error_m = m_tracking ? (aimed_point_now() - m_plan.target_world).norm() : 1e9;
        if (m_tracking) event.aimed_point_at_contact = aimed_point_now();
        event.range_m = m_strike_range_m;
        if (m_previous_effector_s >= 0.0 && t_s > m_previous_effector_s) {
            event.effector_speed_mps = (frame.effector - m_previous_effector).norm() / (t_s - m_previous_effector_s);
        }
        push_event(event);
    }
    m_previous_effector = frame.effector;
    m_previous_effector_s = t_s;
    body.encoder.encode(m_mir, m_pose.view());
    apply_defence(); // a block with the free arm (decodes the frame again with its edit, when one is on)
    if (index >= adapter.frame_count() - 1) {
        FighterEvent event = strike_event(FighterEvent::Type::strike_end, t_s);
        event.overshoot_m = m_strike_overshoot_m;
        event.joint_limit_violations = m_strike_violations;
        push_event(event);
        enter(FighterState::recover, t_s);
        finish_frame();
        start_clip(m_guard_clip, t_s, false);
        m_blend_start_s = t_s;
    }
}

void Fighter::finish_frame() {
    const Body& body = *m_bodies[m_character];
    m_heading = pose_heading(body.rig->skeleton(), body.rig->anatomy(), positions(), rotations());
}

void Fighter::step(double t_s, const Eigen::Vector3d* head, const UserHands* hands) {
    m_previous_step_s = m_now_s;
    m_now_s = t_s;
    m_hands = hands ? *hands : UserHands{};
    if (!m_started) {
        m_started = true;
        enter(FighterState::rest, t_s);
        start_clip(m_guard_clip, t_s, false);
        m_blend_start_s = -1e9;
    }
    // The tracker.
    if (head) {
        m_head = *head;
        m_last_head_s = t_s;
        m_head_motion.update(t_s, m_head);
        if (!m_tracking && m_have_head) {
            FighterEvent event;
            event.type = FighterEvent::Type::tracker_back;
            event.t_s = t_s;
            push_event(event);
            if (m_state == FighterState::hold) {
                enter(FighterState::rest, t_s);
                start_clip(m_guard_clip, t_s, true);
            }
        }
        m_have_head = m_tracking = true;
    } else if (m_tracking && t_s - m_last_head_s > m_settings.tracker_timeout_s) {
        m_tracking = false;
        m_head_motion.reset();
        m_defence.reset();
        m_block_lagging = false;
        FighterEvent event;
        event.type = FighterEvent::Type::tracker_lost;
        event.t_s = t_s;
        push_event(event);
        if (m_state == FighterState::rest || m_state == FighterState::approach) enter(FighterState::hold, t_s);
    }

    if (m_pending && !m_tracking) { // the order came while the tracker has no head: nothing to aim at
        m_pending = false;
        emit_ignored(t_s, "no head to aim at");
    }
    defend(t_s);
    serve_queue(t_s);
    if (m_pending && (m_state == FighterState::rest || m_state == FighterState::approach) && !m_defence.active() && m_may_plan) start_strike(t_s);

    switch (m_state) {
    case FighterState::strike:
        play_strike(t_s);
        if (m_state == FighterState::strike) finish_frame();
        return;
    case FighterState::hold:
        if (t_s - m_state_since_s >= m_settings.hold_s && m_clip != m_guard_clip) start_clip(m_guard_clip, t_s, false);
        if (t_s - m_state_since_s < m_settings.hold_s) { // hold the last pose
            m_bodies[m_character]->decoder.decode(m_pose, m_mir);
            m_shown_by_adapter = false;
            finish_frame();
            return;
        }
        break;
    case FighterState::recover:
        if (t_s - m_state_since_s >= m_settings.recover_s) enter(FighterState::rest, t_s);
        break;
    case FighterState::approach:
    case FighterState::rest: break;
    }

    const DbClip& clip = m_db.clips[m_clip];
    const bool clip_over = t_s - m_clip_start_s >= (clip.frame_count - 1) * double(m_db.meta.frame_time_s);
    // The band where strikes reach.
    const double leg = leg_length(), near_m = m_settings.near_legs * leg, far_m = band_far_m();
    // Resting out of range: step without waiting for the guard loop to end.
    const bool out_of_range = m_state == FighterState::rest && m_tracking && t_s - m_state_since_s >= m_settings.blend_s &&
                              (distance_to_user() > far_m || distance_to_user() < near_m);
    if (clip_over || out_of_range) {
        if (m_state == FighterState::approach) enter(FighterState::rest, t_s);
        // At each loop of the guard: step into the band, or keep guarding, facing the user.
        int next = m_guard_clip;
        double scale = 1.0;
        if (m_state == FighterState::rest && m_tracking) {
            // Land in the far part of the band: in reach, without crowding the user's face.
            const double distance = distance_to_user(), middle = near_m + m_settings.landing_in_band * (far_m - near_m);
            if (distance > far_m && m_step_clips[0] >= 0) next = m_step_clips[0];
            else if (distance < near_m && m_step_clips[1] >= 0) next = m_step_clips[1];
            if (next != m_guard_clip) {
                const double stride = clip_stride_m(next);
                if (stride > 1e-3) scale = std::clamp(std::abs(distance - middle) / stride, m_settings.min_step_scale, 1.0);
                enter(FighterState::approach, t_s);
            }
        }
        start_clip(next, t_s, m_tracking, scale);
    }
    play_clip(t_s);
    finish_frame();
}

} // namespace kumite
