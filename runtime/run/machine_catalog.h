#pragma once

#include <QList>
#include <QString>
#include <functional>
#include <memory>
#include <optional>

#include "core/ports/shaft_machine.h"
#include "core/run/shaft_scenario.h"
#include "runtime/run/run_request.h"

namespace tt::runtime {

class DeviceHub;

/// The key of the lathe assembled from the devices of the Devices page (its CNC output and gauge, each part
/// confirmed by the operator).
inline const QString kDevicesLatheKey = QStringLiteral("devices-lathe");

/// The key a machine has now for one stored before (the lathe from devices was "real"); other keys unchanged.
QString currentMachineKey(const QString& storedKey);

/// Makes the machine of a run for its scenario; called in the loop's thread.
using MachineMaker = std::function<std::shared_ptr<core::ShaftMachine>(const core::ShaftScenario& scenario)>;

/// What a machine offered for shaft runs can do. The Run page asks these, never what the machine is.
struct MachineCapabilities {
    bool adjustableSpeed = false;  ///< its time is simulated: the run paces it at a settable multiple of the wall clock
    bool usesDevices = false;      ///< its CNC output and gauge are chosen from the Devices page
    bool partsConfirmedByOperator = false;  ///< the operator confirms each part (Part finished)
};

/// One machine a run can go on: a complete machine a device plugin offers (QGroundControl's MockLink is just
/// another link: the built-in simulator's lathe is one of these) or the lathe assembled from the devices.
struct MachineOffer {
    QString key;
    QString name;         ///< in the user's language
    QString description;  ///< one sentence for the page
    MachineCapabilities can;
    /// The CNC that cuts its parts and its correction mode, for the run request (RunRequest::cnc, cncMode); empty:
    /// none.
    QString cnc;
    QString cncMode;
    /// Why a run of `request` cannot start on it now, in plain words; empty when it can (GUI thread).
    std::function<QString(const RunRequest& request)> startProblem;
    /// Readies the machine for a run of `request` (GUI thread: a lathe from devices connects its relays) and
    /// returns what makes it in the loop's thread. Throws std::invalid_argument with the reason.
    std::function<MachineMaker(const RunRequest& request)> prepare;
    /// The run on it is over (GUI thread): a lathe from devices refuses the loop's later writes with `reason`.
    std::function<void(const QString& reason)> release;
};

/// Every machine a shaft run can go on: the plugins' complete machines (the simulator's lathe first), those the
/// configured devices make possible (the LinuxCNC lathe of each LinuxCNC device) and the lathe assembled from the
/// devices of the Devices page.
class MachineCatalog {
public:
    /// `hub` may be null (no devices: only machines that need none... and none are known then).
    explicit MachineCatalog(DeviceHub* hub);

    QList<MachineOffer> offers() const;
    std::optional<MachineOffer> find(const QString& key) const;

private:
    MachineOffer devicesLathe() const;

    DeviceHub* m_hub;
};

}  // namespace tt::runtime
