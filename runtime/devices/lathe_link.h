#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>

#include "core/loop/relayed_lathe.h"

namespace tt::devices {
class Device;
class DeviceManager;
}  // namespace tt::devices

namespace tt::runtime {

/// Joins the devices configured on the Devices page (the device thread, where this link lives) to the closed
/// loop of the lathe assembled from them (the loop thread) through a core::RelayedLathe: the chosen gauge's
/// readings and health go to the gauge relay, the loop's writes in the correction relay are done on the
/// chosen CNC output device and answered with its result. The operator's Part finished reaches the lathe's
/// operator cycle directly (thread-safe). Pumped on every device change, when a write waits, and every
/// kPumpMs of this thread's timer. Devices are looked up by id every time, so a device replaced or removed on
/// the Devices page is noticed (removed: its port reports it and refuses).
class LatheLink : public QObject {
    Q_OBJECT
public:
    /// `manager` may be null (no devices: nothing can be connected).
    explicit LatheLink(devices::DeviceManager* manager, QObject* parent = nullptr);
    ~LatheLink() override;

    /// Fresh relays connected to the devices for a new run (`gaugeId` empty: diameters by hand); the previous
    /// run's are closed. Readings the gauge took before are dropped (they belong to no part of this run).
    std::shared_ptr<core::RelayedLathe> connectDevices(const QString& outputId, const QString& gaugeId);
    /// The run is over: the loop's later writes are refused with `reason`; the devices stay open.
    void disconnectDevices(const QString& reason);
    /// Whether a run's relays are connected to the devices.
    bool isConnected() const { return m_lathe != nullptr; }

    /// How often the devices are pumped while a run is connected, ms.
    static constexpr int kPumpMs = 20;

private:
    devices::Device* device(const QString& id) const;
    void pump();
    void pumpGauge();
    void pumpOutput();

    devices::DeviceManager* m_manager;
    QString m_outputId;
    QString m_gaugeId;
    std::shared_ptr<core::RelayedLathe> m_lathe;
    QString m_outputName;
    QString m_gaugeName;
    QTimer m_timer;
};

}  // namespace tt::runtime
