#include "kumite/formats/capture_file.h"

#include "kumite/formats/gltf_reader.h"

#include "kumite/formats/body_map_file.h"

namespace kumite {

Result<BvhFile> capture_read_file(const std::filesystem::path& path, const BvhReadOptions& options,
                                  const std::optional<std::filesystem::path>& body_map_override) {
    Result<BvhFile> file = make_error(ErrorCode::invalid, "");
    if (is_gltf_path(path)) {
        Result<GltfCharacter> character = gltf_read_file(path); // a character's rest pose, one frame
        if (!character) return character.error();
        file = std::move(character->character);
    } else {
        file = bvh_read_file(path, options);
    }
    if (!file) return file;
    std::error_code error;
    std::optional<std::filesystem::path> override_path = body_map_override;
    if (!override_path && std::filesystem::exists(body_map_sidecar_path(path), error)) override_path = body_map_sidecar_path(path);
    if (override_path) {
        Result<BodyMap> map = body_map_apply_override_file(file->body_map, file->clip.skeleton, *override_path);
        if (!map) return map.error();
        file->body_map = *map;
    }
    return file;
}

} // namespace kumite
