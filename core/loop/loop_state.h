#pragma once

#include <string_view>

namespace tt::core {

/// States of the closed loop. Idle: no run. Running: parts are machined and measured. Paused: no new
/// part is started and the CNC keeps the last correction (by the operator, or because the diameters
/// the next correction needs do not come). Fault: something failed that needs the operator (the CNC
/// refused a correction, the history cannot be written); the last correction is held.
enum class LoopState { Idle, Running, Paused, Fault };

/// Plain English name ("running").
constexpr std::string_view toString(LoopState state) {
    switch (state) {
        case LoopState::Idle:
            return "idle";
        case LoopState::Running:
            return "running";
        case LoopState::Paused:
            return "paused";
        case LoopState::Fault:
            return "fault";
    }
    return "unknown";
}

}  // namespace tt::core
