#pragma once
// A small command-line parser for the kumite subcommands: `--flag`, `--flag value`, `--flag=value` and
// positionals; `-o` is short for `--output`. Unknown flags and missing values are usage errors (exit status 2).

#include "kumite/core/result.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace kumite::cli {

inline constexpr int k_exit_ok = 0;
inline constexpr int k_exit_bad_input = 1;
inline constexpr int k_exit_usage = 2;

struct FlagSpec {
    std::string name;       // without dashes: "unit"
    std::string value_name; // empty for a switch: "auto|m|cm|mm|in|cmu"
    std::string help;
    bool repeatable = false; // a flag with a value that may be given several times (Arguments::all)
};

struct CommandSpec {
    std::string name;        // "inspect"
    std::string synopsis;    // "FILE.bvh [--unit ...] [--json]"
    std::string description; // one paragraph
    int min_positionals = 0;
    int max_positionals = 0;
    std::vector<FlagSpec> flags;
};

struct Arguments {
    std::vector<std::string> positionals;
    std::map<std::string, std::string> values; // flags with values
    std::vector<std::string> switches;         // flags without values
    std::map<std::string, std::vector<std::string>> lists; // repeatable flags' values, in the order given

    bool has(const std::string& flag) const;
    std::optional<std::string> value(const std::string& flag) const;
    // Every value of a repeatable flag, in the order given (empty when absent).
    std::vector<std::string> all(const std::string& flag) const;
    // The flag as a whole number in [min, max], `fallback` when absent; an error says which flag and why.
    Result<long long> integer(const std::string& flag, long long min, long long max, long long fallback) const;
    // The flag as a finite number in [min, max] (`unit` names it in the error: "seconds"), `fallback` when absent.
    Result<double> number(const std::string& flag, double min, double max, double fallback, const std::string& unit) const;
};

// Parses argv after the subcommand name. `--help` is reported as help_requested.
struct ParseOutcome {
    Arguments arguments;
    bool help_requested = false;
};
Result<ParseOutcome> parse_arguments(const CommandSpec& spec, int argc, char** argv);

std::string usage_text(const CommandSpec& spec);

// Flags every capture-reading command shares.
FlagSpec unit_flag();
FlagSpec strict_flag(); // --strict: refuse a capture that reads only with warnings
FlagSpec fps_flag();    // --fps N: the rate of a capture whose file gives none
FlagSpec mocap_root_flag();
FlagSpec body_map_flag();
FlagSpec json_flag();
FlagSpec verbose_flag(); // --verbose: every warning, not one line per kind (warning_groups.h)
// Flags every command that opens a motion database shares.
FlagSpec verify_flag(); // --verify: check every per-pose value and the content hash, not only the structure

// Parses and handles --help and usage errors: returns the exit status when the command should stop now.
std::optional<int> parse_command_line(const CommandSpec& spec, int argc, char** argv, Arguments& arguments);

// Prints "kumite NAME: message" and returns the usage exit status.
int usage_error(const CommandSpec& spec, const std::string& message);
// Prints "kumite: message" to stderr and returns the bad-input exit status.
int input_error(const std::string& message);

} // namespace kumite::cli
