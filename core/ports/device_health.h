#pragma once

#include <string>
#include <string_view>

namespace tt::core {

/// Connection state of any device behind a port (gauge, probe, drive readout, CNC output).
enum class DeviceState { Disconnected, Connecting, Ready, Error };

/// State plus the last message in the user's terms ("no answer from COM3 for 2.0 s").
struct DeviceHealth {
    DeviceState state = DeviceState::Disconnected;
    std::string message;

    /// The device works.
    bool ready() const { return state == DeviceState::Ready; }
};

/// Plain English name of a state, for logs and the CLI ("ready", "error", ...).
constexpr std::string_view toString(DeviceState state) {
    switch (state) {
        case DeviceState::Disconnected:
            return "disconnected";
        case DeviceState::Connecting:
            return "connecting";
        case DeviceState::Ready:
            return "ready";
        case DeviceState::Error:
            return "error";
    }
    return "unknown";
}

}  // namespace tt::core
