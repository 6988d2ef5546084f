// BVH parse throughput: bvh_parse on in-memory text, by default (two threads on large files) and serial, against a
// naive baseline measured in the same run (every whitespace token through std::istringstream >> double, as simple
// readers do).
//
// usage: bvh_parse_bench [FILE.bvh ...] [--repeats N]
//        default file: the largest .bvh under $KUMITE_MOCAP_ROOT or data/mocap.
// Prints one JSON document.

#include "kumite/formats/bvh_reader.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

std::filesystem::path largest_capture() {
    const char* env = std::getenv("KUMITE_MOCAP_ROOT");
    const std::filesystem::path root = env && *env ? env : "data/mocap";
    std::filesystem::path best;
    std::uintmax_t best_size = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             root, std::filesystem::directory_options::follow_directory_symlink, error)) {
        if (entry.path().extension() == ".bvh" && entry.file_size() > best_size) {
            best = entry.path();
            best_size = entry.file_size();
        }
    }
    return best;
}

struct Stats {
    double median_ms = 0.0;
    double p99_ms = 0.0;
};

template <class Work>
Stats time_runs(int repeats, Work&& work) {
    std::vector<double> times;
    for (int i = 0; i < repeats; ++i) {
        const auto start = Clock::now();
        work();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    const size_t p99 = std::min(times.size() - 1, static_cast<size_t>(std::ceil(0.99 * times.size())) - 1);
    return {times[times.size() / 2], times[p99]};
}

double naive_parse(const std::string& text) {
    std::istringstream stream(text);
    std::string token;
    double sum = 0.0;
    while (stream >> token) {
        std::istringstream number(token);
        double value = 0.0;
        if (number >> value) sum += value;
    }
    return sum;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    int repeats = 30;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--repeats" && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
        else if (argument == "--help") {
            std::cout << "usage: bvh_parse_bench [FILE.bvh ...] [--repeats N]\n";
            return 0;
        } else files.emplace_back(argument);
    }
    if (files.empty()) files.push_back(largest_capture());
    if (files.front().empty()) {
        std::cerr << "bvh_parse_bench: no capture given and none found under data/mocap\n";
        return 1;
    }

    std::cout << "{\"benchmark\": \"bvh_parse\", \"repeats\": " << repeats << ", \"files\": [";
    for (size_t f = 0; f < files.size(); ++f) {
        std::ifstream stream(files[f], std::ios::binary);
        std::ostringstream buffer;
        buffer << stream.rdbuf();
        const std::string text = buffer.str();
        const double megabytes = text.size() / 1e6;

        volatile int frames = 0;
        auto parse_with = [&](int threads) {
            kumite::BvhReadOptions options;
            options.threads = threads;
            return time_runs(repeats, [&] {
                kumite::Result<kumite::BvhFile> file = kumite::bvh_parse(text, files[f].string(), options);
                if (!file) {
                    std::cerr << file.error().message << "\n";
                    std::exit(1);
                }
                frames = file->clip.frame_count();
            });
        };
        const Stats parse = parse_with(0);  // the default: two threads on large files when the machine has two cores
        const Stats serial = parse_with(1); // one thread
        volatile double sink = 0.0;
        const Stats naive = time_runs(std::max(3, repeats / 5), [&] { sink = naive_parse(text); });
        auto throughput = [&](double ms) { return megabytes / (ms / 1000.0); };

        std::cout << (f ? ", " : "") << "{\"file\": \"" << files[f].string() << "\", \"bytes\": " << text.size()
                  << ", \"frames\": " << frames << ", \"threads\": " << std::min(2u, std::thread::hardware_concurrency())
                  << ", \"parse_ms\": {\"median\": " << parse.median_ms << ", \"p99\": " << parse.p99_ms
                  << "}, \"throughput_mb_s\": {\"median\": " << throughput(parse.median_ms) << ", \"p99\": " << throughput(parse.p99_ms)
                  << "}, \"serial\": {\"parse_ms\": {\"median\": " << serial.median_ms << ", \"p99\": " << serial.p99_ms
                  << "}, \"throughput_mb_s\": {\"median\": " << throughput(serial.median_ms) << ", \"p99\": " << throughput(serial.p99_ms)
                  << "}}, \"baseline\": {\"name\": \"istringstream tokens\", \"median_ms\": " << naive.median_ms
                  << ", \"throughput_mb_s\": " << throughput(naive.median_ms) << "}, \"speedup_vs_baseline\": " << naive.median_ms / parse.median_ms
                  << "}";
    }
    std::cout << "]}\n";
    return 0;
}
