// The kumite executable as users and acceptance scripts call it: exit codes, messages, JSON keys.

#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

using kumite::test::run_command;

namespace {

std::string kumite_exe() { return (kumite::test::bin_dir() / "kumite").string(); }

std::filesystem::path write_text(const std::string& name, const std::string& text) {
    const std::filesystem::path path = kumite::test::make_temp_dir("cli") / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

const std::string k_small_bvh =
    "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    " JOINT Spine\n {\n  OFFSET 0 10 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n  End Site\n  {\n   OFFSET 0 5 0\n  }\n }\n}\n"
    "MOTION\nFrames: 2\nFrame Time: 0.04\n0 90 0 0 0 0 0 0 0\n0 90 0 90 0 0 0 0 0\n";

} // namespace

TEST_CASE("cli: --help and usage errors", "[cli]") {
    CHECK(run_command(kumite_exe() + " --help").status == 0);
    for (const char* command : {"inspect", "positions", "convert"}) {
        const auto help = run_command(kumite_exe() + " " + command + " --help");
        CHECK(help.status == 0);
        CHECK_THAT(help.out, Catch::Contains(std::string("usage: kumite ") + command));
    }
    const auto unknown_command = run_command(kumite_exe() + " frobnicate");
    CHECK(unknown_command.status == 2);
    CHECK_THAT(unknown_command.err, Catch::Contains("unknown command"));

    const std::string file = write_text("small.bvh", k_small_bvh).string();
    const auto unknown_flag = run_command(kumite_exe() + " inspect " + file + " --bogus");
    CHECK(unknown_flag.status == 2);
    CHECK_THAT(unknown_flag.err, Catch::Contains("unknown flag --bogus"));
    CHECK(std::count(unknown_flag.err.begin(), unknown_flag.err.end(), '\n') == 1);

    CHECK(run_command(kumite_exe() + " inspect " + file + " --unit furlong").status == 2);
    CHECK(run_command(kumite_exe() + " inspect").status == 2);
    CHECK(run_command(kumite_exe() + " positions " + file + " --frames 7").status == 2);
    CHECK(run_command(kumite_exe() + " positions " + file + " --frames 1,x").status == 2);
    CHECK(run_command(kumite_exe() + " positions " + file + " --all --frames 0").status == 2);

}

TEST_CASE("cli: inspect --json has the contract's keys", "[cli]") {
    const std::string file = write_text("small.bvh", k_small_bvh).string();
    const auto result = run_command(kumite_exe() + " inspect " + file + " --json --unit cm");
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out);
    for (const char* key : {"joints", "joint_names", "frames", "fps", "duration_s", "unit", "unit_scale_m", "height_m",
                            "rotation_orders", "body_map", "unmapped"}) {
        CHECK(document.contains(key));
    }
    CHECK(document["joints"] == 2);
    CHECK(document["frames"] == 2);
    CHECK(document["fps"].get<double>() == Approx(25.0));
    CHECK(document["duration_s"].get<double>() == Approx(0.04));
    CHECK(document["unit"] == "cm");
    CHECK(document["unit_scale_m"].get<double>() == Approx(0.01));
    CHECK(document["rotation_orders"] == nlohmann::json::array({"ZXY"}));
    CHECK(document["body_map"].is_object());
}

TEST_CASE("cli: a capture read with warnings says so on stderr and in inspect --json, --strict refuses it", "[cli]") {
    std::string text = k_small_bvh;
    text.replace(text.find("End Site"), 8, "End toe");                  // line 10
    text.replace(text.find("0 90 0 0 0 0 0 0 0\n"), 19, "0 90 0 0 0 0 0 0 0 "); // both frames on line 19
    const std::string file = write_text("tolerated.bvh", text).string();
    const auto result = run_command(kumite_exe() + " inspect " + file + " --json --unit cm");
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out);
    REQUIRE(document["warnings"].size() == 2);
    CHECK(document["warnings"][0].get<std::string>().find("tolerated.bvh:10:") != std::string::npos);
    CHECK(document["warnings"][1].get<std::string>().find("tolerated.bvh:19:") != std::string::npos);
    CHECK(document["frames"] == 2);
    CHECK(result.err.find("warning: ") != std::string::npos);
    const auto strict = run_command(kumite_exe() + " inspect " + file + " --strict");
    CHECK(strict.status == 1);
    CHECK(strict.err.find("tolerated.bvh:10:") != std::string::npos);
    const auto plain = run_command(kumite_exe() + " inspect " + write_text("small.bvh", k_small_bvh).string() + " --json --strict");
    CHECK(plain.status == 0);
    CHECK(nlohmann::json::parse(plain.out)["warnings"].empty());
}

