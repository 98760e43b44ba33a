#pragma once

#include <optional>

#include "core/ports/device_health.h"

namespace tt::core {

/// One diameter reading from a gauge micrometer, already converted to millimetres.
struct GaugeReading {
    double diameterMm = 0.0;  ///< measured diameter, mm
    double timeS = 0.0;       ///< when it arrived (Clock time), s
};

/// A gauge micrometer that measures finished diameters (paper 000: 0.001 mm micrometer).
/// Readings are raw values in arrival order; the measurement session assigns them to
/// control points in order. Push gauges send on their data button; polled gauges answer
/// requestReading().
class DiameterGauge {
public:
    virtual ~DiameterGauge() = default;
    /// Whether the gauge delivers readings now, with the reason when not.
    virtual DeviceHealth health() const = 0;
    /// Asks a polled gauge for one reading; push-only gauges ignore it.
    virtual void requestReading() = 0;
    /// The oldest reading not yet taken, if any (never blocks).
    virtual std::optional<GaugeReading> takeReading() = 0;
    /// The readings come from a person typing them in: the loop waits for them as long as it takes,
    /// without the gauge timeout.
    virtual bool handEntry() const { return false; }
};

}  // namespace tt::core
