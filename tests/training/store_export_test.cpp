// The store's export (authoring/training/store_export.h): CSV parsed back by an RFC 4180 reader and JSON by
// nlohmann give the rows written, text with commas, quotes and line breaks intact, a missing value as an empty
// field or null, one trainee's rows only when asked, and a header (or an empty list) when there is no row.

#include "store_export.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace kumite::training;
using kumite::Result;
namespace fs = std::filesystem;

namespace {

// RFC 4180: records of fields, quoted fields may hold commas, doubled quotes and line breaks.
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
    std::vector<std::vector<std::string>> records(1, std::vector<std::string>(1));
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        std::string& field = records.back().back();
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += text[++i];
            else if (c == '"') quoted = false;
            else field += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            records.back().emplace_back();
        } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;
            records.emplace_back(1);
        } else {
            field += c;
        }
    }
    if (records.back().size() == 1 && records.back()[0].empty()) records.pop_back(); // after the last line end
    return records;
}

// Two trainees, three sessions; ann's first session's attacks carry text that needs quoting and a missing response.
fs::path make_store() {
    const fs::path store = kumite::test::make_temp_dir("store-export") / "training.sqlite";
    const char* trainees[] = {"ann", "bob", "ann"};
    for (int s = 0; s < 3; ++s) {
        SessionStart start;
        start.trainee = trainees[s];
        start.drill = "drill, \"quoted\"";
        start.drill_text = "line one\nline two, with a comma\n";
        start.settings_json = R"({"speed":1.5})";
        start.started_utc = "2026-12-0" + std::to_string(s + 1) + "T10:00:00Z";
        auto writer = SessionWriter::open(store, start);
        REQUIRE(writer);
        for (int i = 0; i < 4 + s; ++i) {
            AttackRow row;
            row.seq = i;
            row.t_s = 0.1 * i;
            row.part_name = i == 1 ? "warm-up, \"slow\"\nthen fast" : "warm-up";
            row.command = "punch";
            row.response_time_s = i == 2 ? k_no_value : 0.25 + i;
            row.counter_landed = -1;
            (*writer)->add(row);
        }
        UserStrikeRow strike;
        strike.hand = "left";
        (*writer)->add(strike);
        if (s < 2) REQUIRE((*writer)->finish(30.0 * (s + 1), R"({"score":3})"));
    }
    return store;
}

std::string exported(const fs::path& store, StoreTable table, ExportFormat format, const std::optional<std::string>& trainee = std::nullopt) {
    auto reader = StoreReader::open(store);
    REQUIRE(reader);
    Result<StoreExport> written = store_export(*reader, table, format, trainee);
    REQUIRE(written);
    return written->text;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
    const auto found = std::find(header.begin(), header.end(), name);
    REQUIRE(found != header.end());
    return static_cast<std::size_t>(found - header.begin());
}

} // namespace

TEST_CASE("store export: attacks as CSV parse back with quoting and missing values", "[training]") {
    const fs::path store = make_store();
    const auto records = parse_csv(exported(store, StoreTable::attacks, ExportFormat::csv));
    REQUIRE(records.size() == 1 + 4 + 5 + 6);
    const std::vector<std::string>& header = records[0];
    CHECK(header[0] == "session_id");
    CHECK(header[1] == "trainee");
    for (const auto& record : records) CHECK(record.size() == header.size());
    const std::size_t part_name = column(header, "part_name"), response_time = column(header, "response_time_s");
    CHECK(records[2][part_name] == "warm-up, \"slow\"\nthen fast");
    CHECK(records[3][response_time].empty()); // NaN: an empty field
    CHECK(std::stod(records[4][response_time]) == 3.25);
    CHECK(records[1][column(header, "t_s")] == "0.0"); // a real, so pandas reads the column as floats
    CHECK(records[2][column(header, "t_s")] == "0.1"); // the shortest text that reads back as the double
    CHECK(records[1][column(header, "trainee")] == "ann");
    CHECK(records[5][column(header, "trainee")] == "bob");

    const auto of_bob = parse_csv(exported(store, StoreTable::attacks, ExportFormat::csv, std::string("bob")));
    CHECK(of_bob.size() == 1 + 5);
}

TEST_CASE("store export: sessions and user strikes as JSON records", "[training]") {
    const fs::path store = make_store();
    const nlohmann::json sessions = nlohmann::json::parse(exported(store, StoreTable::sessions, ExportFormat::json));
    REQUIRE(sessions.is_array());
    REQUIRE(sessions.size() == 3);
    CHECK(sessions[0]["trainee"] == "ann");
    CHECK(sessions[0]["drill"] == "drill, \"quoted\"");
    CHECK(sessions[0]["drill_text"] == "line one\nline two, with a comma\n");
    CHECK(sessions[0]["attacks"] == 4);
    CHECK(sessions[0]["user_strikes"] == 1);
    CHECK(sessions[1]["duration_s"] == 60.0);
    CHECK(sessions[1]["complete"] == 1);
    CHECK(sessions[2]["complete"] == 0);
    CHECK(sessions[2]["summary_json"] == "");

    const nlohmann::json attacks = nlohmann::json::parse(exported(store, StoreTable::attacks, ExportFormat::json, std::string("ann")));
    REQUIRE(attacks.size() == 4 + 6);
    CHECK(attacks[2]["response_time_s"].is_null());
    CHECK(attacks[1]["part_name"] == "warm-up, \"slow\"\nthen fast");
    CHECK(attacks[9]["session_id"] == sessions[2]["session_id"]);

    const nlohmann::json strikes = nlohmann::json::parse(exported(store, StoreTable::user_strikes, ExportFormat::json));
    REQUIRE(strikes.size() == 3);
    CHECK(strikes[0]["hand"] == "left");
    CHECK(strikes[0]["peak_speed_mps"].is_null());
}

TEST_CASE("store export: no rows give a header or an empty list", "[training]") {
    const fs::path store = make_store();
    const auto records = parse_csv(exported(store, StoreTable::user_strikes, ExportFormat::csv, std::string("nobody")));
    REQUIRE(records.size() == 1);
    CHECK(records[0][0] == "session_id");
    CHECK(nlohmann::json::parse(exported(store, StoreTable::sessions, ExportFormat::json, std::string("nobody"))) == nlohmann::json::array());
}

TEST_CASE("store export: formats and tables by name", "[training]") {
    CHECK(export_format_for("out.CSV") == ExportFormat::csv);
    CHECK(export_format_for("a/b.json") == ExportFormat::json);
    CHECK_FALSE(export_format_for("out.txt"));
    CHECK(store_table_named("user_strikes") == StoreTable::user_strikes);
    CHECK_FALSE(store_table_named("strikes"));
}
