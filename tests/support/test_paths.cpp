#include "support/test_paths.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>

namespace kumite::test {

std::filesystem::path mocap_root() {
    if (const char* root = std::getenv("KUMITE_MOCAP_ROOT"); root && *root) return root;
    return KUMITE_MOCAP_ROOT;
}

std::filesystem::path source_dir() { return KUMITE_SOURCE_DIR; }
std::filesystem::path bin_dir() { return KUMITE_BIN_DIR; }

std::vector<std::filesystem::path> corpus_files() {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    if (!std::filesystem::exists(mocap_root(), error)) return files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             mocap_root(), std::filesystem::directory_options::follow_directory_symlink, error)) {
        if (entry.is_regular_file() && entry.path().extension() == ".bvh") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::filesystem::path make_temp_dir(const std::string& stem) {
    std::random_device random;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("kumite-" + stem + "-" + std::to_string(random()));
    std::filesystem::create_directories(dir);
    return dir;
}

CommandOutput run_command(const std::string& command) {
    const std::filesystem::path dir = make_temp_dir("cmd");
    const std::string out_path = (dir / "out").string(), err_path = (dir / "err").string();
    const int raw = std::system((command + " >" + out_path + " 2>" + err_path + " </dev/null").c_str());
    CommandOutput output;
    output.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    auto slurp = [](const std::string& path) {
        std::ifstream stream(path);
        std::ostringstream text;
        text << stream.rdbuf();
        return text.str();
    };
    output.out = slurp(out_path);
    output.err = slurp(err_path);
    std::filesystem::remove_all(dir);
    return output;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

} // namespace kumite::test
