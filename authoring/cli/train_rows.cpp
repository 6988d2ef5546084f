// What `kumite train` stores of a bout's event lines (train_rows.h).

#include "train_rows.h"

#include <cmath>

namespace kumite::cli {
namespace {

std::string text_at(const nlohmann::json& line, const char* key) {
    const auto found = line.find(key);
    return found != line.end() && found->is_string() ? found->get<std::string>() : std::string();
}

double number_at(const nlohmann::json& line, const char* key, double otherwise = training::k_no_value) {
    const auto found = line.find(key);
    return found != line.end() && found->is_number() ? found->get<double>() : otherwise;
}

bool flag_at(const nlohmann::json& line, const char* key) {
    const auto found = line.find(key);
    return found != line.end() && found->is_boolean() && found->get<bool>();
}

bool first_fighter(const nlohmann::json& line) { return number_at(line, "fighter", 0.0) == 0.0; }

} // namespace

void TrainRows::take_part(const nlohmann::json& line) {
    const int index = int(number_at(line, "part", -1.0));
    if (index < 0) return;
    if (std::size_t(index) >= m_parts.size()) m_parts.resize(std::size_t(index) + 1);
    m_parts[std::size_t(index)] = {text_at(line, "name"), text_at(line, "difficulty"), number_at(line, "end_s", 0.0)};
}

int TrainRows::part_at(double t_s) const {
    for (std::size_t p = 0; p < m_parts.size(); ++p) {
        if (t_s < m_parts[p].end_s) return int(p);
    }
    return m_parts.empty() ? 0 : int(m_parts.size()) - 1;
}

std::optional<training::AttackRow> TrainRows::attack(const nlohmann::json& line) {
    if (text_at(line, "type") != "user_response" || !first_fighter(line)) return std::nullopt;
    training::AttackRow row;
    row.seq = m_attacks++;
    row.t_s = number_at(line, "began_s", number_at(line, "t", 0.0));
    row.part = part_at(row.t_s);
    if (std::size_t(row.part) < m_parts.size()) {
        row.part_name = m_parts[std::size_t(row.part)].name;
        row.difficulty = m_parts[std::size_t(row.part)].difficulty;
    }
    row.command = text_at(line, "command");
    row.kind = text_at(line, "kind");
    row.height = text_at(line, "height");
    row.side = text_at(line, "clip_side");
    row.target_part = text_at(line, "target_part");
    row.combination = text_at(line, "combination");
    row.blow = int(number_at(line, "blow", 0.0));
    row.own = flag_at(line, "own");
    row.result = text_at(line, "result");
    row.blocked_by = text_at(line, "blocked_by");
    row.response = text_at(line, "response");
    row.response_time_s = number_at(line, "response_time_s");
    row.quality = text_at(line, "quality");
    row.countered = flag_at(line, "countered");
    row.counter_landed = row.countered ? int(flag_at(line, "counter_landed")) : -1;
    return row;
}

std::optional<training::UserStrikeRow> TrainRows::user_strike(const nlohmann::json& line) {
    if (text_at(line, "type") != "user_strike_end" || !first_fighter(line)) return std::nullopt;
    training::UserStrikeRow row;
    row.seq = m_user_strikes++;
    row.t_s = number_at(line, "t", 0.0);
    row.part = part_at(row.t_s);
    row.hand = text_at(line, "hand");
    row.aimed_at = text_at(line, "aimed_at");
    row.move = text_at(line, "move");
    row.outcome = text_at(line, "outcome");
    row.defended = flag_at(line, "defended");
    row.peak_speed_mps = number_at(line, "peak_speed_mps");
    return row;
}

nlohmann::json train_summary_json(const nlohmann::json& report) {
    nlohmann::json summary = nlohmann::json::object();
    for (const char* key : {"frames", "strikes", "hits", "misses", "blocked_by_user", "orders", "difficulty"}) {
        if (report.contains(key)) summary[key] = report.at(key);
    }
    if (report.contains("user_strikes")) summary["user_strikes"] = report.at("user_strikes");
    if (report.contains("user_responses")) summary["user_responses"] = report.at("user_responses");
    if (report.contains("frame_time_us")) summary["frame_time_us"] = report.at("frame_time_us");
    return summary;
}

} // namespace kumite::cli
