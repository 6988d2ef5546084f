#include "kumite/formats/character_catalog.h"

#include <algorithm>
#include <cstdlib>

namespace kumite {

std::filesystem::path locate_data_folder(const char* environment_variable, const std::filesystem::path& relative) {
    if (const char* folder = std::getenv(environment_variable); folder && *folder) return folder;
    std::error_code error;
    if (std::filesystem::exists(relative, error)) return relative;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path repository_root = executable.parent_path().parent_path().parent_path();
        if (std::filesystem::exists(repository_root / relative, error)) return repository_root / relative;
    }
    return relative;
}

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

} // namespace kumite
