// Drill files (drill_file.h), read with toml11 (Debian's libtoml11-dev).

#include "kumite/formats/drill_file.h"

#include <toml.hpp>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <sstream>

namespace kumite {
namespace {

constexpr std::size_t k_largest_file = 1 << 20; // a drill is a page of text; a megabyte is not one
constexpr int k_deepest_nesting = 8;            // [[part]] arrays of strings need 2; toml11 recurses per level
constexpr int k_most_parts = 1000;

// The deepest nesting of [ and { outside strings and comments: refused early, before a recursive parser sees it.
int deepest_nesting(std::string_view text) {
    int depth = 0, deepest = 0;
    char quote = 0;
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (comment) {
            comment = c != '\n';
        } else if (quote) {
            if (c == '\\' && quote == '"') ++i;
            else if (c == quote || c == '\n') quote = 0;
        } else if (c == '#') {
            comment = true;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// The first line holding a byte TOML allows nowhere (a control character but tab, or bytes that are not UTF-8), or 0.
// Refused before the parser sees them: toml11 3.7 reads past the end of an unterminated string of such bytes.
int line_of_bad_byte(std::string_view text) {
    int line = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            continue;
        }
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) return line;
        if (c < 0x80) continue;
        // A UTF-8 sequence: a lead byte and its continuation bytes, no overlong two-byte forms.
        const int more = c >= 0xf5 ? -1 : c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : c >= 0xc2 ? 1 : -1;
        if (more < 0) return line;
        for (int k = 1; k <= more; ++k) {
            if (i + std::size_t(k) >= text.size() || (static_cast<unsigned char>(text[i + std::size_t(k)]) & 0xc0) != 0x80) return line;
        }
        i += std::size_t(more);
    }
    return 0;
}

class Reader {
public:
    explicit Reader(const std::string& file) : m_file(file) {}

    Error error(int line, const std::string& reason) const { return make_error(ErrorCode::invalid, m_file + ":" + std::to_string(line) + ": " + reason); }
    static int line_of(const toml::value& value) { return int(value.location().line()); }

    // Every key of `table` among `known`, else the first that is not.
    Result<void> known_keys(const toml::value& table, std::initializer_list<const char*> known, const char* where) const {
        for (const auto& [key, value] : table.as_table()) {
            bool found = false;
            for (const char* name : known) found = found || key == name;
            if (found) continue;
            std::string names;
            for (const char* name : known) names += (names.empty() ? "" : ", ") + std::string(name);
            return error(line_of(value), "unknown key '" + key + "' in " + where + " (" + names + ")");
        }
        return {};
    }

    Result<std::string> text(const toml::value& value, const char* key) const {
        if (!value.is_string()) return error(line_of(value), std::string(key) + " must be a string");
        std::string out = value.as_string().str;
        if (out.empty()) return error(line_of(value), std::string(key) + " is empty");
        return out;
    }

    Result<double> number(const toml::value& value, const char* key, double low, double high) const {
        double out = 0.0;
        if (value.is_integer()) out = double(value.as_integer());
        else if (value.is_floating()) out = value.as_floating();
        else return error(line_of(value), std::string(key) + " must be a number");
        if (!std::isfinite(out) || out < low || out > high) {
            std::ostringstream range;
            range << key << " must be within " << low << " and " << high;
            return error(line_of(value), range.str());
        }
        return out;
    }

