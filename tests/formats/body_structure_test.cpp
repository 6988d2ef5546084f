// The body found by structure alone (detect_body_map_by_structure) finds what the names find: on every shipped
// character, the shared third-party ones, and captures of every shared source, with their names stripped.

#include "kumite/core/body_map.h"
#include "kumite/formats/bvh_reader.h"
#include "kumite/formats/capture_file.h"
#include "kumite/formats/character_catalog.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <random>

using namespace kumite;

namespace {

// The parts a strike needs (clavicles, spine, neck and toes vary between schemes in where they sit).
constexpr BodyPart k_compared[] = {BodyPart::pelvis, BodyPart::head, BodyPart::upper_arm_l, BodyPart::forearm_l, BodyPart::hand_l,
                                   BodyPart::upper_arm_r, BodyPart::forearm_r, BodyPart::hand_r, BodyPart::thigh_l, BodyPart::shin_l,
                                   BodyPart::foot_l, BodyPart::thigh_r, BodyPart::shin_r, BodyPart::foot_r};

Skeleton stripped(Skeleton skeleton) {
    for (int j = 0; j < skeleton.joint_count(); ++j) skeleton.names[std::size_t(j)] = "joint_" + std::to_string(j * 7919 % 1000);
    return skeleton;
}

// Differences between the named map and the structural one on the compared parts, as text; parts the structure
// did not find count only with `missing_counts`.
std::string differences(const Skeleton& skeleton, const BodyMap& named, bool missing_counts = true) {
    const BodyMap found = detect_body_map_by_structure(stripped(skeleton));
    std::string text;
    for (BodyPart part : k_compared) {
        if (named.joint(part) == found.joint(part) || (!missing_counts && found.joint(part) < 0)) continue;
        auto name = [&](int j) { return j >= 0 ? skeleton.names[std::size_t(j)] : std::string("-"); };
        text += std::string(body_part_name(part)) + ": names " + name(named.joint(part)) + ", structure " + name(found.joint(part)) + "; ";
    }
    return text;
}

} // namespace

TEST_CASE("body structure: the shipped and shared characters, names stripped, give the parts their names give", "[formats]") {
    std::vector<std::filesystem::path> files;
    for (const CharacterEntry& entry : list_characters(kumite::test::source_dir() / "data/characters")) files.push_back(entry.file);
    const std::filesystem::path shared = kumite::test::source_dir() / "../shared/characters";
    if (std::filesystem::exists(shared)) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(shared)) {
            const std::string extension = entry.path().extension().string();
            if (extension == ".glb" || extension == ".gltf") files.push_back(entry.path());
        }
    }
    int compared = 0, found = 0;
    for (const std::filesystem::path& file : files) {
        Result<BvhFile> character = read_character_file(file);
        if (!character) continue; // characters kumite cannot read yet (formats not supported)
        INFO(file.string());
        // Never a wrong part: each is the named one, or (a rest pose that is not standing) none is found.
        CHECK(differences(character->clip.skeleton, character->body_map, false) == "");
        found += differences(character->clip.skeleton, character->body_map).empty();
        ++compared;
    }
    CHECK(compared >= 8);
    CHECK(found == compared);
}

namespace {

// Every offset below `top` (its subtree, not its own offset) turned by `turn`.
void turn_below(Skeleton& skeleton, int top, const Eigen::Matrix3d& turn) {
    for (int j = top + 1; j < skeleton.joint_count(); ++j) {
        if (skeleton.is_ancestor(top, j) && j != top) skeleton.rest_offsets[std::size_t(j)] = turn * skeleton.rest_offsets[std::size_t(j)];
    }
}

void scale_below(Skeleton& skeleton, int top, double factor) {
    for (int j = top + 1; j < skeleton.joint_count(); ++j) {
        if (skeleton.is_ancestor(top, j)) skeleton.rest_offsets[std::size_t(j)] *= factor;
    }
}

// The joints in another order, parents still first: new_of[old] is each joint's new index.
Skeleton shuffled(const Skeleton& skeleton, std::vector<int>& new_of, std::uint32_t seed) {
    std::mt19937 random(seed);
    const int n = skeleton.joint_count();
    new_of.assign(std::size_t(n), -1);
    std::vector<int> order = {0};
    new_of[0] = 0;
    std::vector<int> ready;
    auto open_children = [&](int j) {
        for (int c = 0; c < n; ++c) {
            if (skeleton.parents[std::size_t(c)] == j) ready.push_back(c);
        }
    };
    open_children(0);
    while (!ready.empty()) {
        const std::size_t pick = random() % ready.size();
        const int j = ready[pick];
        ready.erase(ready.begin() + std::ptrdiff_t(pick));
        new_of[std::size_t(j)] = int(order.size());
        order.push_back(j);
        open_children(j);
    }
    Skeleton out;
    for (int old : order) {
        out.names.push_back(skeleton.names[std::size_t(old)]);
        const int parent = skeleton.parents[std::size_t(old)];
        out.parents.push_back(parent < 0 ? -1 : new_of[std::size_t(parent)]);
        out.rest_offsets.push_back(skeleton.rest_offsets[std::size_t(old)]);
    }
    return out;
}

} // namespace