TEST_CASE("cli: positions --json gives FK positions in metres", "[cli]") {
    const std::string file = write_text("small.bvh", k_small_bvh).string();
    const auto result = run_command(kumite_exe() + " positions " + file + " --frames 0,1 --unit cm --json");
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out);
    CHECK(document["joint_names"] == nlohmann::json::array({"Hips", "Spine"}));
    CHECK(document["frames"]["0"][1][1].get<double>() == Approx(1.0));
    CHECK(document["frames"]["1"][1][0].get<double>() == Approx(-0.1)); // Hips turned 90 deg about Z
    const auto all = run_command(kumite_exe() + " positions " + file + " --all --unit cm --json");
    CHECK(nlohmann::json::parse(all.out)["frames"].size() == 2);
}

TEST_CASE("cli: malformed files exit 1 with file:line", "[cli]") {
    std::string broken = k_small_bvh;
    broken.replace(broken.rfind("0 90 0 90"), 9, "0 90 0 zz");
    const std::string file = write_text("broken.bvh", broken).string();
    for (const char* command : {"inspect", "positions"}) {
        const auto result = run_command(kumite_exe() + " " + command + " " + file + " --json");
        CHECK(result.status == 1);
        CHECK(result.out.empty());
        CHECK_THAT(result.err, Catch::Contains(file + ":20:")); // the second frame line
    }
    const auto missing = run_command(kumite_exe() + " inspect /nonexistent/x.bvh");
    CHECK(missing.status == 1);
    CHECK_THAT(missing.err, Catch::Contains("/nonexistent/x.bvh"));
}

TEST_CASE("cli: convert round trip and atomic failure", "[cli]") {
    const std::filesystem::path file = write_text("small.bvh", k_small_bvh);
    const std::filesystem::path out = file.parent_path() / "out.bvh";
    REQUIRE(run_command(kumite_exe() + " convert " + file.string() + " " + out.string() + " --unit cm").status == 0);
    const auto before = run_command(kumite_exe() + " positions " + file.string() + " --all --unit cm --json");
    const auto after = run_command(kumite_exe() + " positions " + out.string() + " --all --unit cm --json");
    const nlohmann::json a = nlohmann::json::parse(before.out), b = nlohmann::json::parse(after.out);
    for (const auto& [frame, positions] : a["frames"].items()) {
        for (size_t joint = 0; joint < positions.size(); ++joint) {
            for (int axis = 0; axis < 3; ++axis) {
                CHECK(b["frames"][frame][joint][axis].get<double>() == Approx(positions[joint][axis].get<double>()).margin(1e-9));
            }
        }
    }
    const auto failed = run_command(kumite_exe() + " convert " + file.string() + " /nonexistent/dir/out.bvh");
    CHECK(failed.status == 1);
    CHECK_THAT(failed.err, Catch::Contains("/nonexistent/dir/out.bvh"));
}

TEST_CASE("cli: relative capture paths resolve under --mocap-root", "[cli]") {
    const std::filesystem::path file = write_text("rooted.bvh", k_small_bvh);
    const auto result = run_command("cd / && " + kumite_exe() + " inspect rooted.bvh --mocap-root " +
                                    file.parent_path().string() + " --json");
    CHECK(result.status == 0);
}

TEST_CASE("cli: characters --json lists the five shipped characters", "[cli]") {
    const auto result = run_command(kumite_exe() + " characters --json --characters-dir " +
                                    (kumite::test::source_dir() / "data/characters").string());
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out);
    REQUIRE(document["characters"].size() == 5);
    double shortest = 10.0, tallest = 0.0;
    for (const auto& character : document["characters"]) {
        for (const char* key : {"name", "file", "height_m", "joints"}) CHECK(character.contains(key));
        shortest = std::min(shortest, character["height_m"].get<double>());
        tallest = std::max(tallest, character["height_m"].get<double>());
    }
    CHECK(shortest == Approx(1.30).margin(0.05));
    CHECK(tallest == Approx(2.10).margin(0.05));
}

