// kumite characters: the characters shipped in data/characters, with their heights and joint counts.

#include "capture_loading.h"
#include "character_catalog.h"
#include "commands.h"

#include "kumite/formats/gltf_reader.h"

#include <iomanip>
#include <iostream>

namespace kumite::cli {

const CommandSpec& characters_spec() {
    static const CommandSpec spec{
        "characters", "[--json]",
        "Lists the characters in data/characters: name, file, standing height, joint count and body (a skinned\n"
        "glTF mesh: NAME.glb beside NAME.bvh, or a .glb/.gltf character of its own).", 0, 0,
        {characters_dir_flag(), json_flag()}};
    return spec;
}

int run_characters(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(characters_spec(), argc, argv, arguments)) return *status;
    const std::filesystem::path folder = arguments.value("characters-dir").value_or(default_characters_dir().string());
    nlohmann::json list = nlohmann::json::array();
    for (const CharacterEntry& entry : list_characters(folder)) {
        Result<BvhFile> file = read_character_file(entry.file);
        if (!file) return input_error(file.error().message);
        list.push_back({{"name", entry.name}, {"file", entry.file.string()}, {"height_m", file->height_m},
                        {"joints", file->clip.skeleton.joint_count()}, {"unit", file->unit.name},
                        {"format", is_gltf_path(entry.file) ? "gltf" : "bvh"}, {"body", entry.body.empty() ? nlohmann::json(nullptr) : nlohmann::json(entry.body.string())}});
    }
    if (arguments.has("json")) {
        print_json({{"characters", list}});
        return k_exit_ok;
    }
    if (list.empty()) std::cout << "no characters in " << folder.string() << "\n";
    for (const auto& character : list) {
        std::cout << std::left << std::setw(10) << character["name"].get<std::string>() << std::right << std::fixed
                  << std::setprecision(2) << character["height_m"].get<double>() << " m  " << std::setw(3)
                  << character["joints"].get<int>() << " joints  " << character["file"].get<std::string>()
                  << (character["body"].is_null() ? "" : "  body " + character["body"].get<std::string>()) << "\n";
    }
    return k_exit_ok;
}

} // namespace kumite::cli
