// The export of the store's tables as CSV and JSON. Values keep their stored type: integers and reals as numbers
// (reals in their shortest form that reads back to the same double), text as text, NULL as a missing value.

#include "store_export.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <charconv>

namespace kumite::training {

namespace {

// The shortest text that reads back as the same double, and reads as a real: "180.0", not "180", so that a column
// of whole seconds stays a float column in pandas, as it is in the JSON.
void append_number(std::string& out, double value) {
    char digits[32];
    const std::to_chars_result written = std::to_chars(digits, digits + sizeof digits, value);
    out.append(digits, written.ptr);
    if (std::string_view(digits, static_cast<std::size_t>(written.ptr - digits)).find_first_of(".eni") == std::string_view::npos) out += ".0";
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
void append_csv_field(std::string& out, const StoreValue& value) {
    if (const auto* integer = std::get_if<std::int64_t>(&value)) {
        out += std::to_string(*integer);
    } else if (const auto* real = std::get_if<double>(&value)) {
        if (!std::isnan(*real)) append_number(out, *real);
    } else if (const auto* text = std::get_if<std::string_view>(&value)) {
        if (text->find_first_of(",\"\r\n") == std::string_view::npos) {
            out += *text;
            return;
        }
        out += '"';
        for (const char c : *text) {
            if (c == '"') out += '"';
            out += c;
        }
        out += '"';
    }
}

nlohmann::ordered_json json_value(const StoreValue& value) {
    if (const auto* integer = std::get_if<std::int64_t>(&value)) return *integer;
    if (const auto* real = std::get_if<double>(&value)) return std::isnan(*real) ? nlohmann::ordered_json() : nlohmann::ordered_json(*real);
    if (const auto* text = std::get_if<std::string_view>(&value)) return std::string(*text);
    return nullptr;
}

} // namespace

std::optional<ExportFormat> export_format_for(const std::filesystem::path& output) {
    std::string extension = output.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".csv") return ExportFormat::csv;
    if (extension == ".json") return ExportFormat::json;
    return std::nullopt;
}

std::optional<StoreTable> store_table_named(std::string_view name) {
    if (name == "sessions") return StoreTable::sessions;
    if (name == "attacks") return StoreTable::attacks;
    if (name == "user_strikes") return StoreTable::user_strikes;
    return std::nullopt;
}

Result<StoreExport> store_export(const StoreReader& reader, StoreTable table, ExportFormat format, const std::optional<std::string>& trainee) {
    StoreExport result;
    std::string& out = result.text;
    std::vector<std::string> columns;
    bool first_row = true;
    const auto on_columns = [&](const std::vector<std::string>& names) {
        columns = names;
        if (format == ExportFormat::json) {
            out += "[";
            return;
        }
        for (std::size_t c = 0; c < names.size(); ++c) {
            if (c > 0) out += ',';
            append_csv_field(out, std::string_view(names[c]));
        }
        out += "\r\n"; // RFC 4180's line end; pandas reads either
    };
    const auto on_row = [&](const std::vector<StoreValue>& values) {
        if (format == ExportFormat::json) {
            nlohmann::ordered_json record = nlohmann::ordered_json::object();
            for (std::size_t c = 0; c < values.size(); ++c) record[columns[c]] = json_value(values[c]);
            out += first_row ? "\n" : ",\n";
            out += record.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
        } else {
            for (std::size_t c = 0; c < values.size(); ++c) {
                if (c > 0) out += ',';
                append_csv_field(out, values[c]);
            }
            out += "\r\n";
        }
        first_row = false;
        ++result.rows;
    };
    if (Result<void> read = reader.read_table(table, trainee, on_columns, on_row); !read) return read.error();
    if (format == ExportFormat::json) out += first_row ? "]\n" : "\n]\n";
    return result;
}

} // namespace kumite::training