TEST_CASE("cli: retarget writes the character's BVH and the report", "[cli][corpus]") {
    const std::filesystem::path capture = kumite::test::mocap_root() / "bandai-namco-1/dataset-1_walk_normal_001.bvh";
    if (!std::filesystem::exists(capture)) return;
    const std::filesystem::path dir = kumite::test::make_temp_dir("retarget");
    const std::string characters = " --characters-dir " + (kumite::test::source_dir() / "data/characters").string();
    const auto result = run_command(kumite_exe() + " retarget " + capture.string() + " --character giant -o " +
                                    (dir / "giant.bvh").string() + " --report " + (dir / "giant.json").string() + characters);
    REQUIRE(result.status == 0);
    std::ifstream report_file(dir / "giant.json");
    const nlohmann::json report = nlohmann::json::parse(report_file);
    for (const char* key : {"frames", "bone_length_error_m", "foot_drift_m", "floor_penetration_m", "limb_extension_error"}) {
        CHECK(report.contains(key));
    }
    CHECK(report["encode_decode_us"].contains("median"));
    CHECK(report["encode_decode_us"].contains("p99"));
    CHECK(report["bone_length_error_m"].get<double>() < 1e-4);

    const auto inspected = run_command(kumite_exe() + " inspect " + (dir / "giant.bvh").string() + " --json");
    REQUIRE(inspected.status == 0);
    const nlohmann::json output = nlohmann::json::parse(inspected.out);
    CHECK(output["joint_names"][0] == "pelvis");
    CHECK(output["unit"] == "m");
    CHECK(output["frames"] == report["frames"]);

    CHECK(run_command(kumite_exe() + " retarget " + capture.string() + " --character nobody -o x.bvh" + characters).status == 2);
    CHECK(run_command(kumite_exe() + " retarget " + capture.string() + " --character kid" + characters).status == 2);
    const std::filesystem::path broken = write_text("broken.bvh", "HIERARCHY\nROOT x\n{\n");
    const auto bad = run_command(kumite_exe() + " retarget " + broken.string() + " --character kid -o " + (dir / "b.bvh").string() + characters);
    CHECK(bad.status == 1);
    CHECK_FALSE(std::filesystem::exists(dir / "b.bvh"));
}

TEST_CASE("cli: suggest --json lists strikes with the contract's keys", "[cli][corpus]") {
    const std::filesystem::path kick = kumite::test::mocap_root() / "bandai-namco-1/dataset-1_kick_normal_001.bvh";
    const std::filesystem::path punch = kumite::test::mocap_root() / "bandai-namco-1/dataset-1_punch_normal_002.bvh";
    if (!std::filesystem::exists(kick) || !std::filesystem::exists(punch)) return;
    const auto one = run_command(kumite_exe() + " suggest " + kick.string() + " --json");
    REQUIRE(one.status == 0);
    const nlohmann::json strikes = nlohmann::json::parse(one.out)["strikes"];
    REQUIRE(strikes.size() == 3);
    for (const char* key : {"semantics", "segment", "side", "hit_frame", "first", "last", "confidence"}) CHECK(strikes[0].contains(key));
    CHECK(strikes[0]["semantics"] == "kick");
    CHECK(strikes[0]["segment"] == "foot_r");
    CHECK(strikes[0]["side"] == "right");

    const auto two = run_command(kumite_exe() + " suggest " + kick.string() + " " + punch.string() + " --json");
    REQUIRE(two.status == 0);
    const nlohmann::json files = nlohmann::json::parse(two.out)["files"];
    REQUIRE(files.size() == 2);
    CHECK(files[1]["strikes"].size() == 5);

    const auto reach = run_command(kumite_exe() + " suggest " + punch.string() + " --segment hand_r --json");
    REQUIRE(reach.status == 0);
    const nlohmann::json reaches = nlohmann::json::parse(reach.out)["strikes"];
    CHECK(reaches.size() >= 5);
    if (!reaches.empty()) CHECK(reaches[0]["semantics"] == "reach");
    CHECK(run_command(kumite_exe() + " suggest " + punch.string() + " --segment elbow").status == 2);

    // Batch pre-annotation: every suggestion becomes a clip, with paths relative to the mocap root.
    const std::filesystem::path annotations = kumite::test::make_temp_dir("suggest") / "suggested.json";
    const auto written = run_command(kumite_exe() + " suggest bandai-namco-1/dataset-1_kick_normal_001.bvh --mocap-root " +
                                     kumite::test::mocap_root().string() + " --write-annotations " + annotations.string());
    REQUIRE(written.status == 0);
    std::ifstream annotation_file(annotations);
    const nlohmann::json document = nlohmann::json::parse(annotation_file);
    REQUIRE(document["clips"].size() == 3);
    CHECK(document["clips"][0]["source"] == "bandai-namco-1/dataset-1_kick_normal_001.bvh");
    CHECK(document["clips"][0]["hit_frame"] == 60);
    CHECK(document["clips"][0]["mirror"] == true);
}

