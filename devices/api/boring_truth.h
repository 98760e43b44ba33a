#pragma once

#include <memory>

#include "core/ports/boring_station.h"

namespace tt::core {
struct BoringScenario;
}

namespace tt::devices {

/// Capability of a deflection source that is a simulated boring station (the simulator's drive
/// read-out and probe mandrel): it runs a boring pass of its own and tells the truth of it (the
/// bore error with and without compensation, the real deflection and force), which no machine
/// can. A user interface asks a source device for it (Device::boringTruth()) and, when offered,
/// runs the compensation on the pass and shows the truth; it never asks what the device is.
class BoringTruth {
public:
    virtual ~BoringTruth() = default;
    /// A fresh simulated pass of `scenario` (at its PLC cycle) for the compensation from this
    /// source: with a drive read-out the cross feed dithers; with a probe mandrel the mandrel is
    /// first calibrated on the simulated stand. The pass is the station the compensation runs on
    /// (its own ports and PLC, moved on one cycle before each compensation cycle, its truth) and
    /// belongs to the caller, who may hand it to the thread that runs the compensation; while it
    /// lasts the source device's health (its fault switches: silent, unplugged) reaches the pass's
    /// source, thread-safe. Throws std::invalid_argument for a bad scenario,
    /// core::LinearisationRefused when the mandrel cannot be calibrated.
    virtual std::shared_ptr<core::BoringStation> beginPass(const core::BoringScenario& scenario) = 0;
};

}  // namespace tt::devices
