// What `kumite train` stores of a bout's event lines (train_rows.h).

#include "train_rows.h"

#include "event_fields.h"

#include <cmath>

namespace kumite::cli {
namespace {

using report::flag;
using report::number_or;
using report::text;

bool first_fighter(const nlohmann::json& line) { return number_or(line, "fighter", 0.0) == 0.0; }

} // namespace

void TrainRows::take_part(const nlohmann::json& line) {
    const int index = int(number_or(line, "part", -1.0));
    if (index < 0) return;
    if (std::size_t(index) >= m_parts.size()) m_parts.resize(std::size_t(index) + 1);
    m_parts[std::size_t(index)] = {text(line, "name"), text(line, "difficulty"), number_or(line, "end_s", 0.0)};
}

int TrainRows::part_at(double t_s) const {
    for (std::size_t p = 0; p < m_parts.size(); ++p) {
        if (t_s < m_parts[p].end_s) return int(p);
    }
    return m_parts.empty() ? 0 : int(m_parts.size()) - 1;
}

std::optional<training::AttackRow> TrainRows::attack(const nlohmann::json& line) {
    if (text(line, "type") != "user_response" || !first_fighter(line)) return std::nullopt;
    training::AttackRow row;
    row.seq = m_attacks++;
    row.t_s = number_or(line, "began_s", number_or(line, "t", 0.0));
    row.part = part_at(row.t_s);
    if (std::size_t(row.part) < m_parts.size()) {
        row.part_name = m_parts[std::size_t(row.part)].name;
        row.difficulty = m_parts[std::size_t(row.part)].difficulty;
    }
    row.command = text(line, "command");
    row.kind = text(line, "kind");
    row.height = text(line, "height");
    row.side = text(line, "clip_side");
    row.target_part = text(line, "target_part");
    row.combination = text(line, "combination");
    row.blow = int(number_or(line, "blow", 0.0));
    row.own = flag(line, "own", false);
    row.result = text(line, "result");
    row.blocked_by = text(line, "blocked_by");
    row.response = text(line, "response");
    row.response_time_s = number_or(line, "response_time_s", training::k_no_value);
    row.quality = text(line, "quality");
    row.countered = flag(line, "countered", false);
    row.counter_landed = row.countered ? int(flag(line, "counter_landed", false)) : -1;
    return row;
}

std::optional<training::UserStrikeRow> TrainRows::user_strike(const nlohmann::json& line) {
    if (text(line, "type") != "user_strike_end" || !first_fighter(line)) return std::nullopt;
    training::UserStrikeRow row;
    row.seq = m_user_strikes++;
    row.t_s = number_or(line, "t", 0.0);
    row.part = part_at(row.t_s);
    row.hand = text(line, "hand");
    row.aimed_at = text(line, "aimed_at");
    row.move = text(line, "move");
    row.outcome = text(line, "outcome");
    row.defended = flag(line, "defended", false);
    row.peak_speed_mps = number_or(line, "peak_speed_mps", training::k_no_value);
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
