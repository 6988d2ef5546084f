#include "kumite/formats/body_map_file.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace kumite {

Result<BodyMap> body_map_apply_override(const BodyMap& body_map, const Skeleton& skeleton, std::string_view text,
                                        std::string_view source_name) {
    const std::string source(source_name);
    const nlohmann::json document = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded()) return make_error(ErrorCode::parse, source + ": not valid JSON");
    const nlohmann::json& entries = document.contains("body_map") ? document["body_map"] : document;
    if (!entries.is_object()) {
        return make_error(ErrorCode::invalid, source + ": expected an object of part -> joint name under \"body_map\"");
    }
    BodyMap result = body_map;
    for (const auto& [part_name, joint_name] : entries.items()) {
        const std::optional<BodyPart> part = body_part_from_name(part_name);
        if (!part) {
            return make_error(ErrorCode::invalid, source + ": unknown body part \"" + part_name +
                                                      "\" (parts are pelvis, spine, chest, neck, head, clavicle_l, "
                                                      "upper_arm_l, forearm_l, hand_l, thigh_l, shin_l, foot_l, toe_l and the _r twins)");
        }
        if (joint_name.is_null()) {
            result.set(*part, -1, BodyMapSource::none);
            continue;
        }
        if (!joint_name.is_string()) {
            return make_error(ErrorCode::invalid, source + ": part \"" + part_name + "\" must map to a joint name or null");
        }
        const std::optional<int> joint = skeleton.find(joint_name.get<std::string>());
        if (!joint) {
            return make_error(ErrorCode::invalid, source + ": part \"" + part_name + "\" names joint \"" +
                                                      joint_name.get<std::string>() + "\", which the skeleton does not have");
        }
        result.set(*part, *joint, BodyMapSource::file);
    }
    return result;
}

Result<BodyMap> body_map_apply_override_file(const BodyMap& body_map, const Skeleton& skeleton,
                                             const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    if (!stream) return make_error(ErrorCode::io, path.string() + ": cannot open body map file");
    std::ostringstream text;
    text << stream.rdbuf();
    return body_map_apply_override(body_map, skeleton, text.str(), path.string());
}

std::filesystem::path body_map_sidecar_path(const std::filesystem::path& capture_path) {
    std::filesystem::path sidecar = capture_path;
    sidecar.replace_extension(".bodymap.json");
    return sidecar;
}

} // namespace kumite
