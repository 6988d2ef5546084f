#pragma once
// Where tests find the reference captures, the repository and the built executables.

#include <filesystem>
#include <string>
#include <vector>

namespace kumite::test {

// $KUMITE_MOCAP_ROOT if set, else the folder configured at build time (data/mocap).
std::filesystem::path mocap_root();
std::filesystem::path source_dir();
std::filesystem::path bin_dir();

// Every .bvh under the mocap root, sorted; empty when the captures are absent.
std::vector<std::filesystem::path> corpus_files();

// A fresh, empty folder under the system temp folder, removed by the OS eventually.
std::filesystem::path make_temp_dir(const std::string& stem);

// A whole file's bytes ("" when it cannot be read).
std::string read_text(const std::filesystem::path& path);

// Runs a shell command, capturing stdout and stderr; returns the exit status.
struct CommandOutput {
    int status = -1;
    std::string out;
    std::string err;
};
CommandOutput run_command(const std::string& command);

} // namespace kumite::test
