#pragma once

#include <optional>

#include "core/ports/device_health.h"

namespace tt::core {

/// One sample from the cross-feed drive (paper 001, way 1).
struct DriveSample {
    double timeS = 0.0;           ///< sample time (Clock), s
    double currentA = 0.0;        ///< motor current (torque-producing), A
    double velocityMmPerS = 0.0;  ///< slide velocity, mm/s (sign = direction)
    double positionMm = 0.0;      ///< slide position, mm
};

/// Read-out of the cross-feed motor current, velocity and position (drive or PLC, e.g. Modbus).
class DriveCurrentReadout {
public:
    virtual ~DriveCurrentReadout() = default;
    /// Whether the read-out delivers samples now, with the reason when not.
    virtual DeviceHealth health() const = 0;
    /// The oldest sample not yet taken, if any (never blocks).
    virtual std::optional<DriveSample> takeSample() = 0;
};

}  // namespace tt::core
