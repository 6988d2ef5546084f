#include "arguments.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <algorithm>
#include <iostream>

namespace kumite::cli {

bool Arguments::has(const std::string& flag) const {
    return values.count(flag) > 0 || lists.count(flag) > 0 || std::find(switches.begin(), switches.end(), flag) != switches.end();
}

std::optional<std::string> Arguments::value(const std::string& flag) const {
    const auto found = values.find(flag);
    if (found == values.end()) return std::nullopt;
    return found->second;
}

std::vector<std::string> Arguments::all(const std::string& flag) const {
    const auto found = lists.find(flag);
    return found == lists.end() ? std::vector<std::string>{} : found->second;
}

Result<long long> Arguments::integer(const std::string& flag, long long min, long long max, long long fallback) const {
    const std::optional<std::string> text = value(flag);
    if (!text) return fallback;
    long long number = 0;
    const char* end = text->data() + text->size();
    const auto [rest, error] = std::from_chars(text->data(), end, number);
    if (error != std::errc() || rest != end || number < min || number > max) {
        return make_error(ErrorCode::invalid, "--" + flag + " must be a whole number from " + std::to_string(min) + " to " +
                                                  std::to_string(max) + ", not '" + *text + "'");
    }
    return number;
}

Result<double> Arguments::number(const std::string& flag, double min, double max, double fallback, const std::string& unit) const {
    const std::optional<std::string> text = value(flag);
    if (!text) return fallback;
    char* end = nullptr;
    const double number = std::strtod(text->c_str(), &end);
    if (text->empty() || end != text->c_str() + text->size() || !std::isfinite(number) || number < min || number > max) {
        std::ostringstream range;
        range << "--" << flag << " must be " << min << " to " << max << " " << unit << ", not '" << *text << "'";
        return make_error(ErrorCode::invalid, range.str());
    }
    return number;
}

Result<ParseOutcome> parse_arguments(const CommandSpec& spec, int argc, char** argv) {
    ParseOutcome outcome;
    Arguments& arguments = outcome.arguments;
    bool only_positionals = false;
    for (int i = 0; i < argc; ++i) {
        std::string argument = argv[i];
        if (argument == "-o" && !only_positionals) argument = "--output"; // the short form every tool knows
        if (only_positionals || argument.size() < 2 || argument[0] != '-' || argument == "-") {
            arguments.positionals.push_back(argument);
            continue;
        }
        if (argument == "--") {
            only_positionals = true;
            continue;
        }
        if (argument == "--help" || argument == "-h") {
            outcome.help_requested = true;
            return outcome;
        }
        if (!argument.starts_with("--")) return make_error(ErrorCode::invalid, "unknown option " + argument);
        std::string name = argument.substr(2);
        std::optional<std::string> inline_value;
        if (const size_t equals = name.find('='); equals != std::string::npos) {
            inline_value = name.substr(equals + 1);
            name = name.substr(0, equals);
        }
        const auto spec_flag = std::find_if(spec.flags.begin(), spec.flags.end(),
                                            [&](const FlagSpec& flag) { return flag.name == name; });
        if (spec_flag == spec.flags.end()) return make_error(ErrorCode::invalid, "unknown flag --" + name);
        if (spec_flag->value_name.empty()) {
            if (inline_value) return make_error(ErrorCode::invalid, "flag --" + name + " takes no value");
            arguments.switches.push_back(name);
            continue;
        }
        if (!inline_value) {
            if (i + 1 >= argc) return make_error(ErrorCode::invalid, "flag --" + name + " needs a value (" + spec_flag->value_name + ")");
            inline_value = argv[++i];
        }
        if (spec_flag->repeatable) {
            arguments.lists[name].push_back(*inline_value);
            continue;
        }
        if (arguments.values.count(name)) return make_error(ErrorCode::invalid, "flag --" + name + " given twice");
        arguments.values[name] = *inline_value;
    }
    const int count = static_cast<int>(arguments.positionals.size());
    if (count < spec.min_positionals) return make_error(ErrorCode::invalid, "missing argument (usage: kumite " + spec.name + " " + spec.synopsis + ")");
    if (count > spec.max_positionals) return make_error(ErrorCode::invalid, "unexpected argument '" + arguments.positionals[spec.max_positionals] + "'");
    return outcome;
}

std::string usage_text(const CommandSpec& spec) {
    std::string text = "usage: kumite " + spec.name + " " + spec.synopsis + "\n\n" + spec.description + "\n\noptions:\n";
    for (const FlagSpec& flag : spec.flags) {
        std::string left = "  --" + flag.name + (flag.value_name.empty() ? "" : " " + flag.value_name);
        if (left.size() < 30) left.resize(30, ' ');
        else left += "\n" + std::string(30, ' ');
        std::string help = flag.help; // continuation lines under the first
        for (std::size_t at = help.find('\n'); at != std::string::npos; at = help.find('\n', at + 31)) help.insert(at + 1, 30, ' ');
        text += left + help + "\n";
    }
    text += "  --help                      this text\n";
    return text;
}

FlagSpec unit_flag() {
    return {"unit", "auto|m|cm|mm|in|cmu", "length unit of the file (default auto: detected from the skeleton's height)"};
}
FlagSpec strict_flag() {
    return {"strict", "", "refuse captures that other readers accept with a warning (an 'End name' block, frames not one per line,\n"
                          "values after the declared frames)"};
}
FlagSpec fps_flag() {
    return {"fps", "N", "frame rate of a capture whose file gives none ('Frame Time: 0' or no such line); replaces a rate the\n"
                        "file states, with a warning"};
}
FlagSpec mocap_root_flag() {
    return {"mocap-root", "DIR", "where relative capture paths are also looked up (default data/mocap)"};
}
FlagSpec body_map_flag() {
    return {"body-map", "FILE.json", "body map override (default: FILE.bodymap.json beside the capture, if any)"};
}
FlagSpec json_flag() { return {"json", "", "print one JSON document on stdout"}; }
FlagSpec verbose_flag() {
    return {"verbose", "", "list every warning on its own line (default: one line per kind of warning, the first in full\n"
                           "with how many there are)"};
}
FlagSpec verify_flag() {
    return {"verify", "", "also check every per-pose value (pose records, MIR frames, features, cluster members) and the\n"
                          "content hash; opening alone checks the structure only, in the same time for any size"};
}

std::optional<int> parse_command_line(const CommandSpec& spec, int argc, char** argv, Arguments& arguments) {
    Result<ParseOutcome> outcome = parse_arguments(spec, argc, argv);
    if (!outcome) return usage_error(spec, outcome.error().message);
    if (outcome->help_requested) {
        std::cout << usage_text(spec);
        return k_exit_ok;
    }
    arguments = std::move(outcome->arguments);
    return std::nullopt;
}

int usage_error(const CommandSpec& spec, const std::string& message) {
    std::cerr << "kumite " << spec.name << ": " << message << " (see kumite " << spec.name << " --help)\n";
    return k_exit_usage;
}

int input_error(const std::string& message) {
    std::cerr << "kumite: " << message << "\n";
    return k_exit_bad_input;
}

} // namespace kumite::cli
