#pragma once
// An event line's fields, read without trusting the line: a key that is missing, of another type, or (for numbers)
// not finite gives the fallback. Shared by the session report and what `kumite train` stores.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace kumite::report {

std::optional<double> number(const nlohmann::json& line, const char* key);
double number_or(const nlohmann::json& line, const char* key, double fallback);
std::string text(const nlohmann::json& line, const char* key);
bool flag(const nlohmann::json& line, const char* key, bool fallback);

} // namespace kumite::report