namespace {

// Bakes the golden annotations once per test run.
std::filesystem::path baked_golden() {
    static const std::filesystem::path path = [] {
        const std::filesystem::path out = kumite::test::make_temp_dir("cli-bake") / "golden.kdb";
        const auto result = run_command(kumite_exe() + " bake " + (kumite::test::source_dir() / "data/annotations/golden.json").string() +
                                        " -o " + out.string() + " --clusters 4 --mocap-root " + kumite::test::mocap_root().string());
        INFO(result.out << result.err);
        REQUIRE(result.status == 0);
        return out;
    }();
    return path;
}

std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

TEST_CASE("cli: bake writes a database that db-info describes with the contract's keys", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::filesystem::path db = baked_golden();
    const auto info = run_command(kumite_exe() + " db-info " + db.string() + " --verify --json");
    REQUIRE(info.status == 0);
    const nlohmann::json document = nlohmann::json::parse(info.out);
    for (const char* key : {"format_version", "bytes", "hash", "clips", "poses", "clusters", "actors", "strikes", "open_us"}) {
        CHECK(document.contains(key));
    }
    CHECK(document["clips"] == 4);
    CHECK(document["clusters"] == 4);
    CHECK(document["strikes"]["kick"]["left"] == 1);
    CHECK(document["strikes"]["kick"]["right"] == 1);
    CHECK(document["strikes"]["punch"]["left"] == 1);
    CHECK(document["strikes"]["punch"]["right"] == 0);
    CHECK(document["bytes"] == std::filesystem::file_size(db));
    // The golden strikes are labelled: a front kick and a straight punch at middle height (the kick mirrored too).
    CHECK(document["kinds"]["kick"]["front"]["left"] == 1);
    CHECK(document["kinds"]["kick"]["front"]["right"] == 1);
    CHECK(document["kinds"]["punch"]["straight"]["left"] == 1);
    CHECK(document["heights"]["punch"]["middle"]["left"] == 1);
    CHECK(document["strikes_before_mirroring"] == 2);
    CHECK(document["labels"].size() == 3);
    const auto text = run_command(kumite_exe() + " db-info " + db.string());
    CHECK(text.status == 0);
    CHECK_THAT(text.out, Catch::Contains("4 clips") && Catch::Contains("kick front middle"));
}

TEST_CASE("cli: db-info refuses flipped, truncated, empty and foreign files with a reason", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::string bytes = file_bytes(baked_golden());
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-corrupt");
    auto refused = [&](const std::string& name, const std::string& content, const char* flags) {
        const std::filesystem::path path = folder / name;
        std::ofstream(path, std::ios::binary) << content;
        const auto result = run_command(kumite_exe() + " db-info " + path.string() + " " + flags);
        INFO(name << ": " << result.err);
        CHECK(result.status == 1);
        CHECK_THAT(result.err, Catch::Contains(path.string()));
        return result.err;
    };
    std::string flipped = bytes;
    flipped[bytes.size() / 2] = static_cast<char>(flipped[bytes.size() / 2] ^ 0x20);
    CHECK_THAT(refused("flipped.kdb", flipped, "--verify"), Catch::Contains("hash"));
    std::string flipped_header = bytes;
    flipped_header[2] = 'X';
    CHECK_THAT(refused("magic.kdb", flipped_header, ""), Catch::Contains("byte 0"));
    CHECK_THAT(refused("truncated.kdb", bytes.substr(0, bytes.size() - 100), ""), Catch::Contains("truncated"));
    CHECK_THAT(refused("empty.kdb", "", ""), Catch::Contains("empty"));
    CHECK_THAT(refused("foreign.kdb", k_small_bvh, ""), Catch::Contains("not a kumite database"));
}

TEST_CASE("cli: a per-pose value opening does not read is refused by --verify, on db-info and the runtime commands", "[cli]") {
    // The golden database with one feature value made NaN: the structure is intact, so opening accepts it.
    const std::filesystem::path golden = kumite::test::source_dir() / "data/golden/golden-v2.kdb";
    const auto info = run_command(kumite_exe() + " db-info " + golden.string() + " --json");
    REQUIRE(info.status == 0);
    const nlohmann::json summary = nlohmann::json::parse(info.out);
    CHECK(summary["values_verified"] == false);
    CHECK(summary["verify_us"].is_null());
    std::uint64_t features = 0;
    for (const auto& section : summary["sections"]) {
        if (section["tag"] == "FEAT") features = section["offset"].get<std::uint64_t>();
    }
    REQUIRE(features > 0);
    std::string bytes = file_bytes(golden);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + features + 5 * sizeof(float), &nan, sizeof nan);
    const std::filesystem::path corrupt = kumite::test::make_temp_dir("cli-verify") / "nan.kdb";
    std::ofstream(corrupt, std::ios::binary) << bytes;

