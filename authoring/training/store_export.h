#pragma once
// The export of the training store's tables for analysis: CSV or JSON that pandas reads as they are
// (pandas.read_csv, pandas.read_json), of the whole store or of one trainee.

#include "training_store.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace kumite::training {

enum class ExportFormat { csv, json };

// The format an output file's extension names (.csv, .json, in any case); none for another extension.
std::optional<ExportFormat> export_format_for(const std::filesystem::path& output);
// The table called `name` (sessions, attacks, user_strikes); none for another name.
std::optional<StoreTable> store_table_named(std::string_view name);

// `table` (of `trainee`'s sessions when given) as CSV: a header row of the column names, then one row per record,
// fields quoted as RFC 4180 says (a comma, quote or line break inside), a missing value (NULL, NaN) as an empty
// field; or as JSON: one list of records keyed by column name, a missing value as null. Columns: StoreReader::
// read_table's.
struct StoreExport {
    std::string text;
    std::size_t rows = 0;
};
Result<StoreExport> store_export(const StoreReader& reader, StoreTable table, ExportFormat format, const std::optional<std::string>& trainee);

} // namespace kumite::training
