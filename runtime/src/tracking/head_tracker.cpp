#include "kumite/runtime/head_tracker.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

namespace kumite {

Result<std::unique_ptr<HeadTracker>> HeadTracker::open(std::string_view spec_view, DtrackConfig config, std::uint64_t seed) {
    const std::string spec(spec_view);
    std::unique_ptr<HeadTracker> tracker(new HeadTracker());
    if (spec.starts_with("simulate:")) {
        const std::string name = spec.substr(9);
        double walk_speed = 0.8, delay = 0.25;
        char extra = 0;
        const std::size_t colon = name.find(':');
        const std::optional<SimulatedKind> answering = colon != std::string::npos ? simulated_kind_from_name(name.substr(0, colon)) : std::nullopt;
        if (name.starts_with("walk:")) {
            if (std::sscanf(name.c_str() + 5, "%lf%c", &walk_speed, &extra) != 1 || !(walk_speed > 0.0) || walk_speed > 3.0) {
                return make_error(ErrorCode::invalid, "--tracker simulate:walk:SPEED takes metres per second, more than 0 and at most 3, not '" + name + "'");
            }
            tracker->m_simulated.emplace(SimulatedKind::walk, seed, walk_speed);
        } else if (answering && SimulatedUser::answers(*answering)) {
            if (std::sscanf(name.c_str() + colon + 1, "%lf%c", &delay, &extra) != 1 || !(delay > 0.0) || delay > 2.0) {
                return make_error(ErrorCode::invalid, "--tracker simulate:" + name.substr(0, colon) + ":DELAY takes seconds, more than 0 and at most 2, not '" + name + "'");
            }
            tracker->m_simulated.emplace(*answering, seed, delay);
        } else if (const std::optional<SimulatedKind> kind = simulated_kind_from_name(name)) {
            tracker->m_simulated.emplace(*kind, seed);
        } else if (std::filesystem::is_regular_file(name)) {
            Result<ScriptedUser> read = ScriptedUser::read(name);
            if (!read) return read.error();
            tracker->m_scripted = std::move(*read);
        } else {
            return make_error(ErrorCode::invalid, "--tracker simulate: takes still, wander, walk[:SPEED], dodge, dodge-seen, punch, counter, slip[:DELAY], cover[:DELAY], step-back[:DELAY], high-guard or a user script file, not '" + name + "'");
        }
    } else if (spec.starts_with("dtrack:")) {
        int port = 0, body = config.head_body, left = -1, right = -1;
        char extra = 0;
        const char* rest = spec.c_str() + 7;
        const int fields = std::sscanf(rest, "%d:%d,%d,%d%c", &port, &body, &left, &right, &extra);
        const bool plain = fields >= 1 && fields <= 2 && std::strchr(rest, ',') == nullptr;
        const bool with_hands = fields == 4;
        if ((!plain && !with_hands) || port <= 0 || port > 65535 || (with_hands && (body < 0 || left < 0 || right < 0))) {
            return make_error(ErrorCode::invalid, "--tracker dtrack:PORT[:HEAD[,LEFT,RIGHT]] (ids of 6d bodies or 3d markers), not '" + spec + "'");
        }
        config.port = port;
        if (fields >= 2) config.head_body = body;
        if (with_hands) config.hand_ids = {left, right};
        Result<std::unique_ptr<DtrackReceiver>> opened = DtrackReceiver::open(config);
        if (!opened) return opened.error();
        tracker->m_receiver = std::move(*opened);
    } else if (spec.starts_with("replay:")) {
        Result<ReplayTrack> read = ReplayTrack::read(spec.substr(7));
        if (!read) return read.error();
        tracker->m_replay = std::move(*read);
    } else if (spec.starts_with("capture:")) {
        Result<CaptureUser> read = CaptureUser::open(std::string_view(spec).substr(8));
        if (!read) return read.error();
        tracker->m_capture = std::move(*read);
    } else {
        return make_error(ErrorCode::invalid, "--tracker must be dtrack:PORT[:HEAD[,LEFT,RIGHT]], replay:FILE, capture:FILE.bvh[:DISTANCE[:START_S]] or simulate:still|wander|walk[:SPEED]|dodge|dodge-seen|punch|counter|slip|cover|step-back[:DELAY]|high-guard|FILE, not '" + spec + "'");
    }
    return tracker;
}

void HeadTracker::set_opponent_limbs(const std::array<Eigen::Vector3d, 4>& limbs) {
    if (m_simulated) m_simulated->set_opponent_limbs(limbs);
}

void HeadTracker::set_opponent(const Eigen::Vector3d& head, const Eigen::Vector3d& chest, bool guarding) {
    if (m_simulated) m_simulated->set_opponent(head, chest, guarding);
    if (m_scripted) m_scripted->set_opponent(head, chest);
}

std::unique_ptr<HeadTracker> HeadTracker::fed() {
    std::unique_ptr<HeadTracker> tracker(new HeadTracker());
    tracker->m_fed = true;
    return tracker;
}

void HeadTracker::feed(const Eigen::Vector3d* head, const UserHands& hands) {
    m_fed_head_present = head != nullptr;
    if (head) m_fed_head = *head;
    m_fed_hands = hands;
}

const Eigen::Vector3d* HeadTracker::head(double t_s) {
    m_hands = UserHands{};
    if (m_fed) {
        if (!m_fed_head_present) return nullptr;
        m_head = m_fed_head;
        m_hands = m_fed_hands;
        return &m_head;
    }
    if (m_simulated) {
        m_head = m_simulated->head(t_s);
        m_hands = m_simulated->hands(t_s);
        return &m_head;
    }
    if (m_scripted) {
        m_head = m_scripted->head(t_s);
        m_hands = m_scripted->hands(t_s);
        return &m_head;
    }
    if (m_capture) {
        m_head = m_capture->head(t_s, m_hands);
        return &m_head;
    }
    if (m_replay) {
        const std::optional<Eigen::Vector3d> replayed = m_replay->head(t_s, &m_hands);
        if (!replayed) return nullptr;
        m_head = *replayed;
        return &m_head;
    }
    if (m_receiver && m_receiver->poll(m_sample, t_s)) {
        m_head = m_sample.position_world;
        m_hands = m_sample.hands;
        return &m_head;
    }
    return nullptr;
}

void HeadTracker::on_order(double t_s) {
    if (m_simulated) m_simulated->on_order(t_s);
    if (m_scripted) m_scripted->on_order(t_s);
}

} // namespace kumite
