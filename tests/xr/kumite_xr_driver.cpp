#include "kumite_xr_driver.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace kumite::test {
namespace {

bool running(void* pid) {
    int status = 0;
    return ::waitpid(*static_cast<pid_t*>(pid), &status, WNOHANG) == 0;
}

} // namespace

int remote_port_from_environment() {
    const char* text = std::getenv("KUMITE_XR_REMOTE_PORT");
    return text ? std::atoi(text) : 0;
}

KumiteRun run_kumite_xr(const std::vector<std::string>& command, const std::string& stdout_path, int port, double timeout_s,
                        const std::function<bool(double, RemoteData&)>& pose_at) {
    KumiteRun run;
    pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        if (std::FILE* out = std::freopen(stdout_path.c_str(), "w", stdout)) (void)out;
        ::execv(argv[0], argv.data());
        std::_Exit(127);
    }
    if (pid < 0) {
        run.error = "fork failed";
        return run;
    }
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    int status = 0;
    bool exited = false;
    RemoteDriverClient client;
    if (client.connect(port, timeout_s, running, &pid, run.error)) {
        const auto connected = std::chrono::steady_clock::now();
        bool sending = true;
        while (!exited && elapsed() < timeout_s) {
            RemoteData data = client.latest();
            if (sending) sending = pose_at(std::chrono::duration<double>(std::chrono::steady_clock::now() - connected).count(), data);
            std::string send_error; // kumite (and Monado in it) ended: the exit status says how
            if (sending && !client.send(data, send_error)) sending = false;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            exited = ::waitpid(pid, &status, WNOHANG) == pid;
        }
    }
    if (!exited) exited = ::waitpid(pid, &status, WNOHANG) == pid;
    if (!exited) {
        // Not connected, or no end in time: give it the rest of the timeout, then kill it.
        while (elapsed() < timeout_s && !exited) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            exited = ::waitpid(pid, &status, WNOHANG) == pid;
        }
        if (!exited) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            run.error = "kumite play --xr did not end within " + std::to_string(int(timeout_s)) + " s: killed";
            return run;
        }
    }
    run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

} // namespace kumite::test
