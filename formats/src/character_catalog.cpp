#include "kumite/formats/character_catalog.h"

#include "kumite/formats/gltf_reader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>

namespace kumite {

std::filesystem::path locate_data_folder(const char* environment_variable, const std::filesystem::path& relative) {
    if (const char* folder = std::getenv(environment_variable); folder && *folder) return folder;
    std::error_code error;
    if (std::filesystem::exists(relative, error)) return relative;
    // The build tree's binaries sit two folders under the repository (build/bin/kumite, build/lib/libkumite.so,
    // build/python/kumite...so): from the executable, else from the library this code was linked into.
    std::vector<std::filesystem::path> binaries;
    if (std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error); !error) binaries.push_back(executable);
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&locate_data_folder), &info) != 0 && info.dli_fname) binaries.push_back(info.dli_fname);
    for (const std::filesystem::path& binary : binaries) {
        const std::filesystem::path repository_root = std::filesystem::absolute(binary, error).parent_path().parent_path().parent_path();
        if (std::filesystem::exists(repository_root / relative, error)) return repository_root / relative;
    }
    return relative;
}

std::filesystem::path default_characters_dir() { return locate_data_folder("KUMITE_CHARACTERS_DIR", "data/characters"); }

std::vector<CharacterEntry> list_characters(const std::filesystem::path& folder) {
    std::vector<CharacterEntry> entries;
    std::error_code error;
    std::vector<std::filesystem::path> bodies;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        if (entry.path().extension() == ".bvh") entries.push_back({entry.path().stem().string(), entry.path(), {}});
        else if (is_gltf_path(entry.path())) bodies.push_back(entry.path());
    }
    // A glTF file beside a BVH of the same name is that character's body; alone, it is a character of its own.
    for (const std::filesystem::path& body : bodies) {
        const auto same = std::find_if(entries.begin(), entries.end(), [&](const CharacterEntry& entry) { return entry.name == body.stem().string(); });
        if (same != entries.end()) same->body = body;
        else entries.push_back({body.stem().string(), body, body});
    }
    std::sort(entries.begin(), entries.end(), [](const CharacterEntry& a, const CharacterEntry& b) { return a.name < b.name; });
    return entries;
}

bool character_file_exists(const std::filesystem::path& path) {
    std::error_code error;
    return (is_gltf_path(path) || path.extension() == ".bvh") && std::filesystem::is_regular_file(path, error);
}

Result<BvhFile> read_character_file(const std::filesystem::path& path) {
    if (!is_gltf_path(path)) return bvh_read_file(path);
    Result<GltfCharacter> character = gltf_read_file(path);
    if (!character) return character.error();
    return std::move(character->character);
}

Result<BvhFile> load_character(const std::filesystem::path& folder, const std::string& name) {
    const std::vector<CharacterEntry> entries = list_characters(folder);
    for (const CharacterEntry& entry : entries) {
        if (entry.name == name) return read_character_file(entry.file);
    }
    // A path to a character file of one's own.
    if (character_file_exists(name)) return read_character_file(name);
    std::string known;
    for (const CharacterEntry& entry : entries) known += (known.empty() ? "" : ", ") + entry.name;
    return make_error(ErrorCode::invalid, "unknown character '" + name + "' in " + folder.string() +
                                              (known.empty() ? " (no characters there)" : " (known: " + known + ")") +
                                              "; a path to a .bvh, .glb or .gltf file works too");
}

} // namespace kumite
