// `kumite inspect` on characters whose body came from somewhere other than names: it says, part by part, whether
// names, the skeleton's structure, a VRM bone map or a .bodymap.json found it, and what was done to the rig.

#include "support/glb_edit.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using kumite::test::Glb;
using kumite::test::run_command;

namespace {

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }

nlohmann::json inspect(const std::filesystem::path& file) {
    const auto result = run_command(kumite_exe() + " inspect " + file.string() + " --json");
    INFO(result.err);
    REQUIRE(result.status == 0);
    return nlohmann::json::parse(result.out);
}

} // namespace

TEST_CASE("cli: inspect says where each body part came from: names, structure, a VRM map or a .bodymap.json", "[cli]") {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "kumite_cli_inspect_rig";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::vector<std::uint8_t> bytes = kumite::test::read_bytes(kumite::test::source_dir() / "data/characters/brawler.glb");

    const nlohmann::json named = inspect(kumite::test::source_dir() / "data/characters/brawler.glb");
    for (const auto& [part, source] : named["body_map_sources"].items()) CHECK(source == "name");

    // Numbered names no scheme knows: the structure finds every part, with its confidence.
    Glb numbered(bytes);
    for (std::size_t n = 0; n < numbered.json["nodes"].size(); ++n) numbered.json["nodes"][n]["name"] = "joint_" + std::to_string(n);
    numbered.write(folder / "numbered.glb");
    const nlohmann::json structure = inspect(folder / "numbered.glb");
    CHECK(structure["body_map"].size() == named["body_map"].size());
    for (const auto& [part, source] : structure["body_map_sources"].items()) CHECK(source == "structure");
    CHECK(structure["body_map_structure_confidence"].get<double>() > 0.9);

    // The same file with a sidecar naming the head: that part from the file, the rest from structure.
    const std::string head = structure["body_map"]["head"];
    std::ofstream(folder / "numbered.bodymap.json") << nlohmann::json{{"body_map", {{"head", head}}}}.dump();
    const nlohmann::json sidecar = inspect(folder / "numbered.glb");
    CHECK(sidecar["body_map_sources"]["head"] == "file");
    CHECK(sidecar["body_map_sources"]["hand_l"] == "structure");

    // A VRM 1.0 avatar: its bone map names the parts.
    Glb avatar(bytes);
    nlohmann::json bones = nlohmann::json::object();
    bones["hips"] = {{"node", avatar.node_named("mixamorig:Hips")}};
    bones["head"] = {{"node", avatar.node_named("mixamorig:Head")}};
    bones["rightHand"] = {{"node", avatar.node_named("mixamorig:RightHand")}};
    avatar.json["extensions"]["VRMC_vrm"] = {{"specVersion", "1.0"}, {"humanoid", {{"humanBones", bones}}}};
    avatar.write(folder / "avatar.vrm");
    const nlohmann::json vrm = inspect(folder / "avatar.vrm");
    CHECK(vrm["body_map_sources"]["pelvis"] == "vrm");
    CHECK(vrm["body_map_sources"]["hand_r"] == "vrm");
    CHECK(vrm["body_map_sources"]["hand_l"] == "name");

    // A rig with an IK target root: taken, with the warning in the JSON.
    Glb rig(bytes);
    rig.add_joints({rig.add_node("hand_IK_target.L", -1, rig.world(rig.node_named("mixamorig:LeftHand")))});
    rig.write(folder / "rig.glb");
    const nlohmann::json warned = inspect(folder / "rig.glb");
    REQUIRE(warned["warnings"].size() == 1);
    CHECK_THAT(warned["warnings"][0].get<std::string>(), Catch::Contains("hand_IK_target.L") && Catch::Contains("left out"));
    std::filesystem::remove_all(folder);
}
