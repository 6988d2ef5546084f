#pragma once
// What `kumite train` stores of a bout's event lines: the first fighter's blows with the person's answers
// (user_response lines) and the person's strikes (user_strike_end lines), each in the drill part it started in (as
// the drill_part lines told), and the session's summary from the report.

#include "training_store.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace kumite::cli {

class TrainRows {
public:
    // Takes one event line; returns the row it makes, if any.
    std::optional<training::AttackRow> attack(const nlohmann::json& line);
    std::optional<training::UserStrikeRow> user_strike(const nlohmann::json& line);
    void take_part(const nlohmann::json& line); // drill_part lines

private:
    struct Part {
        std::string name, difficulty;
        double end_s = 0.0;
    };
    int part_at(double t_s) const;

    std::vector<Part> m_parts;
    int m_attacks = 0, m_user_strikes = 0;
};

// The few numbers a session is remembered by: blows, their results and answers, the person's strikes.
nlohmann::json train_summary_json(const nlohmann::json& report);

} // namespace kumite::cli
