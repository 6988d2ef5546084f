#pragma once
// The kumite subcommands. Each takes the arguments after its name and returns the process exit status
// (0 success, 1 bad input, 2 usage error).

#include "arguments.h"

namespace kumite::cli {

struct Command {
    const CommandSpec& (*spec)();
    int (*run)(int argc, char** argv);
};

const CommandSpec& inspect_spec();
int run_inspect(int argc, char** argv);

const CommandSpec& positions_spec();
int run_positions(int argc, char** argv);

const CommandSpec& convert_spec();
int run_convert(int argc, char** argv);

const CommandSpec& characters_spec();
int run_characters(int argc, char** argv);

const CommandSpec& retarget_spec();
int run_retarget(int argc, char** argv);

const CommandSpec& suggest_spec();
int run_suggest(int argc, char** argv);

const CommandSpec& bake_spec();
int run_bake(int argc, char** argv);

const CommandSpec& db_info_spec();
int run_db_info(int argc, char** argv);

const CommandSpec& query_spec();
int run_query(int argc, char** argv);

const CommandSpec& adapt_spec();
int run_adapt(int argc, char** argv);

const CommandSpec& play_spec();
int run_play(int argc, char** argv);

const CommandSpec& report_spec();
int run_report(int argc, char** argv);

// Training (authoring/training): a drill run and stored, the store's sessions, a trainee's progress, the export.
const CommandSpec& train_spec();
int run_train(int argc, char** argv);

const CommandSpec& sessions_spec();
int run_sessions(int argc, char** argv);

const CommandSpec& progress_spec();
int run_progress(int argc, char** argv);

const CommandSpec& export_spec();
int run_export(int argc, char** argv);

} // namespace kumite::cli
