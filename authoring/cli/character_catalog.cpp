#include "character_catalog.h"

#include "kumite/formats/bvh_writer.h"
#include "kumite/formats/character_body.h"
#include "kumite/formats/character_catalog.h"
#include "kumite/formats/gltf_writer.h"

#include <algorithm>
#include <cctype>

namespace kumite::cli {

FlagSpec characters_dir_flag() {
    return {"characters-dir", "DIR", "where the character files are (default data/characters)"};
}

std::filesystem::path characters_folder(const Arguments& arguments) {
    const std::optional<std::string> folder = arguments.value("characters-dir");
    return folder ? std::filesystem::path(*folder) : default_characters_dir();
}

std::optional<std::string> recording_path_problem(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".gltf") return std::nullopt;
    return path + ": kumite records glTF as binary .glb, not .gltf";
}

Result<void> write_recording(const std::string& path, const Clip& motion, const BvhFile& character, const std::filesystem::path& folder,
                             const std::string& character_name) {
    if (!is_gltf_path(path)) {
        // A pelvis moved under a Root joint needs position channels the character's own layout may not have.
        const BvhLayout layout = motion.has_local_translations() ? bvh_default_layout(motion) : character.layout;
        return bvh_write_file(path, motion, layout, character.unit);
    }
    if (std::optional<std::string> problem = recording_path_problem(path)) return make_error(ErrorCode::invalid, *problem);
    Result<std::optional<SkinnedMesh>> body = load_character_body(folder, character_name, motion.skeleton);
    if (!body) return body.error();
    return gltf_write_animation_file(path, motion, *body ? &**body : nullptr, character_name);
}

} // namespace kumite::cli
