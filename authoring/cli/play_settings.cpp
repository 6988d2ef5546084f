// Reading, writing and assigning the fighters' settings by name (play_settings.h); the table is in
// play_settings_table.cpp.

#include "play_settings.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace kumite::cli {

namespace {

constexpr std::uintmax_t k_max_settings_file_bytes = 1 << 20;

std::string number_text(double value) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value); // the shortest text that reads back exactly
    return error == std::errc() ? std::string(buffer, end) : std::string("nan");
}

std::string_view trimmed(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// What a setting takes, for errors and the file's comments: "a number from 0 to 5 s".
std::string accepted_text(const Setting& setting) {
    struct Describe {
        const Setting& s;
        std::string range(const char* kind) const {
            std::string text = std::string(kind) + " from " + number_text(s.min) + " to " + number_text(s.max);
            return *s.unit ? text + " " + s.unit : text;
        }
        std::string operator()(double*) const { return range("a number"); }
        std::string operator()(int*) const { return range("a whole number"); }
        std::string operator()(bool*) const { return "true or false"; }
        std::string operator()(FighterAim*) const { return "latched or predicted"; }
    };
    BoutOptions scratch;
    return std::visit(Describe{setting}, setting.field(scratch));
}

// Splits `help` into comment lines of at most ~116 characters, `tail` kept whole at its end.
void write_comment(std::ostringstream& out, const std::string& help, const std::string& tail) {
    std::vector<std::string> words;
    std::istringstream split(help);
    for (std::string word; split >> word;) words.push_back(word);
    words.push_back(tail);
    std::string line = "#";
    for (const std::string& word : words) {
        if (line.size() + 1 + word.size() > 116 && line.size() > 1) {
            out << line << "\n";
            line = "#";
        }
        line += " " + word;
    }
    out << line << "\n";
}

} // namespace

Result<void> play_setting_assign(BoutOptions& options, const Setting& setting, std::string_view text) {
    const std::string value(trimmed(text));
    const auto refuse = [&]() -> Result<void> {
        return make_error(ErrorCode::invalid, std::string(setting.name) + " must be " + accepted_text(setting) + ", not '" + value + "'");
    };
    const char* begin = value.data();
    const char* end = value.data() + value.size();
    struct Assign {
        const Setting& s;
        const std::string& value;
        const char *begin, *end;
        bool operator()(double* field) const {
            double number = 0.0;
            const auto [rest, error] = std::from_chars(begin, end, number);
            if (value.empty() || error != std::errc() || rest != end || !std::isfinite(number) || number < s.min || number > s.max) return false;
            *field = number;
            return true;
        }
        bool operator()(int* field) const {
            int number = 0;
            const auto [rest, error] = std::from_chars(begin, end, number);
            if (value.empty() || error != std::errc() || rest != end || number < s.min || number > s.max) return false;
            *field = number;
            return true;
        }
        bool operator()(bool* field) const {
            if (value != "true" && value != "false") return false;
            *field = value == "true";
            return true;
        }
        bool operator()(FighterAim* field) const {
            const std::optional<FighterAim> aim = fighter_aim_from_name(value);
            if (aim) *field = *aim;
            return aim.has_value();
        }
    };
    if (!std::visit(Assign{setting, value, begin, end}, setting.field(options))) return refuse();
    return {};
}

Result<void> play_setting_assign(BoutOptions& options, std::string_view name_equals_value) {
    const std::size_t equals = name_equals_value.find('=');
    if (equals == std::string_view::npos) {
        return make_error(ErrorCode::invalid, "--set takes name=value, not '" + std::string(name_equals_value) + "'");
    }
    const std::string name(trimmed(name_equals_value.substr(0, equals)));
    const Setting* setting = play_setting_named(name);
    if (!setting) return make_error(ErrorCode::invalid, "--set: no setting named '" + name + "' (kumite play --print-settings lists them)");
    return play_setting_assign(options, *setting, name_equals_value.substr(equals + 1));
}

std::string play_setting_text(const BoutOptions& options, const Setting& setting) {
    struct Text {
        std::string operator()(double* field) const { return number_text(*field); }
        std::string operator()(int* field) const { return std::to_string(*field); }
        std::string operator()(bool* field) const { return *field ? "true" : "false"; }
        std::string operator()(FighterAim* field) const { return fighter_aim_name(*field); }
    };
    BoutOptions copy = options;
    return std::visit(Text{}, setting.field(copy));
}

Result<void> play_settings_read(const std::filesystem::path& path, BoutOptions& options) {
    const std::string where = path.string();
    std::error_code size_error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, size_error);
    if (size_error) return make_error(ErrorCode::io, where + ": cannot read the settings file (" + size_error.message() + ")");
    if (bytes > k_max_settings_file_bytes) return make_error(ErrorCode::limit, where + ": " + std::to_string(bytes) + " bytes is too large for a settings file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ErrorCode::io, where + ": cannot open the settings file");
    // Assigned to a copy: a file refused half-way changes nothing.
    BoutOptions read = options;
    std::vector<std::pair<std::string, int>> seen; // name, line
    std::string raw;
    for (int line = 1; std::getline(in, raw); ++line) {
        const std::string_view content = trimmed(std::string_view(raw).substr(0, raw.find('#')));
        if (content.empty()) continue;
        const auto at = [&](const std::string& message, ErrorCode code = ErrorCode::invalid) {
            return make_error(code, where + ":" + std::to_string(line) + ": " + message);
        };
        const std::size_t equals = content.find('=');
        if (equals == std::string_view::npos) return at("expected 'name = value', not '" + std::string(content) + "'", ErrorCode::parse);
        const std::string name(trimmed(content.substr(0, equals)));
        const Setting* setting = play_setting_named(name);
        if (!setting) return at("no setting named '" + name + "' (kumite play --print-settings lists them)");
        for (const auto& [earlier, earlier_line] : seen) {
            if (earlier == name) return at(name + " is given twice (first on line " + std::to_string(earlier_line) + ")");
        }
        seen.emplace_back(name, line);
        if (Result<void> assigned = play_setting_assign(read, *setting, content.substr(equals + 1)); !assigned) return at(assigned.error().message);
    }
    if (in.bad()) return make_error(ErrorCode::io, where + ": reading the settings file failed");
    options = read;
    return {};
}

nlohmann::json play_settings_json(const BoutOptions& options) {
    struct Value {
        nlohmann::json operator()(double* field) const { return *field; }
        nlohmann::json operator()(int* field) const { return *field; }
        nlohmann::json operator()(bool* field) const { return *field; }
        nlohmann::json operator()(FighterAim* field) const { return fighter_aim_name(*field); }
    };
    BoutOptions copy = options;
    nlohmann::json values = nlohmann::json::object();
    for (const Setting& setting : play_settings()) values[setting.name] = std::visit(Value{}, setting.field(copy));
    return values;
}

std::string play_settings_text(const BoutOptions& options) {
    const BoutOptions defaults;
    std::ostringstream out;
    out << "# kumite play settings: `name = value` per line, `#` starts a comment. Read with kumite play --settings FILE;\n"
           "# written by kumite play --print-settings (every setting, its meaning, what it takes and its default).\n";
    const char* group = nullptr;
    for (const Setting& setting : play_settings()) {
        if (!group || std::string_view(group) != setting.group) {
            group = setting.group;
            out << "\n# == " << group << "\n";
        }
        write_comment(out, setting.help, "[" + accepted_text(setting) + "; default " + play_setting_text(defaults, setting) + "]");
        out << setting.name << " = " << play_setting_text(options, setting) << "\n";
    }
    return out.str();
}

} // namespace kumite::cli