TEST_CASE("body structure: rigs made from the shipped ones: shuffled, A-pose, other proportions, facing away", "[formats]") {
    int variants = 0;
    for (const CharacterEntry& entry : list_characters(kumite::test::source_dir() / "data/characters")) {
        Result<BvhFile> character = read_character_file(entry.file);
        REQUIRE(character.has_value());
        const Skeleton& original = character->clip.skeleton;
        const BodyMap& named = character->body_map;
        INFO(entry.name);
        auto expect_parts = [&](const Skeleton& variant, const std::vector<int>& new_of, const char* what) {
            INFO(what);
            const BodyMap found = detect_body_map_by_structure(stripped(variant));
            for (BodyPart part : k_compared) {
                INFO(body_part_name(part));
                CHECK(found.joint(part) == new_of[std::size_t(named.joint(part))]);
            }
            ++variants;
        };
        std::vector<int> same(std::size_t(original.joint_count()));
        for (int j = 0; j < original.joint_count(); ++j) same[std::size_t(j)] = j;

        std::vector<int> new_of;
        for (std::uint32_t seed : {1u, 2u, 3u}) {
            const Skeleton mixed = shuffled(original, new_of, seed);
            expect_parts(mixed, new_of, "shuffled");
        }
        Skeleton a_pose = original; // arms 40 degrees down from the T (the characters face +Z: left is +X)
        turn_below(a_pose, named.joint(BodyPart::upper_arm_l), Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix());
        turn_below(a_pose, named.joint(BodyPart::upper_arm_r), Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix());
        expect_parts(a_pose, same, "A-pose");
        Skeleton proportions = original; // long legs, short arms
        scale_below(proportions, named.joint(BodyPart::thigh_l), 1.3);
        scale_below(proportions, named.joint(BodyPart::thigh_r), 1.3);
        scale_below(proportions, named.joint(BodyPart::upper_arm_l), 0.8);
        scale_below(proportions, named.joint(BodyPart::upper_arm_r), 0.8);
        expect_parts(proportions, same, "long legs, short arms");
        Skeleton away = original; // facing -Z: left and right from the facing, not from +X
        for (Eigen::Vector3d& offset : away.rest_offsets) offset = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY()) * offset;
        expect_parts(away, same, "facing -Z");
    }
    CHECK(variants == 5 * 6);
}

TEST_CASE("body structure: what is not a standing humanoid gives no map, never a crash", "[formats]") {
    Skeleton chain; // a 200-joint snake lying on the floor
    for (int j = 0; j < 200; ++j) {
        chain.names.push_back("j" + std::to_string(j));
        chain.parents.push_back(j - 1);
        chain.rest_offsets.push_back(j == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.05, 0.0, 0.0));
    }
    CHECK(detect_body_map_by_structure(chain).mapped_count() == 0);
    Skeleton star; // a root with 1000 children, zero-length bones
    star.names.push_back("root");
    star.parents.push_back(-1);
    star.rest_offsets.push_back(Eigen::Vector3d::Zero());
    for (int j = 1; j <= 1000; ++j) {
        star.names.push_back("s" + std::to_string(j));
        star.parents.push_back(0);
        star.rest_offsets.push_back(j % 2 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(std::sin(j), std::cos(j), 0.0));
    }
    CHECK(detect_body_map_by_structure(star).mapped_count() == 0);
    Skeleton flat = chain; // everything at one point
    for (Eigen::Vector3d& offset : flat.rest_offsets) offset.setZero();
    CHECK(detect_body_map_by_structure(flat).mapped_count() == 0);
}
