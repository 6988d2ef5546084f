// The fighter's frame (fighter.h): the parts called in the order of a frame, and the state machine between them.

#include "kumite/runtime/fighter.h"

#include "fighter/fighter_parts.h"
#include "fighter/strike_aim.h"

#include "kumite/runtime/motion_meter.h"

namespace kumite {
namespace {

// The limb (LimbSample's order) a strike strikes with.
int striking_limb(const Strike& strike) { return limb_of_segment(static_cast<BodyPart>(std::max(0, strike.segment()))); }

constexpr double k_crowd_settle_s = 0.1; // a state's first frames blend from the clip before: no step back begun in them

// The user rushed in (FighterSettings::crowd_legs): nearer than `limit_m` while the fighter steps or recovers from a
// strike (`state`, entered `in_state_s` ago), not already stepping back.
bool crowded(FighterState state, double in_state_s, bool tracking, bool stepping_back, double limit_m, const Footwork::UserRange& range) {
    if (!tracking || stepping_back) return false;
    if (state != FighterState::approach && state != FighterState::recover) return false;
    return in_state_s >= k_crowd_settle_s && range.distance_m < limit_m;
}

} // namespace

Fighter::Fighter(const MotionDatabaseView& database, const Retriever& retriever, std::vector<CharacterRig*> characters, FighterSettings settings,
                 std::shared_ptr<const LibrarySpeeds> library_speeds)
    : m_settings(settings), m_parts(std::make_unique<Parts>(database, retriever, characters, settings, std::move(library_speeds))) {}

Fighter::~Fighter() = default;

void Fighter::step(double t_s, const Eigen::Vector3d* head, const UserHands* hands) {
    m_previous_step_s = m_now_s;
    m_now_s = t_s;
    m_parts->user.take_hands(hands);
    if (!m_started) begin(t_s);
    track(t_s, head);
    m_parts->user.update_guard(m_parts->body.heading().origin);
    defend(t_s);
    take_blow(t_s);
    serve_orders(t_s);
    plan(t_s);
    if (m_state == FighterState::strike) play_strike(t_s);
    else move(t_s);
    watch_responses(t_s);
}

void Fighter::watch_responses(double t_s) {
    Parts& p = *m_parts;
    ResponseWatch::Blow blow;
    blow.fighter = p.body.heading().origin;
    blow.striking = m_state == FighterState::strike && p.strike.segment() >= 0;
    if (blow.striking) {
        blow.point = p.strike.striking_point(p.body);
        blow.target = p.strike.plan().target_world;
    }
    p.responses.watch(t_s, blow, p.user, p.log);
}

void Fighter::begin(double t_s) {
    m_started = true;
    enter(FighterState::rest, t_s); // told by no event: a fighter starts at rest
    Parts& p = *m_parts;
    p.player.start(p.footwork.guard_clip(), t_s, p.body.mir(), p.body.heading(), p.body.leg_length());
    p.player.skip_blend();
}

void Fighter::track(double t_s, const Eigen::Vector3d* head) {
    Parts& p = *m_parts;
    switch (p.user.take_head(t_s, head, m_settings.tracker_timeout_s, p.log)) {
    case TrackedUser::Change::back:
        if (m_state == FighterState::hold) {
            enter(FighterState::rest, t_s);
            // Faces the heading it has: the guard's next loop turns to the user.
            p.player.start(p.footwork.guard_clip(), t_s, p.body.mir(), p.body.heading(), p.body.leg_length());
        }
        break;
    case TrackedUser::Change::lost:
        p.defence.reset();
        if (m_state == FighterState::rest || m_state == FighterState::approach) enter(FighterState::hold, t_s);
        break;
    case TrackedUser::Change::none: break;
    }
    if (p.orders.has_pending() && !p.user.tracking()) p.orders.refuse(t_s, "no head to aim at", p.log); // nothing to aim at
}

void Fighter::defend(double t_s) {
    Parts& p = *m_parts;
    const int striking_segment = m_state == FighterState::strike ? p.strike.segment() : -1;
    p.defence.defend(t_s, m_previous_step_s, p.user.hands(), p.user.tracking(), m_state, striking_segment, p.body, p.log);
}

void Fighter::take_blow(double t_s) {
    Parts& p = *m_parts;
    if (p.defence.landed() && m_settings.hit_reactions) {
        if (!m_blow_pending) m_blow_s = t_s;
        m_blows = m_blow_pending ? m_blows + 1 : 1;
        m_blow_pending = true;
        m_blow = p.defence.landed_strike();
    }
    // A strike under way ends first (strike_follow_s after its contact, its recoil shown): cut short before that, a
    // kick's leg would drop from the target at several times a person's speed.
    if (!m_blow_pending || m_state == FighterState::strike) return;
    m_blow_pending = false;
    const HeadingFrame heading = p.body.heading();
    const Eigen::Vector3d push_in_heading = heading.direction_to_heading(m_blow.hand_velocity);
    const HitReactions::Choice choice = p.reactions.choose(push_in_heading, m_blow.at_head);
    FighterEvent event = EventLog::at(FighterEvent::Type::hit_reaction, t_s);
    event.user_strike = m_blow;
    event.clip = choice.clip;
    event.reaction_fit = choice.fit;
    event.reaction_delay_s = t_s - m_blow_s;
    event.reaction_blows = m_blows;
    p.log.push(event);
    if (choice.clip < 0) return; // no captured reaction: the body goes on (the event says so)
    enter(FighterState::hit_reaction, t_s);
    // Blended in from the pose shown (a block's or slip's edits included: the move stops here, its arm goes on
    // from where it was).
    p.player.start(choice.clip, t_s, p.defence.shown() ? p.defence.shown_mir() : p.body.mir(), heading, p.body.leg_length());
    p.defence.cancel_move();
}

void Fighter::serve_orders(double t_s) {
    Parts& p = *m_parts;
    p.orders.serve(t_s, busy(), p.user.head(), p.log);
}

void Fighter::plan(double t_s) {
    Parts& p = *m_parts;
    const bool follow_up = m_state == FighterState::recover && p.orders.has_pending() && p.orders.pending().order.blow > 0;
    const bool free = m_state == FighterState::rest || m_state == FighterState::approach || follow_up;
    if (!p.orders.has_pending() || !free || p.defence.active() || !p.planner.may_plan()) return;
    switch (p.planner.plan(t_s, m_settings.aim, m_state == FighterState::approach, p.orders, p.body, p.user, p.footwork, p.strike)) {
    case StrikePlanner::Outcome::waiting: break;
    case StrikePlanner::Outcome::refused: p.orders.refuse(t_s, "no strike of that kind can start from here", p.log); break;
    case StrikePlanner::Outcome::begun:
        p.orders.performed(t_s, p.log);
        enter(FighterState::strike, t_s); // the planner began the adaptation
        break;
    }
}

namespace {

// The guard or a step Footwork chose, facing the user; a step with the guard's arms up.
void start_clip(MotionPlayer& player, CharacterBody& body, const TrackedUser& user, const Footwork::Next& next, double t_s) {
    player.start(next.clip, t_s, body.mir(), user.facing(body.heading()), body.leg_length(), next.step_scale, next.is_step);
}

} // namespace

void Fighter::play_strike(double t_s) {
    Parts& p = *m_parts;
    p.strike.play(t_s, p.body, p.user);
    keep_fists_off_gloves();
    p.defence.apply(t_s, std::max(0, p.strike.segment()), p.player.pins(), p.body); // a block or the guard kept with the free arm
    show(t_s);
    if (m_settings.human_speed || m_settings.human_speed_but_strikes || m_settings.human_extremities) {
        // A striking limb held back: the strike waits for it (its clock goes back by the share not shown), or, at
        // the library's speed for its kind, it runs at that speed and the strike waits only for a fist or foot more
        // than strike_lag_share of the hit radius behind the pose asked for (it lands at the limb's own speed).
        const int limb = striking_limb(p.strike);
        const bool runs_at_its_bar = !m_settings.human_speed && m_settings.human_speed_but_strikes && m_settings.human_speed_strikes;
        if (!runs_at_its_bar || p.speed_limit.lag_m(limb) > m_settings.strike_lag_share * m_settings.hit_radius_m) {
            p.strike.held_back(p.speed_limit.shown_share(limb));
        }
    }
    p.strike.measure(t_s, p.body, p.user, p.log); // the contact as shown
    // Over at the clip's end, or once its contact and recoil are shown (strike_follow_s): the recovery takes it from there.
    const double contact_s = p.strike.contact_shown_s();
    const bool followed_through = m_settings.strike_follow_s > 0.0 && contact_s >= 0.0 && t_s - contact_s >= m_settings.strike_follow_s;
    if (!p.strike.over() && !followed_through) return;
    p.strike.end(t_s, p.log);
    enter(FighterState::recover, t_s);
    // A combination's next blow begins from here, the recoil (planned next frame), not from the guard.
    const bool follow_up = p.orders.take_follow_up(t_s, p.user.head());
    if (!follow_up && m_settings.step_out_after_strikes && p.user.tracking() && !p.orders.has_pending() && !p.orders.has_queued()) {
        // Out after: a strike that leaves the fighter inside the fighting distance recovers stepping back out.
        const Footwork::UserRange range = Footwork::range_of(p.body, p.user);
        const Footwork::Band band = p.footwork.rest_band(p.body, p.user);
        const Footwork::Next next = p.footwork.next_clip(true, range, band, p.body.leg_length());
        if (next.is_step && range.distance_m < band.near_m) {
            start_clip(p.player, p.body, p.user, next, t_s);
            return;
        }
    }
    p.player.start(p.footwork.guard_clip(), t_s, p.body.mir(), p.body.heading(), p.body.leg_length());
}

void Fighter::move(double t_s) {
    Parts& p = *m_parts;
    if (m_state == FighterState::hold) {
        if (t_s - m_state_since_s >= m_settings.hold_s && p.player.clip() != p.footwork.guard_clip()) {
            p.player.start(p.footwork.guard_clip(), t_s, p.body.mir(), p.body.heading(), p.body.leg_length());
        }
        if (t_s - m_state_since_s < m_settings.hold_s) { // hold the last pose
            p.body.decode(p.body.mir());
            show(t_s);
            return;
        }
    } else if (m_state == FighterState::recover && t_s - m_state_since_s >= m_settings.recover_s) {
        // Recovered: resting, or still stepping out (a step begun with the recovery).
        const bool stepping = p.player.clip() != p.footwork.guard_clip() && !p.player.over(t_s);
        enter(stepping ? FighterState::approach : FighterState::rest, t_s);
    } else if (m_state == FighterState::hit_reaction && p.player.over(t_s)) { // back to the guard
        enter(FighterState::recover, t_s);
        p.player.start(p.footwork.guard_clip(), t_s, p.body.mir(), p.user.facing(p.body.heading()), p.body.leg_length());
    }
    // The band where strikes reach while an order waits (closer still when no strike reached from in it: an elbow,
    // a knee), else the fighting distance; resting out of it, the fighter steps without waiting for the guard loop.
    const double leg = p.body.leg_length();
    const Footwork::UserRange range = Footwork::range_of(p.body, p.user);
    const Footwork::Band band = p.orders.has_pending() ? p.footwork.strike_band(p.body, p.user, p.orders.pending().tried ? range.distance_m : -1.0)
                                                       : p.footwork.rest_band(p.body, p.user);
    const bool out_of_range = m_state == FighterState::rest && p.user.tracking() && t_s - m_state_since_s >= m_settings.blend_s &&
                              p.footwork.out_of_band(range, band);
    // Rushed: a step back now, from whatever plays (a step in, the recovery's guard), out to the fighting distance;
    // with an order waiting, only from inside the band its strike starts from (an elbow's, a knee's, closer in).
    double crowd_m = m_settings.crowd_legs * leg;
    if (p.orders.has_pending()) crowd_m = std::min(crowd_m, band.near_m);
    else if (p.orders.has_queued()) crowd_m = std::min(crowd_m, p.footwork.near_m(p.body, p.user));
    const Footwork::Next evade = crowded(m_state, t_s - m_state_since_s, p.user.tracking(), p.player.clip() == p.footwork.step_back_clip(), crowd_m, range)
                                     ? p.footwork.next_clip(true, range, p.footwork.rest_band(p.body, p.user), leg)
                                     : Footwork::Next{};
    if (evade.is_step && evade.clip == p.footwork.step_back_clip()) {
        start_clip(p.player, p.body, p.user, evade, t_s);
    } else if (p.player.over(t_s) || out_of_range) {
        if (m_state == FighterState::approach) enter(FighterState::rest, t_s);
        // At each loop of the guard: step into the band, or keep guarding, facing the user.
        const Footwork::Next next = p.footwork.next_clip(m_state == FighterState::rest && p.user.tracking(), range, band, leg);
        if (next.is_step) enter(FighterState::approach, t_s);
        start_clip(p.player, p.body, p.user, next, t_s);
    }
    // A blow is answered over its own blend (the reaction's); everything else over the fighter's.
    p.player.play(t_s, p.body, m_state == FighterState::hit_reaction ? m_settings.reaction_blend_s : m_settings.blend_s);
    keep_fists_off_gloves();
    p.defence.apply(t_s, -1, p.player.pins(), p.body);
    show(t_s);
}

void Fighter::keep_fists_off_gloves() {
    Parts& p = *m_parts;
    // Only with every arm held to human speed (the default): a fist pushed out of a glove that came on is then shown
    // no faster than its bar, not at the glove's speed.
    if (!p.user.tracking() || !m_settings.user_guard.enabled || !(m_settings.human_speed || m_settings.human_speed_but_strikes)) return;
    p.defence.keep_fists_off_gloves(p.user.guard(), m_settings.user_guard.striking_radius_m, m_settings.user_guard.knuckles_past_wrist_m);
}

void Fighter::show(double t_s) {
    Parts& p = *m_parts;
    const MoveKind kind = MotionMeter::move_kind(*this, p.db);
    const bool in_part = m_settings.human_speed_but_strikes || m_settings.human_speed_blocks || m_settings.human_extremities;
    if (m_settings.human_speed) p.speed_limit.apply(t_s, kind, p.body, SpeedLimit::k_all_limbs, false, &p.defence);
    else if (in_part) { // noted every frame
        // Every limb but a strike's own held to the library's speeds for the kind of move; else the blocking arm, and
        // an arm still behind the pose asked for after its block (a blow landed, the move cancelled): it catches up
        // at the speeds of what comes next instead of in one frame. Every other wrist and ankle no faster than a
        // person's.
        unsigned limbs = 0u;
        if (m_settings.human_speed_but_strikes) {
            limbs = SpeedLimit::k_all_limbs;
            if (is_strike_kind(kind) && !m_settings.human_speed_strikes) limbs &= ~(1u << striking_limb(p.strike));
        } else if (m_settings.human_speed_blocks) {
            if (kind == MoveKind::block) limbs |= 1u << p.defence.defence().block_arm();
            for (int arm = 0; arm < 2; ++arm) if (p.speed_limit.held_to_library(arm)) limbs |= 1u << arm;
        }
        p.speed_limit.apply(t_s, kind, p.body, limbs, m_settings.human_extremities, &p.defence);
    }
    if ((m_settings.human_speed || in_part) && p.speed_limit.held()) p.defence.shown_held(p.body);
    p.defence.note_shown_arm(t_s, p.body);
    p.body.update_heading();
}

void Fighter::enter(FighterState state, double t_s) {
    if (state == m_state && m_started) return;
    m_state = state;
    m_state_since_s = t_s;
    FighterEvent event = EventLog::at(FighterEvent::Type::state, t_s);
    event.state = state;
    m_parts->log.push(event);
}

bool Fighter::order(const StrikeOrder& order) {
    Parts& p = *m_parts;
    return p.orders.offer(order, m_now_s, busy(), p.defence.active(), p.user.head(), p.log);
}

void Fighter::set_character(int index) {
    Parts& p = *m_parts;
    if (!p.body.select(index)) return;
    p.defence.reset();
    FighterEvent event = EventLog::at(FighterEvent::Type::character, m_now_s);
    event.character = index;
    p.log.push(event);
    if (m_state == FighterState::strike) p.strike.carry_over(p.body); // the strike carries on, on the new skeleton
}

bool Fighter::busy() const {
    return m_state == FighterState::strike || m_state == FighterState::recover || m_state == FighterState::hit_reaction || m_parts->orders.has_pending() ||
           m_parts->defence.active();
}

// What the fighter tells its callers, read from its parts.

void Fighter::set_defence(bool enabled) { m_parts->defence.defence().settings().enabled = enabled; }
void Fighter::set_reaction(double reaction_delay_s, double defend_share) {
    DefenceSettings& settings = m_parts->defence.defence().settings();
    settings.reaction_delay_s = reaction_delay_s;
    settings.defend_share = defend_share;
}
bool Fighter::defence_enabled() const { return m_parts->defence.defence().enabled(); }
const Defence& Fighter::defence() const { return m_parts->defence.defence(); }
const UserGuard& Fighter::user_guard() const { return m_parts->user.guard(); }
bool Fighter::has_waiting_order() const { return m_parts->orders.has_pending() || m_parts->orders.has_queued() || m_parts->orders.has_follow_up(); }

bool Fighter::wants_to_plan() const {
    // As step() decides, from the state before it: a queued order becomes pending in the step when the fighter is
    // free, so it wants to plan too.
    const bool free_to_strike = (m_state == FighterState::rest || m_state == FighterState::approach) && !m_parts->defence.active();
    return free_to_strike && m_parts->user.tracking() && has_waiting_order();
}

bool Fighter::plan_is_retry() const {
    const OrderQueue& orders = m_parts->orders;
    return orders.has_pending() && (orders.pending().tried || orders.pending().part > 0);
}

double Fighter::order_since_s() const { return m_parts->orders.has_pending() ? m_parts->orders.pending().since_s : m_parts->orders.queued_since_s(); }
void Fighter::set_may_plan(bool may_plan, int parts) { m_parts->planner.set_budget(may_plan, parts); }
bool Fighter::may_plan() const { return m_parts->planner.may_plan(); }
int Fighter::character() const { return m_parts->body.index(); }
const std::array<long long, k_move_kind_count>& Fighter::held_back_frames() const { return m_parts->speed_limit.held_frames(); }
double Fighter::held_back_lag_m() const { return m_parts->speed_limit.largest_lag_m(); }
const Pose& Fighter::pose() const { return m_parts->body.pose(); }
const MirFrame& Fighter::mir() const { return m_parts->defence.shown() ? m_parts->defence.shown_mir() : m_parts->body.mir(); }
std::span<const Eigen::Vector3d> Fighter::positions() const { return m_parts->body.positions(); }
std::span<const Eigen::Quaterniond> Fighter::rotations() const { return m_parts->body.rotations(); }
Eigen::Vector3d Fighter::part_position(BodyPart part) const { return m_parts->body.part_position(part); }
HeadingFrame Fighter::heading() const { return m_parts->body.heading(); }
const StrikePlan& Fighter::strike_plan() const { return m_parts->strike.plan(); }
double Fighter::leg_length() const { return m_parts->body.leg_length(); }
double Fighter::strike_reach_m() const { return kumite::strike_reach_m(m_parts->body, m_parts->user.head(), m_settings.reach_fallback); }
std::span<const FighterEvent> Fighter::events() const { return m_parts->log.events(); }
void Fighter::clear_events() { m_parts->log.clear(); }

} // namespace kumite
