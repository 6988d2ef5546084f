#include "kumite/core/strike_thresholds.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace kumite {
namespace {

struct Field {
    const char* name;
    double StrikeThresholds::*member;
};

constexpr std::array<Field, 8> k_fields{{{"punch_reach", &StrikeThresholds::punch_reach},
                                         {"punch_rise", &StrikeThresholds::punch_rise},
                                         {"both_arms_s", &StrikeThresholds::both_arms_s},
                                         {"swing_speed", &StrikeThresholds::swing_speed},
                                         {"swing_guard_height", &StrikeThresholds::swing_guard_height},
                                         {"uppercut_rise", &StrikeThresholds::uppercut_rise},
                                         {"cover_rise", &StrikeThresholds::cover_rise},
                                         {"cover_upright", &StrikeThresholds::cover_upright}}};

std::string field_names() {
    std::string names;
    for (const Field& field : k_fields) names += std::string(names.empty() ? "" : ", ") + field.name;
    return names;
}

} // namespace

Result<StrikeThresholds> strike_thresholds_parse(std::string_view text) {
    StrikeThresholds thresholds;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (item.empty()) continue;
        const std::size_t equals = item.find('=');
        const std::string_view name = item.substr(0, equals);
        const Field* field = nullptr;
        for (const Field& candidate : k_fields) {
            if (name == candidate.name) field = &candidate;
        }
        if (!field) {
            return make_error(ErrorCode::invalid, "unknown strike threshold '" + std::string(name) + "' (known: " + field_names() + ")");
        }
        const std::string value(equals == std::string_view::npos ? std::string_view{} : item.substr(equals + 1));
        double number = 0.0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
        if (value.empty() || error != std::errc{} || end != value.data() + value.size() || !std::isfinite(number)) {
            return make_error(ErrorCode::invalid, "strike threshold " + std::string(name) + ": '" + value + "' is not a number (write name=value)");
        }
        thresholds.*(field->member) = number;
    }
    return thresholds;
}

} // namespace kumite
