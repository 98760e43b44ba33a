#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <optional>

#include "core/control/in_process_compensation.h"
#include "core/loop/boring_relays.h"
#include "runtime/boring/compensation_worker.h"

namespace tt::devices {
class DeviceManager;
}

namespace tt::runtime {

/// Joins the devices chosen on the Boring tab (GUI thread, where they live) to the compensation's
/// thread through a core::RelayedBoringStation: the source device's samples (its drive read-out or
/// its probe mandrel) and health go into the source relay, the offsets the compensation hands over
/// are written to the CNC output device and answered with its result, and the output's health is
/// published. Pumped on every device change, when an offset waits, and on a short timer. Devices
/// are looked up by id every time, so a removed device is noticed (its relay reports it
/// disconnected and the offset is refused).
class BoringLink : public QObject {
    Q_OBJECT
public:
    /// `manager` may be null (nothing can be connected).
    explicit BoringLink(devices::DeviceManager* manager, QObject* parent = nullptr);
    ~BoringLink() override;

    /// Fresh relays joined to `sourceId` (its drive read-out for Current, its probe for Probe) and
    /// `outputId`, for a run at `plcCycleS`; the previous run's are closed. Samples the source
    /// took before are dropped (they belong to no cycle of this run).
    std::shared_ptr<core::RelayedBoringStation> connectDevices(const QString& sourceId, core::BoringMethod method,
                                                               const QString& outputId, double plcCycleS);
    /// The run is over: later offsets are refused; the devices stay open.
    void disconnectDevices();
    bool isConnected() const { return m_station != nullptr; }
    /// When the offsets of the connected (or last) run were written to the CNC output (steady clock, in the
    /// device thread), oldest first: a busy window must not space them out.
    std::vector<std::chrono::steady_clock::time_point> writeTimes() const { return m_writes.starts(); }

private:
    void pump();
    void pumpSource();
    void pumpOutput();

    devices::DeviceManager* m_manager;
    QString m_sourceId;
    QString m_outputId;
    core::BoringMethod m_method = core::BoringMethod::Current;
    std::shared_ptr<core::RelayedBoringStation> m_station;
    CycleSchedule m_writes;
    QTimer m_timer;
};

}  // namespace tt::runtime
