#include "kumite/formats/character_body.h"

#include "kumite/formats/character_catalog.h"

#include <cmath>

namespace kumite {
Result<SkinnedMesh> body_on_skeleton(const GltfCharacter& body, const Skeleton& skeleton, const std::string& body_source) {
    const Skeleton& body_skeleton = body.character.clip.skeleton;
    const std::vector<Eigen::Vector3d> body_world = rest_model_positions(body_skeleton);
    const std::vector<Eigen::Vector3d> world = rest_model_positions(skeleton);
    const double tolerance = 0.01 * std::max(body.character.height_m, 0.3);

    // Each body joint the mesh uses, found in the skeleton by name, at the same rest position.
    std::vector<int> used(body_skeleton.joint_count(), 0);
    for (const auto& joints : body.mesh.joints) {
        for (std::uint16_t j : joints) used[j] = 1;
    }
    std::vector<int> skeleton_joint(body_skeleton.joint_count(), -1);
    for (int j = 0; j < body_skeleton.joint_count(); ++j) {
        const std::optional<int> found = skeleton.find(body_skeleton.names[j]);
        if (found) skeleton_joint[j] = *found;
        if (!used[j]) continue;
        if (!found) return make_error(ErrorCode::invalid, body_source + ": the body is bound to joint '" + body_skeleton.names[j] + "', which the character's skeleton does not have");
        const double apart = (body_world[j] - world[*found]).norm();
        if (!(apart <= tolerance)) {
            return make_error(ErrorCode::invalid, body_source + ": joint '" + body_skeleton.names[j] + "' rests " + std::to_string(apart) +
                                                      " m from where the character's skeleton has it; the body must be modelled on the character's rest pose");
        }
    }
    SkinnedMesh mesh = body.mesh;
    mesh.bind_to_rest.assign(skeleton.joint_count(), Eigen::Matrix4f::Identity());
    for (int j = 0; j < body_skeleton.joint_count(); ++j) {
        if (skeleton_joint[j] >= 0) mesh.bind_to_rest[skeleton_joint[j]] = body.mesh.bind_to_rest[j];
    }
    for (auto& joints : mesh.joints) {
        for (std::uint16_t& j : joints) j = static_cast<std::uint16_t>(used[j] ? skeleton_joint[j] : 0);
    }
    return mesh;
}

Result<std::optional<SkinnedMesh>> load_character_body(const std::filesystem::path& folder, const std::string& name, const Skeleton& skeleton) {
    std::filesystem::path body_path;
    for (const CharacterEntry& entry : list_characters(folder)) {
        if (entry.name == name) body_path = entry.body;
    }
    if (body_path.empty() && is_gltf_path(name)) body_path = name;
    if (body_path.empty()) return std::optional<SkinnedMesh>{};
    Result<GltfCharacter> body = gltf_read_file(body_path);
    if (!body) return body.error();
    Result<SkinnedMesh> mesh = body_on_skeleton(*body, skeleton, body_path.string());
    if (!mesh) return mesh.error();
    return std::optional<SkinnedMesh>(std::move(*mesh));
}

} // namespace kumite