    CHECK(run_command(kumite_exe() + " db-info " + corrupt.string()).status == 0); // opening reads no feature
    const auto verified = run_command(kumite_exe() + " db-info " + corrupt.string() + " --verify");
    CHECK(verified.status == 1);
    CHECK_THAT(verified.err, Catch::Contains(corrupt.string()) && Catch::Contains("FEAT 5") && Catch::Contains("not a finite number"));
    const auto query = run_command(kumite_exe() + " query " + corrupt.string() + " --character kid --target 0,1,0.5 --command punch --verify");
    CHECK(query.status == 1);
    CHECK_THAT(query.err, Catch::Contains("FEAT 5"));

    const auto good = run_command(kumite_exe() + " db-info " + golden.string() + " --verify --json");
    REQUIRE(good.status == 0);
    const nlohmann::json checked = nlohmann::json::parse(good.out);
    CHECK(checked["values_verified"] == true);
    CHECK(checked["hash_verified"] == true);
    CHECK(checked["verify_us"].get<double>() > 0.0);
    CHECK(checked["open_us"].get<double>() > 0.0);
}

TEST_CASE("cli: bake usage and input errors leave no file behind", "[cli]") {
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-bake-errors");
    const std::string out = (folder / "out.kdb").string();
    const std::string annotations = write_text("bad.json", R"({"version": 1, "clips": [{"name": "a"}]})").string();
    CHECK(run_command(kumite_exe() + " bake " + annotations).status == 2);                          // no -o
    CHECK(run_command(kumite_exe() + " bake " + annotations + " -o " + out + " --clusters 0").status == 2);
    CHECK(run_command(kumite_exe() + " bake " + annotations + " -o " + out + " --jobs many").status == 2);
    const auto bad = run_command(kumite_exe() + " bake " + annotations + " -o " + out);
    CHECK(bad.status == 1);
    CHECK_THAT(bad.err, Catch::Contains("bad.json: clip 0 (a): missing \"source\""));
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator{}) == 0);
}

