#pragma once

#include <cstdint>
#include <optional>

#include "core/ports/correction_output.h"
#include "core/ports/device_health.h"

namespace tt::core {

/// A part that came off the machine.
struct FinishedPart {
    std::int64_t partNumber = 0;
    double timeS = 0.0;  ///< when the cycle ended (Clock), s
};

/// The machine's part cycle as the closed loop sees it (cell-controller style): the loop asks for the
/// next part once its corrections are on the CNC, and learns when it is finished (the CNC's cycle-end
/// signal). Non-blocking like every port.
class MachineCycle {
public:
    virtual ~MachineCycle() = default;
    /// Whether the machine can run parts now, with the reason when not.
    virtual DeviceHealth health() const = 0;
    /// Starts machining part `partNumber` with the corrections last sent to the CNC. Fails (with the
    /// reason) when the machine is busy or not ready.
    virtual OutputResult startPart(std::int64_t partNumber) = 0;
    /// The oldest finished part not yet taken, if any (never blocks).
    virtual std::optional<FinishedPart> takeFinishedPart() = 0;
};

}  // namespace tt::core
