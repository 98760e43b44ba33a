#pragma once

#include <QList>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

#include "core/control/in_process_compensation.h"
#include "core/ports/boring_station.h"
#include "core/run/boring_run.h"

namespace tt::core {
struct BoringScenario;
}

namespace tt::runtime {

class DeviceHub;

/// Where the compensation's deflection comes from: a drive read-out (current + dither) or a probe mandrel.
struct BoringSource {
    QString deviceId;
    core::BoringMethod method = core::BoringMethod::Current;
};

/// What the place the offset goes can do. The Boring tab asks these, never what the place is.
struct BoringTargetCapabilities {
    bool knowsTruth = false;       ///< the bore error with and without compensation is known (bore chart, progress)
    bool ownTool = false;          ///< it bores with a boring bar of its own (offered first among the tools)
    bool adjustableSpeed = false;  ///< its PLC cycles may run faster than the wall clock
    bool holdsOffset = false;      ///< the CNC keeps the offset after a run; the operator may zero it by hand
    bool choosesPlane = true;      ///< the probe's plane along X is chosen (else plane 1 lies along X)
};

/// A run's station, ready to hand to the compensation's thread, and what ends its link.
struct PreparedStation {
    std::shared_ptr<core::BoringStation> station;
    /// Ends the run's link (the devices stay open); returns the offset the CNC confirmed last, if any.
    std::function<std::optional<double>()> finish;
};

/// One place the compensation's offset can go for a source: the source's own simulated boring pass (its PLC,
/// devices::BoringTruth) or a CNC output of the Devices page (the devices joined through relays in the device
/// thread, runtime::BoringLink). Preparing it assembles the station; the tab never does.
struct BoringTarget {
    QString key;  ///< stored with the tab's choices ("station", or "dev:<id>")
    QString name;
    BoringTargetCapabilities can;
    /// The station for a run from `source` with `choices` (adjusted here: a pass starts at offset 0 with plane 1
    /// along X; a CNC output continues from `heldOffsetMm`) on `scenario`'s pass. Throws std::invalid_argument.
    std::function<PreparedStation(const BoringSource& source, core::BoringRunChoices& choices,
                                  const core::BoringScenario& scenario, double heldOffsetMm)>
        prepare;
};

/// The targets for `source`: its own simulated pass first when it runs one and the scenario can be read
/// (`scenarioUsable`), then every CNC output of the hub (may be null: none).
QList<BoringTarget> boringTargets(DeviceHub* hub, const QString& sourceId, bool scenarioUsable);

}  // namespace tt::runtime
