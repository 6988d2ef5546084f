// kumite: the command line of the kumite toolkit. See ../../../shared/docs/CLI.md for the contract.

#include "commands.h"

#include <array>
#include <cstring>
#include <iostream>

namespace {

using kumite::cli::Command;

constexpr std::array<Command, 16> k_commands = {{
    {kumite::cli::inspect_spec, kumite::cli::run_inspect},
    {kumite::cli::positions_spec, kumite::cli::run_positions},
    {kumite::cli::convert_spec, kumite::cli::run_convert},
    {kumite::cli::characters_spec, kumite::cli::run_characters},
    {kumite::cli::retarget_spec, kumite::cli::run_retarget},
    {kumite::cli::suggest_spec, kumite::cli::run_suggest},
    {kumite::cli::bake_spec, kumite::cli::run_bake},
    {kumite::cli::db_info_spec, kumite::cli::run_db_info},
    {kumite::cli::query_spec, kumite::cli::run_query},
    {kumite::cli::adapt_spec, kumite::cli::run_adapt},
    {kumite::cli::play_spec, kumite::cli::run_play},
    {kumite::cli::report_spec, kumite::cli::run_report},
    {kumite::cli::train_spec, kumite::cli::run_train},
    {kumite::cli::sessions_spec, kumite::cli::run_sessions},
    {kumite::cli::progress_spec, kumite::cli::run_progress},
    {kumite::cli::export_spec, kumite::cli::run_export},
}};

void print_overview(std::ostream& out) {
    out << "usage: kumite COMMAND [ARGS...]\n\ncommands:\n";
    for (const Command& command : k_commands) {
        const kumite::cli::CommandSpec& spec = command.spec();
        std::string name = "  " + spec.name;
        name.resize(14, ' ');
        out << name << spec.synopsis << "\n";
    }
    out << "\n'kumite COMMAND --help' describes one command.\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        print_overview(std::cerr);
        return kumite::cli::k_exit_usage;
    }
    const std::string name = argv[1];
    if (name == "--help" || name == "-h" || name == "help") {
        print_overview(std::cout);
        return kumite::cli::k_exit_ok;
    }
    if (name == "--version") {
        std::cout << "kumite 0.1.0\n";
        return kumite::cli::k_exit_ok;
    }
    for (const Command& command : k_commands) {
        if (command.spec().name == name) return command.run(argc - 2, argv + 2);
    }
    std::cerr << "kumite: unknown command '" << name << "' (see kumite --help)\n";
    return kumite::cli::k_exit_usage;
}
