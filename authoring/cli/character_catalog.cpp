#include "character_catalog.h"

#include "capture_loading.h"

#include <algorithm>

namespace kumite::cli {

std::filesystem::path default_characters_dir() { return locate_data_folder("KUMITE_CHARACTERS_DIR", "data/characters"); }

std::vector<CharacterEntry> list_characters(const std::filesystem::path& folder) {
    std::vector<CharacterEntry> entries;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".bvh") entries.push_back({entry.path().stem().string(), entry.path()});
    }
    std::sort(entries.begin(), entries.end(), [](const CharacterEntry& a, const CharacterEntry& b) { return a.name < b.name; });
    return entries;
}

Result<BvhFile> load_character(const std::filesystem::path& folder, const std::string& name) {
    const std::vector<CharacterEntry> entries = list_characters(folder);
    for (const CharacterEntry& entry : entries) {
        if (entry.name == name) return bvh_read_file(entry.file);
    }
    std::string known;
    for (const CharacterEntry& entry : entries) known += (known.empty() ? "" : ", ") + entry.name;
    return make_error(ErrorCode::invalid, "unknown character '" + name + "' in " + folder.string() +
                                              (known.empty() ? " (no characters there)" : " (known: " + known + ")"));
}

FlagSpec characters_dir_flag() {
    return {"characters-dir", "DIR", "where the character files are (default data/characters)"};
}

} // namespace kumite::cli
