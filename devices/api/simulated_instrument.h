#pragma once

#include "devices/api/boring_truth.h"
#include "devices/api/calibration_stand.h"
#include "devices/api/device.h"

namespace tt::devices {

/// What only a simulated instrument can do, as an interface of its own beside Device (one interface per
/// role): fault switches that make it misbehave like a real one, the inputs a lathe simulator drives it
/// with, a boring pass of its own whose truth it knows, and the calibration stand it sits on. The built-in
/// simulator's devices implement it; a device on a machine does not. Ask for it with simulatedInstrument().
class SimulatedInstrument {
public:
    virtual ~SimulatedInstrument() = default;

    /// Its fault switches (silent, noisy, stuck, malformed frames, unplugged).
    virtual FaultSwitches& faultSwitches() = 0;
    /// The true values it measures, set by a lathe simulator.
    virtual SimulationInputs& simulationInputs() = 0;
    /// A simulated boring pass of its own and its truth (drive read-outs and probe mandrels); null otherwise.
    virtual BoringTruth* boringTruth() { return nullptr; }
    /// The calibration stand it sits on (screw jack, hydraulic jack); null when it is on no stand.
    virtual CalibrationStand* calibrationStand() { return nullptr; }
};

/// The device as a simulated instrument; null for a device that is not one.
inline SimulatedInstrument* simulatedInstrument(Device& device) {
    return dynamic_cast<SimulatedInstrument*>(&device);
}

/// The device as a simulated instrument (read-only); null for a device that is not one.
inline const SimulatedInstrument* simulatedInstrument(const Device& device) {
    return dynamic_cast<const SimulatedInstrument*>(&device);
}

}  // namespace tt::devices
