#include "fighter/speed_limit.h"

#include <algorithm>

namespace kumite {
namespace {

constexpr Limb k_sample_limbs[4] = {Limb::arm_l, Limb::arm_r, Limb::leg_l, Limb::leg_r}; // LimbSample's order
constexpr int k_bound_halvings = 6;  // a limb held back further to keep it in bounds: its share found to 1/64 of the way

// The search for the share of a step that brings a measure to its bar: the largest share known under the bar (0: the
// last pose, taken as no speed at all), the smallest known over it (1: the asked pose), and the ratios measured
// there; the next share to try is where the line between them reaches just under the bar (the ratio is near linear
// in the share over one frame, though not through 0 where the trunk carries the limb: aimed at the bar itself,
// the estimates crept up to it from above and never got under), else halfway. Done once the ratio is within
// [0.98, 1] of the bar or the bracket is closed.
struct ShareSearch {
    static constexpr double k_aim = 0.99;
    double under = 0.0, above = 1.0, share = 1.0;
    double ratio_under = 0.0, ratio_above = 1.0;
    explicit ShareSearch(double asked_ratio) : share(k_aim / asked_ratio), ratio_above(asked_ratio) {}
    // The ratio measured at `share`; true when done (`under` is the answer).
    bool measured(double ratio) {
        if (ratio <= 1.0) under = share, ratio_under = ratio;
        else above = share, ratio_above = ratio;
        if ((ratio <= 1.0 && ratio >= 0.98) || above - under <= 1e-3) return true;
        const double slope = (ratio_above - ratio_under) / (above - under);
        const double estimate = slope > 1e-9 ? under + (k_aim - ratio_under) / slope : 0.5 * (under + above);
        share = estimate > under && estimate < above ? estimate : 0.5 * (under + above);
        return false;
    }
};

// `out` part of the way from `from` to `to` (share in [0, 1]); the three poses are of one skeleton.
void blend_pose(Pose& out, const Pose& from, const Pose& to, double share) {
    out.root_translation = from.root_translation + share * (to.root_translation - from.root_translation);
    for (std::size_t j = 0; j < to.local_rotations.size(); ++j) out.local_rotations[j] = from.local_rotations[j].slerp(share, to.local_rotations[j]);
    for (std::size_t j = 0; j < to.local_translations.size() && j < from.local_translations.size(); ++j) {
        out.local_translations[j] = from.local_translations[j] + share * (to.local_translations[j] - from.local_translations[j]);
    }
}

// `out` as `to`, except each limb's joints part of the way from `from` by that limb's share.
void blend_limbs(Pose& out, const Pose& from, const Pose& to, const std::vector<int>& limb_of_joint, const std::array<double, 4>& share) {
    out.root_translation = to.root_translation;
    for (std::size_t j = 0; j < to.local_rotations.size(); ++j) {
        const int limb = j < limb_of_joint.size() ? limb_of_joint[j] : -1;
        out.local_rotations[j] = limb < 0 ? to.local_rotations[j] : from.local_rotations[j].slerp(share[std::size_t(limb)], to.local_rotations[j]);
    }
    for (std::size_t j = 0; j < to.local_translations.size(); ++j) out.local_translations[j] = to.local_translations[j];
}

} // namespace

SpeedLimit::SpeedLimit(std::shared_ptr<const LibrarySpeeds> library) : m_library(std::move(library)) {}

void SpeedLimit::reserve(int joints) {
    for (Pose* pose : {&m_last, &m_asked}) {
        pose->local_rotations.reserve(std::size_t(joints));
        pose->local_translations.reserve(std::size_t(joints));
    }
}

void SpeedLimit::map_limbs(const std::vector<CharacterRig*>& characters) {
    m_limb_of_joint.clear();
    for (const CharacterRig* character : characters) {
        const Skeleton& skeleton = character->skeleton();
        std::vector<int> limb_of(std::size_t(skeleton.joint_count()), -1);
        for (int k = 0; k < 4; ++k) limb_of[std::size_t(character->anatomy().limbs[int(k_sample_limbs[k])].root)] = k;
        for (int j = 1; j < skeleton.joint_count(); ++j) { // parents come first: a limb's joints and all below them
            if (limb_of[std::size_t(j)] < 0) limb_of[std::size_t(j)] = limb_of[std::size_t(skeleton.parents[std::size_t(j)])];
        }
        m_limb_of_joint.push_back(std::move(limb_of));
    }
}

std::array<double, 4> SpeedLimit::limb_ratios(const LimbSample& sample, const LimbBars& bars, double dt_s) const {
    auto ratio = [](double value, double limit) { return limit > 0.0 ? value / limit : 0.0; };
    std::array<double, 4> ratios{};
    for (std::size_t k = 0; k < 4; ++k) {
        const bool arm = k < 2;
        const JointSpeeds& bar = bars[k];
        const double travel = (sample.extremity[k] - m_last_sample.extremity[k]).norm() / dt_s;
        const double bend = std::abs(sample.flexion_rad[k] - m_last_sample.flexion_rad[k]) / dt_s;
        ratios[k] = std::max(ratio(travel, arm ? bar.wrist_mps : bar.ankle_mps), ratio(bend, arm ? bar.elbow_radps : bar.knee_radps));
    }
    return ratios;
}

bool SpeedLimit::hold_limbs(const LimbBars& bars, const LimbBars& whole_pose_bars, double dt_s, const std::array<double, 4>& asked_ratios,
                            CharacterBody& body) {
    if (std::size_t(body.index()) >= m_limb_of_joint.size()) return false;
    const std::vector<int>& limb_of_joint = m_limb_of_joint[std::size_t(body.index())];
    const RestAnatomy& anatomy = body.anatomy();
    // A search per limb over its bar (its joints as last shown assumed under it until measured); the limbs under
    // their bar stay as asked (share 1).
    std::array<ShareSearch, 4> searches{ShareSearch(1.0), ShareSearch(1.0), ShareSearch(1.0), ShareSearch(1.0)};
    std::array<double, 4> share{}, under{};
    std::array<bool, 4> done{};
    for (std::size_t k = 0; k < 4; ++k) {
        done[k] = asked_ratios[k] <= 1.0;
        if (!done[k]) searches[k] = ShareSearch(asked_ratios[k]);
        share[k] = searches[k].share;
        under[k] = done[k] ? 1.0 : 0.0;
    }
    for (int refine = 0; refine < 10 && !(done[0] && done[1] && done[2] && done[3]); ++refine) {
        blend_limbs(body.pose(), m_last, m_asked, limb_of_joint, share);
        body.show_edited_pose();
        const std::array<double, 4> ratios = limb_ratios(LimbSample::of(anatomy, body.positions()), bars, dt_s);
        for (std::size_t k = 0; k < 4; ++k) {
            if (asked_ratios[k] <= 1.0) continue;
            done[k] = searches[k].measured(ratios[k]);
            under[k] = searches[k].under;
            share[k] = done[k] ? under[k] : searches[k].share;
        }
    }
    blend_limbs(body.pose(), m_last, m_asked, limb_of_joint, under);
    body.show_edited_pose();
    // A limb the trunk alone carries too fast (a turn, a lunge) is over its bar with its own joints held: the whole
    // pose is held instead, to the bars that hold whatever carries the limb.
    const std::array<double, 4> ratios = limb_ratios(LimbSample::of(anatomy, body.positions()), whole_pose_bars, dt_s);
    m_shown_share = under;
    return *std::max_element(ratios.begin(), ratios.end()) <= 1.0;
}

void SpeedLimit::keep_in_bounds(const HeldPoseBounds& bounds, CharacterBody& body) {
    const std::vector<int>& limb_of_joint = m_limb_of_joint[std::size_t(body.index())];
    std::array<double, 4> share = m_shown_share;
    auto show = [&](int limb, double limb_share) {
        share[std::size_t(limb)] = limb_share;
        blend_limbs(body.pose(), m_last, m_asked, limb_of_joint, share);
        body.show_edited_pose();
        return bounds.blocked(body, limb);
    };
    for (int limb = 0; limb < 4; ++limb) {
        const double held = m_shown_share[std::size_t(limb)];
        if (held >= 1.0 || !bounds.blocked(body, limb)) continue;
        // Clear where it was last shown (else what it is in came onto it: nothing to hold back from), then the
        // largest share that is, by halving.
        if (show(limb, 0.0)) {
            show(limb, held);
            continue;
        }
        double clear = 0.0, in = held;
        for (int halving = 0; halving < k_bound_halvings; ++halving) {
            const double middle = 0.5 * (clear + in);
            (show(limb, middle) ? in : clear) = middle;
        }
        show(limb, clear);
        m_shown_share[std::size_t(limb)] = clear;
    }
}

void SpeedLimit::release_limbs(const LimbBars& whole_pose_bars, double dt_s, CharacterBody& body) {
    const std::vector<int>& limb_of_joint = m_limb_of_joint[std::size_t(body.index())];
    const RestAnatomy& anatomy = body.anatomy();
    // Each held limb eased from its share towards the asked pose by one common part `eased` (1: as asked, under the
    // bars, known): the least that brings every limb under them, by halving.
    const std::array<double, 4> held = m_shown_share;
    auto ease = [&](double eased) {
        std::array<double, 4> share{};
        for (std::size_t k = 0; k < 4; ++k) share[k] = held[k] + eased * (1.0 - held[k]);
        blend_limbs(body.pose(), m_last, m_asked, limb_of_joint, share);
        body.show_edited_pose();
        m_shown_share = share;
    };
    double under = 1.0, over = 0.0;
    for (int refine = 0; refine < 10; ++refine) {
        const double eased = 0.5 * (under + over);
        ease(eased);
        const std::array<double, 4> ratios = limb_ratios(LimbSample::of(anatomy, body.positions()), whole_pose_bars, dt_s);
        (*std::max_element(ratios.begin(), ratios.end()) <= 1.0 ? under : over) = eased;
    }
    ease(under);
}

void SpeedLimit::hold_pose(const LimbBars& bars, double dt_s, double over, CharacterBody& body) {
    const RestAnatomy& anatomy = body.anatomy();
    // Part of the way: the share that brings the fastest joint to its bar; the one found under the bar is shown.
    ShareSearch search(over);
    for (int refine = 0; refine < 10; ++refine) {
        blend_pose(body.pose(), m_last, m_asked, search.share);
        body.show_edited_pose();
        const std::array<double, 4> ratios = limb_ratios(LimbSample::of(anatomy, body.positions()), bars, dt_s);
        if (search.measured(*std::max_element(ratios.begin(), ratios.end()))) break;
    }
    if (search.share != search.under) { // the last one tried was over the bar
        blend_pose(body.pose(), m_last, m_asked, search.under);
        body.show_edited_pose();
    }
    m_shown_share = {search.under, search.under, search.under, search.under};
}

void SpeedLimit::apply(double t_s, MoveKind kind, CharacterBody& body, unsigned limbs, bool extremities, const HeldPoseBounds* bounds) {
    const RestAnatomy& anatomy = body.anatomy();
    const double dt_s = t_s - m_last_s;
    m_shown_share = {1.0, 1.0, 1.0, 1.0};
    m_lag_m = {};
    m_library_held = 0u;
    const bool comparable = m_has_last && m_character == body.index() && dt_s > 0.0 && m_library &&
                            body.index() < int(m_library->per_character.size());
    if (comparable) {
        // Each limb's bar: the library's for its kind (`limbs`), a person's wrist or ankle (`extremities`), or none.
        // The whole pose, when a limb's own joints are not enough, is held to the library's only with every limb
        // under it (a slip's trunk is not slowed for the blocking arm it carries).
        const JointSpeeds library = speed_bar(m_library->per_character[std::size_t(body.index())], kind);
        JointSpeeds person;
        if (extremities) person.wrist_mps = person.ankle_mps = k_human_extremity_mps;
        LimbBars bars, whole_pose_bars;
        for (std::size_t k = 0; k < 4; ++k) {
            const bool held_to_library = limbs & (1u << k);
            bars[k] = held_to_library ? library : person;
            whole_pose_bars[k] = held_to_library && limbs == k_all_limbs ? library : person;
        }
        const LimbSample asked = LimbSample::of(anatomy, body.positions());
        const std::array<double, 4> ratios = limb_ratios(asked, bars, dt_s);
        const double over = *std::max_element(ratios.begin(), ratios.end());
        if (over > 1.0) {
            // The limbs over their bar held back on their own (a punch's leg that lunges too fast does not slow its
            // fist); when the trunk itself carries one too fast, the whole pose.
            m_asked = body.pose();
            const bool limbs_held = hold_limbs(bars, whole_pose_bars, dt_s, ratios, body);
            if (limbs_held && bounds != nullptr) keep_in_bounds(*bounds, body);
            if (!limbs_held) {
                const std::array<double, 4> whole_ratios = limb_ratios(asked, whole_pose_bars, dt_s);
                const double whole_over = *std::max_element(whole_ratios.begin(), whole_ratios.end());
                if (whole_over > 1.0) {
                    body.pose() = m_asked;
                    hold_pose(whole_pose_bars, dt_s, whole_over, body);
                } else {
                    // The asked pose is under them: a limb held on a turning trunk swung wider than asked (an arm
                    // kept straight where the clip folds it in). It is held only as far as keeps it under them.
                    release_limbs(whole_pose_bars, dt_s, body);
                }
            }
            for (std::size_t k = 0; k < 4; ++k) {
                if (m_shown_share[k] < 1.0 && (limbs & (1u << k))) m_library_held |= 1u << k;
            }
            // What comes next (a blend, a strike) starts from the pose shown, not from the one asked for.
            body.encode(body.mir());
            ++m_held_frames[int(kind)];
            const LimbSample shown = LimbSample::of(anatomy, body.positions());
            for (int k = 0; k < 4; ++k) {
                m_lag_m[std::size_t(k)] = (shown.extremity[k] - asked.extremity[k]).norm();
                m_largest_lag_m = std::max(m_largest_lag_m, m_lag_m[std::size_t(k)]);
            }
        }
    }
    m_has_last = true;
    m_character = body.index();
    m_last_s = t_s;
    m_last = body.pose();
    m_last_sample = LimbSample::of(anatomy, body.positions());
}

} // namespace kumite
