#pragma once

#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <optional>

#include "core/loop/relayed_lathe.h"

namespace tt::devices {
class Device;
class DeviceManager;
}  // namespace tt::devices

namespace tt::ui {

/// One run on the lathe assembled from the devices: the machine the loop thread uses (thread-safe relays to
/// the devices that live in the GUI thread) and the devices' names.
struct LathePorts {
    std::shared_ptr<core::RelayedLathe> machine;
    QString outputName;  ///< the CNC output as named on the Devices page
    QString gaugeName;   ///< the gauge as named there; empty: diameters typed by hand
};

/// Connects the devices configured on the Devices page (GUI thread) to the closed loop of the real lathe
/// (loop thread) through LathePorts: the chosen gauge's readings and health go to the gauge relay, the loop's
/// writes in the correction relay are done on the chosen CNC output device and answered with its result,
/// and the operator's Part finished goes to the operator cycle. Devices are looked up by id every time, so a
/// device replaced or removed on the Devices page is noticed (removed: its port reports it and refuses).
class LatheLink : public QObject {
    Q_OBJECT
public:
    /// `manager` may be null (no devices: nothing can be connected).
    explicit LatheLink(devices::DeviceManager* manager, QObject* parent = nullptr);
    ~LatheLink() override;

    /// Why the loop cannot run with these devices now, in plain words; empty when it can. `gaugeId` empty:
    /// diameters are typed by hand.
    QString startProblem(const QString& outputId, const QString& gaugeId) const;
    /// Fresh ports connected to the devices for a new run; the previous run's are closed. Readings the gauge
    /// took before are dropped (they belong to no part of this run).
    std::shared_ptr<const LathePorts> connectDevices(const QString& outputId, const QString& gaugeId);
    /// The run is over: the loop's later writes are refused with `reason`; the devices stay open.
    void disconnectDevices(const QString& reason);
    /// Whether a run's ports are connected to the devices.
    bool isConnected() const { return m_ports != nullptr; }
    /// The ports of the connected run; null when none.
    const LathePorts* ports() const { return m_ports.get(); }

    /// The part on the machine now, if any.
    std::optional<qint64> partOnMachine() const;
    /// The operator confirms the part on the machine is finished; returns its number.
    std::optional<qint64> finishPart();
    /// Asks the gauge for one reading (polled gauges; push gauges send when their DATA button is pressed).
    void requestReading();
    /// The connected gauge's last value ("26.812 mm"), the CNC output's ("part 7: part-7.nc"); empty if none.
    QString gaugeValue() const;
    QString outputValue() const;

private:
    devices::Device* device(const QString& id) const;
    void pump();
    void pumpGauge();
    void pumpOutput();

    devices::DeviceManager* m_manager;
    QString m_outputId;
    QString m_gaugeId;
    std::shared_ptr<LathePorts> m_ports;
    QTimer m_timer;
};

}  // namespace tt::ui
