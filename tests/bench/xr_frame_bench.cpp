// Frame work in the headset: from xrWaitFrame's return to xrEndFrame's (the bout stepped to the display time, the
// scene built, both eyes drawn, the frame ended), as `kumite play --xr` reports it, against Monado's null
// compositor (software rendering: Mesa's llvmpipe), pinned to one core (taskset -c CORE: kumite, Monado in it and
// llvmpipe's threads share it). For 1 and 4 fighters (or --fighters LIST), at the null compositor's view size and at
// 2016x2240 per eye (a Valve Index-class headset). The user stands still 1.5 m in front of the fighters, hands up.
// The baseline, measured in the same run: the same bout headless (kumite play --headless, no XR, no drawing), its
// per-step time; a 20 Hz runtime frame carries three steps. On one core kumite keeps llvmpipe's drawing in its own
// thread (LP_NUM_THREADS=0); the runtime-size run is repeated with Mesa's default, a worker per core of the machine,
// as the before.
//
// usage (under scripts/with_monado.sh): xr_frame_bench KUMITE [--seconds S] [--fighters 1,4] [--core N] [--character NAME]
// (default: --xr's own, the human body)

#include "xr/kumite_xr_driver.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <utility>

using namespace kumite::test;

namespace {

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    return in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
}

nlohmann::json figures(const nlohmann::json& times) {
    return {{"median", times.value("median", 0.0)}, {"p99", times.value("p99", 0.0)}, {"max", times.value("max", 0.0)}, {"n", times.value("count", 0)}};
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: xr_frame_bench KUMITE [--seconds S] [--fighters 1,4] [--core N] [--character NAME]   (under scripts/with_monado.sh)\n";
        return 2;
    }
    const std::string kumite = std::filesystem::absolute(argv[1]).string();
    double seconds = 20.0;
    std::string fighters_list = "1,4", core = "0", character;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--seconds") seconds = std::atof(argv[i + 1]);
        else if (flag == "--fighters") fighters_list = argv[i + 1];
        else if (flag == "--core") core = argv[i + 1];
        else if (flag == "--character") character = argv[i + 1];
    }
    const int port = remote_port_from_environment();
    if (port == 0) {
        std::cerr << "xr_frame_bench: KUMITE_XR_REMOTE_PORT is unset: run it through scripts/with_monado.sh\n";
        return 2;
    }
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("xr_frame_bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const std::string taskset = "/usr/bin/taskset";
    nlohmann::json results = nlohmann::json::array();
    std::stringstream list(fighters_list);
    for (std::string item; std::getline(list, item, ',');) {
        const std::string fighters = item;
        // The baseline: the same bout, headless.
        const std::string baseline_report = (folder / ("baseline-" + fighters + ".json")).string();
        const std::string headless = taskset + " -c " + core + " " + kumite + " play --headless --fighters " + fighters + " --duration " +
                                     std::to_string(seconds) + " --tracker simulate:still --report " + baseline_report + " > /dev/null 2>&1";
        const int baseline_status = std::system(headless.c_str());
        const nlohmann::json baseline = read_json(baseline_report);
        const std::string cores_of_machine = std::to_string(std::max(1u, std::thread::hardware_concurrency()));
        for (const auto& [size, raster_threads] : {std::pair<std::string, std::string>{"", ""}, {"", cores_of_machine}, {"2016x2240", ""}}) {
            const std::string report_path =
                (folder / ("xr-" + fighters + "-" + (size.empty() ? "runtime" : size) + "-" + raster_threads + ".json")).string();
            // --headless: no supervisor's window drawing on the same core.
            std::vector<std::string> command = {taskset, "-c", core, kumite, "play", "--xr", "--headless", "--fighters", fighters, "--duration",
                                                std::to_string(seconds), "--report", report_path};
            if (!raster_threads.empty()) command.insert(command.begin(), {"/usr/bin/env", "LP_NUM_THREADS=" + raster_threads});
            if (!size.empty()) command.insert(command.end(), {"--xr-view-size", size});
            if (!character.empty()) command.insert(command.end(), {"--character", character});
            const KumiteRun run = run_kumite_xr(command, (folder / "kumite.out").string(), port, seconds + 90.0, [](double, RemoteData& data) {
                data.head.center = remote_pose(Eigen::Quaternionf::Identity(), {0.0f, 1.65f, 1.41f});
                data.left.pose = remote_pose(Eigen::Quaternionf::Identity(), {-0.2f, 1.35f, 1.2f});
                data.right.pose = remote_pose(Eigen::Quaternionf::Identity(), {0.2f, 1.35f, 1.2f});
                data.left.active = data.right.active = true;
                return true;
            });
            const nlohmann::json report = read_json(report_path);
            nlohmann::json entry = {{"name", "xr_frame_work_us"}, {"fighters", std::stoi(fighters)}, {"core", core}, {"exit_status", run.exit_status}};
            if (!run.error.empty()) entry["error"] = run.error;
            if (report.is_object() && report.contains("xr")) {
                const nlohmann::json& xr = report["xr"];
                entry["view_size_px"] = xr["view_size_px"], entry["swapchain_size_px"] = xr["swapchain_size_px"];
                entry["software_raster_threads"] = xr.value("software_raster_threads", nlohmann::json());
                if (!raster_threads.empty()) entry["before"] = "Mesa's default: a rasteriser thread per core of the machine";
                entry["frames_waited"] = xr["frames_waited"], entry["frames_submitted"] = xr["frames_submitted"], entry["errors"] = xr["errors"];
                entry["frame_work_us"] = figures(xr["frame_work_us"]);
                entry["render_us"] = figures(xr["render_us"]);
                for (const char* part : {"steps_us", "scene_us", "end_frame_us"}) {
                    if (xr.contains(part)) entry[part] = figures(xr[part]);
                }
                entry["first_frame_work_us"] = xr["first_frame_work_us"];
                const double work = xr["frame_work_us"].value("median", 0.0);
                entry["render_share_of_median"] = work > 0.0 ? xr["render_us"].value("median", 0.0) / work : 0.0;
                entry["left_of_90hz_frame_at_p99_us"] = 1e6 / 90.0 - xr["frame_work_us"].value("p99", 0.0);
            }
            if (baseline_status == 0 && baseline.is_object()) {
                entry["baseline"] = {{"name", "headless bout step (no XR, no drawing), per 60 Hz step"},
                                     {"median_or_mean", baseline["frame_time_us"].value("mean", 0.0)}, {"p99", baseline["frame_time_us"].value("p99", 0.0)}};
            }
            results.push_back(entry);
            std::cerr << "xr_frame_bench: " << entry.dump() << "\n";
        }
    }
    std::filesystem::remove_all(folder);
    std::cout << nlohmann::json({{"benchmark", "xr_frame_bench"}, {"seconds", seconds}, {"character", character.empty() ? "the --xr default" : character}, {"runtime", "Monado null compositor, llvmpipe"}, {"results", results}}).dump(2) << "\n";
    return 0;
}
