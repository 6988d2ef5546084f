// A bout's characters, read from a folder and a path (bout_cast.h).

#include "kumite/runtime/bout_cast.h"

#include "kumite/formats/character_body.h"
#include "kumite/formats/gltf_reader.h"

#include <algorithm>

namespace kumite {

Result<BoutCast> load_bout_cast(const std::filesystem::path& folder, std::string wanted) {
    BoutCast cast;
    cast.entries = list_characters(folder);
    if (cast.entries.empty()) return make_error(ErrorCode::io, folder.string() + ": no characters");
    if (wanted.empty()) wanted = cast.entries[0].name;
    auto named = [&](const std::string& name) {
        return std::any_of(cast.entries.begin(), cast.entries.end(), [&](const CharacterEntry& entry) { return entry.name == name; });
    };
    // A path to a character file of one's own joins the shipped ones under its file's stem.
    if (!named(wanted)) {
        const std::filesystem::path path(wanted);
        if (character_file_exists(path)) {
            cast.entries.push_back({named(path.stem().string()) ? path.filename().string() : path.stem().string(), path,
                                    is_gltf_path(path) ? path : std::filesystem::path()});
            wanted = cast.entries.back().name;
        }
    }
    cast.start = -1;
    for (std::size_t i = 0; i < cast.entries.size(); ++i) {
        const CharacterEntry& entry = cast.entries[i];
        Result<BvhFile> file = read_character_file(entry.file);
        if (!file) return file.error();
        std::shared_ptr<const SkinnedMesh> body;
        if (!entry.body.empty()) {
            Result<std::optional<SkinnedMesh>> loaded = load_character_body(folder, entry.body.string(), file->clip.skeleton);
            if (!loaded) return loaded.error();
            if (*loaded) body = std::make_shared<const SkinnedMesh>(std::move(**loaded));
        }
        cast.characters.push_back({entry.name, std::move(*file), std::move(body)});
        if (entry.name == wanted) cast.start = static_cast<int>(i);
    }
    if (cast.start < 0) return make_error(ErrorCode::invalid, "unknown character '" + wanted + "' (see kumite characters)");
    return cast;
}

} // namespace kumite
