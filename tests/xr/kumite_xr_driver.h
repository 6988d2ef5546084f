#pragma once
// Runs one `kumite play --xr` process and plays the user through Monado's remote driver while it runs: connects
// to the driver (in kumite's process, once its OpenXR instance exists), then every 10 ms asks `pose_at` for the
// state to send at that time (seconds since the connection) and sends it. For the --xr tests and benchmarks, run
// under scripts/with_monado.sh.

#include "remote_driver_client.h"

#include <functional>
#include <string>
#include <vector>

namespace kumite::test {

struct KumiteRun {
    int exit_status = -1; // -1: killed (no end within the timeout) or not started
    std::string error;    // why nothing was fed, or why it was killed
};

// `command[0]` is the executable (absolute path), stdout goes to `stdout_path`. `pose_at` changes a copy of the
// driver's own latest state; return false to stop sending (kumite runs on). Killed after `timeout_s`.
KumiteRun run_kumite_xr(const std::vector<std::string>& command, const std::string& stdout_path, int port, double timeout_s,
                        const std::function<bool(double, RemoteData&)>& pose_at);

// The remote driver's port from KUMITE_XR_REMOTE_PORT (set by scripts/with_monado.sh), or 0.
int remote_port_from_environment();

} // namespace kumite::test
