#pragma once
// A client of Monado's `remote` driver (the runtime the --xr tests run against): one TCP connection to 127.0.0.1,
// whole `struct r_remote_data` written each time a pose changes, nothing acknowledged. The layout is the one in
// the Monado archive's src/xrt/drivers/remote/r_interface.h (376 bytes on x86-64, native byte order), mirrored
// here with its sizes and offsets checked at compile time. Head pose: the view pose (between the eyes).

#include <Eigen/Geometry>

#include <cstdint>
#include <string>

namespace kumite::test {

struct RemotePose { // struct xrt_pose: orientation x y z w, then position
    float qx = 0, qy = 0, qz = 0, qw = 1, x = 0, y = 0, z = 0;
};
struct RemoteFov { // struct xrt_fov
    float angle_left = 0, angle_right = 0, angle_up = 0, angle_down = 0;
};
struct RemoteHeadView {
    RemoteFov fov;
    RemotePose pose;
    std::uint32_t pad = 0;
};
struct RemoteHead { // struct r_head_data
    RemoteHeadView views[2];
    RemotePose center;
    bool per_view_data_valid = false, pad0 = false, pad1 = false, pad2 = false;
};
struct RemoteController { // struct r_remote_controller_data
    RemotePose pose;
    float linear_velocity[3] = {}, angular_velocity[3] = {}, hand_curl[5] = {};
    float trigger_value = 0, squeeze_value = 0, squeeze_force = 0, thumbstick[2] = {}, trackpad_force = 0, trackpad[2] = {};
    bool hand_tracking_active = false, active = false, system_click = false, system_touch = false, a_click = false, a_touch = false, b_click = false,
         b_touch = false, trigger_click = false, trigger_touch = false, thumbstick_click = false, thumbstick_touch = false, trackpad_touch = false,
         pad0 = false, pad1 = false, pad2 = false;
};
struct RemoteData { // struct r_remote_data
    std::uint64_t header = 0;
    RemoteHead head;
    RemoteController left, right;
};
static_assert(sizeof(RemotePose) == 28 && sizeof(RemoteHeadView) == 48 && sizeof(RemoteHead) == 128);
static_assert(sizeof(RemoteController) == 120 && sizeof(RemoteData) == 376, "r_remote_data is 376 bytes (r_interface.h)");
static_assert(offsetof(RemoteData, head) == 8 && offsetof(RemoteData, left) == 136 && offsetof(RemoteData, right) == 256);
static_assert(offsetof(RemoteController, active) == 105 && offsetof(RemoteController, a_click) == 108);

RemotePose remote_pose(const Eigen::Quaternionf& orientation, const Eigen::Vector3f& position);

class RemoteDriverClient {
public:
    ~RemoteDriverClient();
    // Connects (retrying until `timeout_s`, while `keep_trying()` says so) and reads the two states Monado sends
    // first (its reset and latest); `latest()` is then the template to change and send.
    bool connect(int port, double timeout_s, bool (*keep_trying)(void*), void* context, std::string& error);
    bool send(const RemoteData& data, std::string& error);
    const RemoteData& latest() const { return m_latest; }

private:
    int m_socket = -1;
    RemoteData m_latest;
};

} // namespace kumite::test
