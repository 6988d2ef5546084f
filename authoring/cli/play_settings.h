#pragma once
// The fighters' settings by name, for `kumite play --settings FILE`, `--set name=value` and `--print-settings`:
// every field of BoutOptions that tunes the fighters (their strikes, distance, speeds, defence, reactions, orders and
// the head filter behind predicted aim), each with its range and one line that documents it. Names are the fields'
// own, nested ones with their struct's prefix (`defence.hold_s`); the defaults are BoutOptions{}'s.

#include "kumite/core/result.h"
#include "kumite/runtime/bout.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace kumite::cli {

using SettingField = std::variant<double*, int*, bool*, FighterAim*>;

struct Setting {
    const char* name;  // "defence.hold_s"
    const char* group; // the heading it is printed under
    double min = 0.0, max = 0.0; // numbers and whole numbers: the accepted range
    const char* unit;  // "s", "m", "m/s", "leg lengths", ... ("" for none)
    const char* help;  // one line
    SettingField (*field)(BoutOptions& options);
};

// Every setting, in the order --print-settings prints them.
std::span<const Setting> play_settings();
// nullptr when there is no setting of that name.
const Setting* play_setting_named(std::string_view name);

// Sets one setting from its text (a number, a whole number, true/false, latched/predicted); the error says which
// setting, what it takes and what it got.
Result<void> play_setting_assign(BoutOptions& options, const Setting& setting, std::string_view text);
// `name=value` (the --set flag's value).
Result<void> play_setting_assign(BoutOptions& options, std::string_view name_equals_value);
// The setting's value as the settings file writes it (numbers in their shortest exact form).
std::string play_setting_text(const BoutOptions& options, const Setting& setting);

// Reads a settings file: `name = value` lines, `#` comments, blank lines; a setting given twice, an unknown name or a
// bad value is refused with the file and line. Settings the file leaves out keep their value in `options`.
Result<void> play_settings_read(const std::filesystem::path& path, BoutOptions& options);
// The settings file of every setting's value, each under a comment with its meaning and default: what
// play_settings_read reads back to the same values.
std::string play_settings_text(const BoutOptions& options);
// Every setting's value by name, typed (numbers, whole numbers, true/false, the aim's name): the report's "settings".
nlohmann::json play_settings_json(const BoutOptions& options);

} // namespace kumite::cli