TEST_CASE("cli: query answers with the contract's keys, for one target, a targets file and the exhaustive search", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::string db = baked_golden().string();
    const auto one = run_command(kumite_exe() + " query " + db + " --character giant --target 0.1,1.4,0.7 --command kick --side left --json");
    INFO(one.err);
    REQUIRE(one.status == 0);
    const nlohmann::json result = nlohmann::json::parse(one.out);
    for (const char* key : {"clip", "clip_index", "semantics", "side", "segment", "start_frame", "contact_frame", "time_to_contact_s",
                            "d_pose", "d_target", "score", "latency_us"}) {
        CHECK(result.contains(key));
    }
    CHECK(result["semantics"] == "kick");
    CHECK(result["side"] == "left");
    CHECK(result["segment"] == "foot_l");
    CHECK(result["contact_frame"].get<int>() >= result["start_frame"].get<int>());

    const std::filesystem::path targets = write_text("targets.csv", "# x,y,z\n0,1.2,0.6\n\n0.2, 1.0, 0.5\r\n-0.1,1.5,0.8\n");
    const auto many = run_command(kumite_exe() + " query " + db + " --character kid --targets " + targets.string() + " --command punch --json");
    REQUIRE(many.status == 0);
    const nlohmann::json list = nlohmann::json::parse(many.out);
    REQUIRE(list["results"].size() == 3);
    CHECK(list.contains("total_us"));
    const auto exhaustive = run_command(kumite_exe() + " query " + db + " --character kid --targets " + targets.string() +
                                        " --command punch --exhaustive --json");
    REQUIRE(exhaustive.status == 0);
    const nlohmann::json reference = nlohmann::json::parse(exhaustive.out);
    for (int i = 0; i < 3; ++i) CHECK(reference["results"][i]["score"] == list["results"][i]["score"]);
    const auto text = run_command(kumite_exe() + " query " + db + " --character kid --target 0,1.2,0.6 --command punch");
    CHECK(text.status == 0);
    CHECK_THAT(text.out, Catch::Contains("punch"));
}

TEST_CASE("cli: query refuses what it cannot answer, saying why", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::string db = baked_golden().string();
    const std::string base = kumite_exe() + " query " + db + " --character kid ";
    CHECK(run_command(base + "--command punch").status == 2);                                         // no target
    CHECK(run_command(base + "--target 0,1,1 --targets x.csv --command punch").status == 2);          // both
    CHECK(run_command(base + "--target 0,1 --command punch").status == 2);                            // two numbers
    CHECK(run_command(base + "--target 0,nan,1 --command punch").status == 2);
    CHECK(run_command(base + "--target 1e300,0,0 --command punch").status == 2);           // not metres
    CHECK(run_command(base + "--target 0,1,1 --command punch --side up").status == 2);
    CHECK(run_command(kumite_exe() + " query " + db + " --character nobody --target 0,1,1 --command punch").status == 2);
    const auto unknown = run_command(base + "--target 0,1,1 --command headbutt");
    CHECK(unknown.status == 1);
    CHECK_THAT(unknown.err, Catch::Contains("no 'headbutt' strikes") && Catch::Contains("punch"));
    const auto no_right_punch = run_command(base + "--target 0,1,1 --command punch --side right"); // the golden file has none
    CHECK(no_right_punch.status == 1);
    const auto no_hook = run_command(base + "--target 0,1,1 --command punch --kind hook");
    CHECK(no_hook.status == 1);
    CHECK_THAT(no_hook.err, Catch::Contains("punch hook") && Catch::Contains("holds no such strike"));
    CHECK(run_command(base + "--target 0,1,1 --command punch --kind roundhouse").status == 2); // not a punch's kind
    CHECK(run_command(base + "--target 0,1,1 --command punch --height knee").status == 2);
    const auto straight = run_command(base + "--target 0,1,0.6 --command punch --kind straight --height middle --json");
    REQUIRE(straight.status == 0);
    const nlohmann::json answer = nlohmann::json::parse(straight.out);
    CHECK(answer["kind"] == "straight");
    CHECK(answer["height"] == "middle");
    const std::filesystem::path bad = write_text("bad.csv", "0,1,1\n0,x,1\n");
    const auto bad_line = run_command(base + "--targets " + bad.string() + " --command punch");
    CHECK(bad_line.status == 1);
    CHECK_THAT(bad_line.err, Catch::Contains("bad.csv:2"));
    const std::filesystem::path corrupt = write_text("corrupt.kdb", "KUMITEDB but not really");
    CHECK(run_command(kumite_exe() + " query " + corrupt.string() + " --character kid --target 0,1,1 --command punch").status == 1);
}