    Result<DrillPart> part(const toml::value& table, int index) const {
        DrillPart part;
        part.line = line_of(table);
        if (!table.is_table()) return error(part.line, "part " + std::to_string(index) + " must be a table ([[part]])");
        if (auto keys = known_keys(table, {"name", "attacks", "free_sparring", "order", "cadence_s", "count", "duration_s", "seed", "difficulty"},
                                   "a part");
            !keys) {
            return keys.error();
        }
        const auto& t = table.as_table();
        const auto at = [&t](const char* key) -> const toml::value* {
            const auto found = t.find(key);
            return found == t.end() ? nullptr : &found->second;
        };
        if (!at("name")) return error(part.line, "part " + std::to_string(index) + " has no name");
        if (auto name = text(*at("name"), "name"); !name) return name.error();
        else part.name = *name;
        if (const toml::value* free = at("free_sparring")) {
            if (!free->is_boolean()) return error(line_of(*free), "free_sparring must be true or false");
            part.free_sparring = free->as_boolean();
        }
        if (const toml::value* attacks = at("attacks")) {
            if (part.free_sparring) return error(line_of(*attacks), "a free sparring part takes no attacks (the fighter chooses them)");
            if (!attacks->is_array() || attacks->as_array().empty()) return error(line_of(*attacks), "attacks must be a list of commands, e.g. [\"punch\", \"combo one-two\"]");
            for (const toml::value& attack : attacks->as_array()) {
                Result<std::string> command = text(attack, "an attack");
                if (!command) return command.error();
                part.attacks.push_back({*command, line_of(attack)});
            }
        } else if (!part.free_sparring) {
            return error(part.line, "part '" + part.name + "' has neither attacks nor free_sparring = true");
        }
        if (const toml::value* order = at("order")) {
            Result<std::string> way = text(*order, "order");
            if (!way) return way.error();
            if (*way != "random" && *way != "in turn") return error(line_of(*order), "order must be \"random\" or \"in turn\", not \"" + *way + "\"");
            part.in_turn = *way == "in turn";
        }
        if (const toml::value* cadence = at("cadence_s")) {
            if (cadence->is_array()) {
                const auto& range = cadence->as_array();
                if (range.size() != 2) return error(line_of(*cadence), "cadence_s must be a number or [low, high]");
                Result<double> low = number(range[0], "cadence_s", 0.3, 600.0), high = number(range[1], "cadence_s", 0.3, 600.0);
                if (!low) return low.error();
                if (!high) return high.error();
                if (*high < *low) return error(line_of(*cadence), "cadence_s's high end is under its low end");
                part.cadence_min_s = *low, part.cadence_max_s = *high;
            } else {
                Result<double> fixed = number(*cadence, "cadence_s", 0.3, 600.0);
                if (!fixed) return fixed.error();
                part.cadence_min_s = part.cadence_max_s = *fixed;
            }
        }
        const toml::value *count = at("count"), *duration = at("duration_s");
        if ((count != nullptr) == (duration != nullptr)) return error(part.line, "part '" + part.name + "' needs one of count and duration_s");
        if (count) {
            if (!count->is_integer() || count->as_integer() < 1 || count->as_integer() > 100000) return error(line_of(*count), "count must be a whole number from 1 to 100000");
            part.count = int(count->as_integer());
        } else {
            Result<double> seconds = number(*duration, "duration_s", 1.0, 36000.0);
            if (!seconds) return seconds.error();
            part.duration_s = *seconds;
        }
        if (const toml::value* seed = at("seed")) {
            if (!seed->is_integer() || seed->as_integer() < 0) return error(line_of(*seed), "seed must be a whole number, 0 or more");
            part.seed = std::uint64_t(seed->as_integer());
        }
        if (const toml::value* difficulty = at("difficulty")) {
            Result<std::string> level = text(*difficulty, "difficulty");
            if (!level) return level.error();
            part.difficulty = {*level, line_of(*difficulty)};
        }
        return part;
    }

    Result<Drill> drill(const toml::value& root) const {
        if (auto keys = known_keys(root, {"name", "part"}, "the drill"); !keys) return keys.error();
        const auto& t = root.as_table();
        Drill drill;
        const auto name = t.find("name");
        if (name == t.end()) return error(1, "the drill has no name (name = \"...\")");
        if (auto text_name = text(name->second, "name"); !text_name) return text_name.error();
        else drill.name = *text_name;
        const auto parts = t.find("part");
        if (parts == t.end() || !parts->second.is_array() || parts->second.as_array().empty()) {
            return error(parts == t.end() ? 1 : line_of(parts->second), "the drill has no parts ([[part]] tables)");
        }
        if (int(parts->second.as_array().size()) > k_most_parts) return error(line_of(parts->second), "more than 1000 parts");
        int index = 1;
        for (const toml::value& table : parts->second.as_array()) {
            Result<DrillPart> part = this->part(table, index++);
            if (!part) return part.error();
            drill.parts.push_back(std::move(*part));
        }
        return drill;
    }

private:
    std::string m_file;
};

} // namespace

Result<Drill> drill_parse(std::string_view text, const std::string& file_name) {
    if (text.size() > k_largest_file) return make_error(ErrorCode::invalid, file_name + ":1: larger than a drill can be (1 MB)");
    if (deepest_nesting(text) > k_deepest_nesting) return make_error(ErrorCode::parse, file_name + ":1: lists nested deeper than a drill's");
    if (const int bad = line_of_bad_byte(text)) {
        return make_error(ErrorCode::parse, file_name + ":" + std::to_string(bad) + ": a control character or bytes that are not UTF-8 text");
    }
    Reader reader(file_name);
    try {
        std::istringstream in{std::string(text) + "\n"}; // a last line ended: toml11 then never reads past the text
        const toml::value root = toml::parse(in, file_name);
        return reader.drill(root);
    } catch (const toml::exception& e) {
        // toml11's message: "[error] toml::parse_...: REASON\n --> FILE\n ..." with the line in its location.
        std::string reason = e.what();
        reason = reason.substr(0, reason.find('\n'));
        if (const std::size_t colon = reason.find(": "); reason.rfind("[error]", 0) == 0 && colon != std::string::npos) reason = reason.substr(colon + 2);
        return make_error(ErrorCode::parse, file_name + ":" + std::to_string(std::max<std::uint_least32_t>(1, e.location().line())) + ": " + reason);
    } catch (const std::exception& e) {
        return make_error(ErrorCode::parse, file_name + ":1: " + e.what());
    }
}

Result<Drill> drill_read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(ErrorCode::io, path + ": cannot read the drill");
    std::string text;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, std::size_t(in.gcount()));
        if (text.size() > k_largest_file) break;
    }
    return drill_parse(text, path);
}

} // namespace kumite
