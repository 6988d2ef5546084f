// Reading a bout's event lines into a SessionLog (session_log.h): every field is checked before it is used, so a
// hostile or truncated file gives what could be read and where reading stopped, never an exception.

#include "session_log.h"

#include "event_fields.h"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace kumite::report {

namespace {

// Coordinates past this are not a room's: a corrupt line.
constexpr double k_room_limit_m = 1e4;
constexpr double k_time_limit_s = 1e7;

std::optional<RoomPoint> point(const nlohmann::json& line, const char* key, double t_s) {
    const auto found = line.find(key);
    if (found == line.end() || !found->is_array() || found->size() != 3) return std::nullopt;
    RoomPoint p{t_s};
    double* out[3] = {&p.x, &p.y, &p.z};
    for (int i = 0; i < 3; ++i) {
        const nlohmann::json& value = (*found)[std::size_t(i)];
        if (!value.is_number()) return std::nullopt;
        *out[i] = value.get<double>();
        if (!std::isfinite(*out[i]) || std::abs(*out[i]) > k_room_limit_m) return std::nullopt;
    }
    return p;
}

} // namespace

std::optional<double> number(const nlohmann::json& line, const char* key) {
    const auto found = line.find(key);
    if (found == line.end() || !found->is_number()) return std::nullopt;
    const double value = found->get<double>();
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

double number_or(const nlohmann::json& line, const char* key, double fallback) { return number(line, key).value_or(fallback); }

std::string text(const nlohmann::json& line, const char* key) {
    const auto found = line.find(key);
    return found != line.end() && found->is_string() ? found->get<std::string>() : std::string();
}

bool flag(const nlohmann::json& line, const char* key, bool fallback) {
    const auto found = line.find(key);
    return found != line.end() && found->is_boolean() ? found->get<bool>() : fallback;
}

bool SessionLog::stop(std::string why) {
    if (!stopped) stopped = std::move(why);
    return false;
}

bool SessionLog::add_text(std::string_view text_line, long long line_number) {
    if (stopped) return false;
    if (text_line.find_first_not_of(" \t\r") == std::string_view::npos) return true; // blank lines are nothing
    nlohmann::json line = nlohmann::json::parse(text_line, nullptr, false);
    if (line.is_discarded()) {
        return stop("line " + std::to_string(line_number) + ": not a JSON object" +
                    (text_line.back() != '}' ? " (cut off: the file ends inside this line?)" : ""));
    }
    if (!add(line)) {
        stopped = "line " + std::to_string(line_number) + ": " + *stopped;
        return false;
    }
    return true;
}

bool SessionLog::add(const nlohmann::json& line) {
    if (stopped) return false;
    if (!line.is_object()) return stop("not a JSON object");
    const std::optional<double> t = number(line, "t");
    const std::string type = text(line, "type");
    if (!t || *t < 0.0 || *t > k_time_limit_s) return stop("no time \"t\" in seconds");
    if (type.empty()) return stop("no \"type\"");
    // Not necessarily in time order: an order's end is stamped with the order's time, and fighters' events interleave.
    last_t_s = std::max(last_t_s, *t);
    ++lines;

    if (type == "bout_start") return start = line, true;
    if (type == "bout_end") return end = line, true;
    if (type == "tracker_source") return tracker_source = line, true;
    if (type == "track") {
        if (std::optional<RoomPoint> head = point(line, "head", *t)) head_path.push_back(*head);
        return true;
    }

    // Everything else is a fighter's.
    const auto fighter_field = line.find("fighter");
    int index = 0;
    if (fighter_field != line.end()) {
        if (!fighter_field->is_number_integer() || fighter_field->get<long long>() < 0 || fighter_field->get<long long>() >= k_max_fighters) {
            return stop("fighter must be a number from 0 to " + std::to_string(k_max_fighters - 1));
        }
        index = static_cast<int>(fighter_field->get<long long>());
    }
    static const char* const k_fighter_types[] = {"order", "order_queued", "order_performed", "order_expired", "ignored_order", "strike",
                                                  "strike_end", "user_strike", "user_strike_end", "character", "tracker_lost",
                                                  "tracker_back", "fighter_position", "state", "hit_reaction", "user_strike_course", "user_response"};
    if (std::none_of(std::begin(k_fighter_types), std::end(k_fighter_types), [&](const char* known) { return type == known; })) {
        ++unknown_lines;
        return true;
    }
    FighterLog& log = fighter(index);
    if (type == "order" || type == "order_queued") {
        log.orders.push_back({*t, text(line, "command"), type == "order_queued"});
    } else if (type == "order_performed" || type == "order_expired" || type == "ignored_order") {
        const OrderEnd::How how = type == "order_performed" ? OrderEnd::How::performed
                                  : type == "order_expired" ? OrderEnd::How::expired
                                                            : OrderEnd::How::refused;
        log.order_ends.push_back({how, *t, number_or(line, "waited_s", -1.0), text(line, "why")});
    } else if (type == "strike") {
        StrikeRecord strike;
        strike.t_s = *t;
        strike.command = text(line, "command");
        strike.kind = text(line, "kind");
        strike.height = text(line, "height");
        strike.side = text(line, "clip_side");
        strike.clip = text(line, "clip");
        strike.aim = text(line, "aim");
        strike.hit = text(line, "result") == "hit";
        if (text(line, "result") == "blocked") strike.blocked_by = text(line, "blocked_by");
        strike.impact = text(line, "outcome") != "follow_through";
        strike.contact_error_m = number_or(line, "contact_error_m", -1.0);
        strike.effector_speed_mps = number_or(line, "effector_speed_at_contact_mps", -1.0);
        const double prediction = number_or(line, "prediction_error_m", -1.0);
        strike.prediction_error_m = prediction < 1e8 ? prediction : -1.0; // 1e9: no head at the contact
        strike.target = point(line, "target", *t);
        strike.aimed_point_at_contact = point(line, "aimed_point_at_contact", *t);
        log.strikes.push_back(std::move(strike));
    } else if (type == "user_response") {
        ResponseRecord response;
        response.t_s = *t;
        response.contact_s = number_or(line, "contact_s", -1.0);
        response.attack = text(line, "command") + " " + text(line, "kind");
        response.result = text(line, "result");
        response.response = text(line, "response");
        response.quality = text(line, "quality");
        response.moved = flag(line, "moved", false);
        response.response_time_s = number_or(line, "response_time_s", -1e9);
        response.countered = flag(line, "countered", false);
        response.counter_landed = flag(line, "counter_landed", false);
        log.responses.push_back(std::move(response));
    } else if (type == "strike_end") {
        if (!log.strikes.empty() && log.strikes.back().overshoot_m < 0.0) {
            StrikeRecord& strike = log.strikes.back();
            if (strike.impact) strike.overshoot_m = std::max(0.0, number_or(line, "overshoot_m", -1.0));
        }
        log.joint_limit_violations += static_cast<long long>(std::max(0.0, number_or(line, "joint_limit_violations", 0.0)));
    } else if (type == "user_strike") {
        UserStrikeRecord strike;
        strike.seen_s = *t;
        strike.hand = text(line, "hand");
        strike.aimed_at = text(line, "aimed_at");
        strike.move = text(line, "move");
        strike.detected = flag(line, "detected", true);
        log.user_strikes.push_back(strike);
        m_open_user_strikes[index].push_back(log.user_strikes.size() - 1);
    } else if (type == "user_strike_end") {
        // It ends the open strike of the same hand; an arrival never seen coming has no start.
        std::vector<std::size_t>& open = m_open_user_strikes[index];
        const std::string hand = text(line, "hand");
        auto match = std::find_if(open.begin(), open.end(), [&](std::size_t i) { return log.user_strikes[i].hand == hand; });
        UserStrikeRecord* strike = nullptr;
        if (match != open.end()) {
            strike = &log.user_strikes[*match];
            open.erase(match);
        } else {
            log.user_strikes.push_back({});
            strike = &log.user_strikes.back();
            strike->hand = hand;
            strike->aimed_at = text(line, "aimed_at");
            strike->move = text(line, "move");
        }
        strike->end_s = *t;
        strike->outcome = text(line, "outcome");
        strike->detected = flag(line, "detected", strike->detected);
        if (strike->outcome.empty()) strike->outcome = "unknown";
        strike->kept_off = strike->outcome == "slipped" && number_or(line, "unslipped_clearance_m", 1.0) <= 0.0;
        strike->approach_s = number_or(line, "approach_s", -1.0);
        m_last_ended[index][hand == "left" ? 0 : 1] = static_cast<std::size_t>(strike - log.user_strikes.data()) + 1;
        log.joint_limit_violations += static_cast<long long>(std::max(0.0, number_or(line, "joint_limit_violations", 0.0)));
    } else if (type == "user_strike_course") {
        // A blocked strike's path, followed on: it would have landed (on_course) or passed wide.
        const std::size_t last = m_last_ended[index][text(line, "hand") == "left" ? 0 : 1]; // its index + 1; 0: none
        if (last > 0 && last <= log.user_strikes.size() && log.user_strikes[last - 1].outcome == "blocked") {
            log.user_strikes[last - 1].kept_off = flag(line, "on_course", false);
        }
    } else if (type == "hit_reaction") {
        ++log.hit_reactions;
        const auto clip = line.find("clip");
        log.captured_hit_reactions += clip != line.end() && clip->is_string();
        log.hit_reaction_blows += static_cast<long long>(std::max(1.0, number_or(line, "blows", 1.0)));
    } else if (type == "character") {
        log.characters.push_back({*t, text(line, "character")});
    } else if (type == "tracker_lost") {
        if (log.tracker_losses.empty() || log.tracker_losses.back().back_s >= 0.0) log.tracker_losses.push_back({*t, -1.0});
    } else if (type == "tracker_back") {
        if (!log.tracker_losses.empty() && log.tracker_losses.back().back_s < 0.0) log.tracker_losses.back().back_s = *t;
    } else if (type == "fighter_position") {
        if (std::optional<RoomPoint> position = point(line, "position", *t)) log.positions.push_back(*position);
    }
    return true;
}

Result<SessionLog> read_session_log(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ErrorCode::io, path.string() + ": cannot open the events file");
    SessionLog log;
    std::string line;
    long long number = 0;
    while (std::getline(in, line)) {
        if (!log.add_text(line, ++number)) break;
    }
    if (log.stopped) log.stopped = path.string() + ":" + log.stopped->substr(5) + "; reading stopped there";
    return log;
}

} // namespace kumite::report
