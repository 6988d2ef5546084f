#pragma once
// The reference database (data/annotations/reference.json) baked once per test executable, in memory; null when
// the captures are absent. Executables that include this link kumite_bake.

#include "bake.h"
#include "support/test_paths.h"

#include <catch2/catch.hpp>

#include <optional>

namespace kumite::test {

inline const MotionDatabaseContent* reference_database() {
    static const std::optional<MotionDatabaseContent> database = []() -> std::optional<MotionDatabaseContent> {
        if (!std::filesystem::exists(mocap_root() / "bandai-namco-1")) return std::nullopt;
        Result<RawAnnotations> annotations = annotations_read_file(source_dir() / "data/annotations/reference.json");
        REQUIRE(annotations.has_value());
        bake::BakeOptions options;
        options.mocap_root = mocap_root();
        Result<bake::BakeResult> baked = bake::bake_database(*annotations, "reference.json", options);
        REQUIRE(baked.has_value());
        return std::move(baked->database);
    }();
    return database ? &*database : nullptr;
}

} // namespace kumite::test
