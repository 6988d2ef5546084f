// kumite export: a table of the training store as CSV or JSON for analysis (pandas reads either as it is).

#include "commands.h"
#include "store_flags.h"
#include "store_export.h"

#include "kumite/formats/atomic_file.h"

#include <iostream>

namespace kumite::cli {

const CommandSpec& export_spec() {
    static const CommandSpec spec{
        "export",
        "[--store PATH] [--trainee NAME] --table sessions|attacks|user_strikes -o OUT.csv|OUT.json",
        "Writes a table of the training store (kumite train), of everyone or one trainee, in session order: sessions\n"
        "(with the trainee, the counts of attacks and user strikes, the settings, summary and drill text), attacks (the\n"
        "fighter's blows and the trainee's answers) or user_strikes (the trainee's own strikes), each row with its\n"
        "session_id and trainee. The format follows OUT's extension: CSV (a header row, RFC 4180 quoting, an empty field\n"
        "for a missing value) or JSON (a list of records, null for a missing value): pandas.read_csv and\n"
        "pandas.read_json read them as they are. OUT is replaced whole or not at all.",
        0, 0,
        {store_flag(),
         trainee_flag(),
         {"table", "sessions|attacks|user_strikes", "the table to write (required)"},
         {"output", "OUT.csv|OUT.json", "the file to write (required); its extension gives the format"}}};
    return spec;
}

int run_export(int argc, char** argv) {
    Arguments arguments;
    if (std::optional<int> status = parse_command_line(export_spec(), argc, argv, arguments)) return *status;
    const std::optional<std::string> table_name = arguments.value("table");
    if (!table_name) return usage_error(export_spec(), "--table sessions|attacks|user_strikes is required");
    const std::optional<training::StoreTable> table = training::store_table_named(*table_name);
    if (!table) return usage_error(export_spec(), "--table " + *table_name + ": not a table (sessions, attacks, user_strikes)");
    const std::optional<std::string> output = arguments.value("output");
    if (!output) return usage_error(export_spec(), "-o OUT.csv or -o OUT.json is required");
    const std::optional<training::ExportFormat> format = training::export_format_for(*output);
    if (!format) return usage_error(export_spec(), "-o " + *output + ": the format comes from the extension, .csv or .json");

    const std::filesystem::path store_path = store_path_of(arguments);
    const std::optional<std::string> trainee = arguments.value("trainee");
    Result<training::StoreReader> store = open_store_of(arguments);
    if (!store) return input_error(store.error().message);
    Result<training::StoreExport> exported = training::store_export(*store, *table, *format, trainee);
    if (!exported) return input_error(exported.error().message);
    if (Result<void> written = write_file_atomically(*output, exported->text); !written) return input_error(written.error().message);
    std::cout << "wrote " << *output << ": " << exported->rows << " row(s) of " << *table_name << (trainee ? " of " + *trainee : std::string()) << " from "
              << store_path.string() << "\n";
    return k_exit_ok;
}

} // namespace kumite::cli