TEST_CASE("cli: adapt writes a BVH on the character and a report with the contract's keys", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::string db = baked_golden().string();
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-adapt");
    const std::string bvh = (folder / "kick.bvh").string(), report = (folder / "kick.json").string();
    const std::string filmstrip = (folder / "kick.png").string();
    const auto result = run_command(kumite_exe() + " adapt " + db + " --character runner --target -0.1,0.9,0.6 --command kick --side right" +
                                    " --record " + bvh + " --report " + report + " --filmstrip " + filmstrip);
    INFO(result.err);
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(file_bytes(report));
    for (const char* key : {"effector", "contact_frame", "effector_at_contact", "target", "contact_error_m", "reachable",
                            "bone_length_error_m", "foot_drift_m", "support_foot_lifted", "frame_cost_us"}) {
        CHECK(document.contains(key));
    }
    CHECK(document["effector"] == "Foot_R");
    CHECK(document["reachable"] == true);
    CHECK(document["contact_error_m"].get<double>() < 0.01);
    CHECK(document["support_foot_lifted"] == false);
    CHECK(document["bone_length_error_m"].get<double>() < 1e-4);
    for (const char* key : {"median", "p99", "max"}) CHECK(document["frame_cost_us"].contains(key));
    // The strike lands at its annotated hit and stops there.
    for (const char* key : {"hit_frame", "overshoot_m", "effector_speed_at_contact_mps", "joint_limit_violations"}) CHECK(document.contains(key));
    CHECK(document["hit_frame"] == document["contact_frame"]);
    CHECK(document["overshoot_m"].get<double>() <= 0.03);
    CHECK(document["joint_limit_violations"] == 0);
    // The filmstrip: a PNG with two rows of frames (its IHDR holds width and height, big-endian).
    const std::string png = file_bytes(filmstrip);
    REQUIRE(png.size() > 24);
    CHECK(png.substr(1, 3) == "PNG");
    auto be32 = [&](std::size_t at) { return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
                                             (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3])); };
    CHECK(be32(16) > 1000); // width: several frames side by side
    CHECK(be32(20) > 400);  // height: side and front rows
    // A filmstrip that cannot be written fails with status 1 and says where.
    const auto unwritable = run_command(kumite_exe() + " adapt " + db + " --character runner --target -0.1,0.9,0.6 --command kick --record " + bvh +
                                        " --filmstrip " + (folder / "missing-folder" / "strip.png").string());
    CHECK(unwritable.status == 1);
    CHECK(unwritable.err.find("strip.png") != std::string::npos);
    // The BVH is the runner's skeleton, and its contact frame exists.
    const auto inspect = run_command(kumite_exe() + " inspect " + bvh + " --json");
    REQUIRE(inspect.status == 0);
    const nlohmann::json summary = nlohmann::json::parse(inspect.out);
    CHECK(summary["frames"].get<int>() > document["contact_frame"].get<int>());
    const auto runner = run_command(kumite_exe() + " inspect " + (kumite::test::source_dir() / "data/characters/runner.bvh").string() + " --json");
    CHECK(nlohmann::json::parse(runner.out)["joint_names"] == summary["joint_names"]);

    CHECK(run_command(kumite_exe() + " adapt " + db + " --character runner --command kick --record " + bvh).status == 2); // no target
    CHECK(run_command(kumite_exe() + " adapt " + db + " --character runner --target 0,1,1 --command kick").status == 2); // no record
}

TEST_CASE("cli: play query and adapt with no database bake the reference one once, or say how to get captures", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::filesystem::path cache = kumite::test::make_temp_dir("cli-default-db");
    const std::string environment = "KUMITE_CACHE_DIR=" + cache.string() + " KUMITE_MOCAP_ROOT=" + kumite::test::mocap_root().string() + " ";
    const auto first = run_command(environment + kumite_exe() + " play --headless --duration 2");
    INFO(first.err);
    REQUIRE(first.status == 0);
    CHECK(first.err.find("baked") != std::string::npos); // says it baked, once
    const auto again = run_command(environment + kumite_exe() + " query --character scout --target 0,1.2,0.6 --command punch --json");
    REQUIRE(again.status == 0);
    CHECK(again.err.find("baked") == std::string::npos); // the cached one
    CHECK(nlohmann::json::parse(again.out).contains("clip"));
    int cached = 0;
    for (const auto& entry : std::filesystem::directory_iterator(cache)) cached += entry.path().extension() == ".kdb";
    CHECK(cached == 1);
    // No captures: a message that says what to do, exit 1.
    const auto none = run_command("KUMITE_CACHE_DIR=" + cache.string() + " KUMITE_MOCAP_ROOT=" + (cache / "nothing").string() + " " + kumite_exe() +
                                  " adapt --character kid --target 0,1,0.5 --command kick --record " + (cache / "x.bvh").string());
    CHECK(none.status == 1);
    CHECK(none.err.find("fetch_mocap.sh") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(cache / "x.bvh"));
    // $KUMITE_DB names the database to use.
    const auto named = run_command("KUMITE_DB=" + (cache / "absent.kdb").string() + " " + kumite_exe() + " play --headless --duration 1");
    CHECK(named.status == 1);
    CHECK(named.err.find("absent.kdb") != std::string::npos);
}

TEST_CASE("cli: play runs a headless bout: report keys, events, a recording, the same events twice", "[cli][corpus]") {
    if (!std::filesystem::exists(kumite::test::mocap_root() / "bandai-namco-1")) return;
    const std::filesystem::path folder = kumite::test::make_temp_dir("cli-play");
    const std::string db = (folder / "ref.kdb").string();
    REQUIRE(run_command(kumite_exe() + " bake " + (kumite::test::source_dir() / "data/annotations/reference.json").string() + " -o " + db +
                        " --mocap-root " + kumite::test::mocap_root().string()).status == 0);
    const std::string script = (kumite::test::source_dir() / "data/bouts/demo.txt").string();
    auto play = [&](const std::string& name) {
        return run_command(kumite_exe() + " play " + db + " --character brawler --tracker simulate:still --commands script:" + script +
                           " --headless --duration 13 --seed 5 --events " + (folder / (name + ".jsonl")).string() + " --report " +
                           (folder / (name + ".json")).string() + " --record " + (folder / (name + ".bvh")).string());
    };
    const auto first = play("a");
    INFO(first.err);
    REQUIRE(first.status == 0);
    REQUIRE(play("b").status == 0);
    CHECK(file_bytes(folder / "a.jsonl") == file_bytes(folder / "b.jsonl"));
    const nlohmann::json report = nlohmann::json::parse(file_bytes(folder / "a.json"));
    for (const char* key : {"frames", "frame_time_us", "missed_frames", "orders", "strikes", "hits", "misses", "ignored_orders",
                            "tracker_packets", "tracker_rejected", "command_to_strike_frames", "order_outcomes"}) {
        CHECK(report.contains(key));
    }
    CHECK(report["frames"] == 780);
    CHECK(report["orders"] == 4); // the demo script's orders before 13 s (the last, at 11.5 s, lands by then)
    CHECK(report["strikes"] == report["orders"]);
    CHECK(report["command_to_strike_frames"]["max"].get<double>() <= 1.0);
    const auto inspect = run_command(kumite_exe() + " inspect " + (folder / "a.bvh").string() + " --json");
    REQUIRE(inspect.status == 0);
    CHECK(nlohmann::json::parse(inspect.out)["frames"] == 780);
    std::size_t strike_lines = 0;
    std::istringstream lines(file_bytes(folder / "a.jsonl"));
    for (std::string line; std::getline(lines, line);) {
        const nlohmann::json event = nlohmann::json::parse(line);
        CHECK(event.contains("t"));
        CHECK(event.contains("type"));
        strike_lines += event["type"] == "strike";
    }
    CHECK(strike_lines == report["strikes"].get<std::size_t>());

    // Without a display the viewer cannot open: the bout runs headless and says so.
    const auto no_display = run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + kumite_exe() + " play " + db + " --duration 2 --json");
    CHECK(no_display.status == 0);
    CHECK_THAT(no_display.err, Catch::Contains("no display"));
    CHECK(nlohmann::json::parse(no_display.out)["viewer"] == false);
    CHECK(run_command(kumite_exe() + " play " + db + " --headless --viewer-config /no/such/file.json").status == 1);
    CHECK(run_command(kumite_exe() + " play " + db + " --headless --tracker simulate:sleepy").status == 2);
    CHECK(run_command(kumite_exe() + " play " + db + " --headless --tracker dtrack:99999").status == 2);
    CHECK(run_command(kumite_exe() + " play " + db + " --headless --commands script:/no/such/file").status == 1);
}
