#pragma once

#include <QHash>
#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/control/in_process_compensation.h"
#include "core/loop/boring_relays.h"
#include "core/loop/relayed_lathe.h"
#include "devices/api/device_plugin.h"
#include "runtime/devices/device_view.h"

class QSettings;

namespace tt::core {
struct BoringScenario;
class Clock;
}  // namespace tt::core

namespace tt::runtime {

class CalibrationLink;
class DeviceHost;

/// The windows' handle on the devices, which live in a thread of their own (QGroundControl's link manager):
/// the device thread runs the plugins' instances (serial ports, Modbus clients, timers) and the pumps that
/// join them to the runs (DeviceHost), so a window that is busy for seconds delays no reading, no offset and
/// no correction. The windows see snapshots (DeviceView), updated through queued signals; they command
/// through the hub, whose calls run in the device thread (set-up calls wait for it, which is safe: the device
/// thread never waits for the GUI). Lives in the GUI thread.
class DeviceHub : public QObject {
    Q_OBJECT
public:
    /// Starts the device thread with its DeviceManager; `clock` (may be null: a steady clock) stamps every
    /// sample and must outlive the hub.
    explicit DeviceHub(const core::Clock* clock = nullptr, QObject* parent = nullptr);
    /// Closes every run's link and every instance in the device thread, then ends the thread.
    ~DeviceHub() override;

    // ---- plugins and instances ----
    /// Loads the plugin libraries of `folder`; returns how many loaded (DeviceManager::loadPlugins).
    int loadPlugins(const QString& folder);
    QStringList pluginErrors() const;
    /// Every plugin, the ones linked into the program first. Their schemas and checks may be asked from any
    /// thread; their instances are made in the device thread only.
    QList<devices::DevicePlugin*> plugins() const { return m_plugins; }
    devices::DevicePlugin* plugin(const QString& pluginId) const;
    /// The complete machines the plugins offer for shaft runs, and those their configured devices make possible
    /// (DevicePlugin::deviceMachines: a LinuxCNC device's LinuxCNC lathe).
    QList<devices::ShaftMachineOffer> shaftMachineOffers() const;
    /// The clock that stamps the samples (thread-safe).
    const core::Clock& clock() const { return *m_clock; }

    /// As DeviceManager::addDevice / updateDevice / removeDevice, in the device thread; the snapshots are up to
    /// date when they return. Throws std::invalid_argument with every settings problem.
    QString addDevice(const QString& pluginId, devices::DeviceKind kind, const QString& name,
                      const QVariantMap& settings);
    void updateDevice(const QString& id, const QString& name, const QVariantMap& settings);
    void removeDevice(const QString& id);
    /// Writes every instance to `settings` / replaces them with those saved there (DeviceManager::save,
    /// restore); restore returns the problems in plain words.
    void save(QSettings& settings);
    QStringList restore(QSettings& settings);
    void openAll();
    void open(const QString& id);
    void testConnection(const QString& id);
    void requestReading(const QString& id);
    void setFaults(const QString& id, const devices::FaultSwitches& faults);
    /// A trial instance with typed settings (view kTrialDeviceId), `closeId` closed meanwhile (DeviceHost).
    void startTrial(const QString& pluginId, devices::DeviceKind kind, const QVariantMap& settings,
                    const QString& closeId);
    void endTrial();

    // ---- snapshots ----
    QStringList deviceIds() const;
    /// The latest snapshot of `id` (or of the trial instance); null when there is none. Valid until the next
    /// event loop turn.
    const DeviceView* view(const QString& id) const;
    QStringList devicesOfKind(devices::DeviceKind kind) const;
    DeviceSummary summary() const;

    // ---- the runs' links (their pumps run in the device thread) ----
    std::shared_ptr<core::RelayedLathe> connectLathe(const QString& outputId, const QString& gaugeId);
    void disconnectLathe(const QString& reason);
    /// Whether a run's relays are connected to the devices of the lathe assembled from them.
    bool latheConnected();
    std::shared_ptr<core::RelayedBoringStation> connectBoring(const QString& sourceId, core::BoringMethod method,
                                                              const QString& outputId, double plcCycleS);
    void disconnectBoring();
    /// When the boring run's offsets were written to its CNC output, in the device thread (oldest first).
    std::vector<std::chrono::steady_clock::time_point> boringWriteTimes();
    std::shared_ptr<core::BoringStation> beginBoringPass(const QString& sourceId, const core::BoringScenario& scenario);
    /// Writes a dynamic X offset to a CNC output at once (DeviceHost::writeOffset).
    core::OutputResult writeOffset(const QString& outputId, double xOffsetMm);

    // ---- the calibration wizards' instruments ----
    std::shared_ptr<CalibrationLink> calibrationLink(const QString& id);
    void bendBar(const QString& id, int plane, double tipDeflectionMm);
    void applyLoadN(const QString& id, double loadN);
    void releaseJack(const QString& id);
    void uploadTable(const QString& id, const std::vector<std::uint8_t>& image, std::uint16_t version,
                     std::uint32_t crc32c);

    /// Runs `work` on the instance `id` in the device thread and waits for it (a lathe simulator setting a
    /// simulated instrument's inputs, tests reading an instrument); false when there is no such instance.
    bool withDevice(const QString& id, const std::function<void(devices::Device&)>& work);

    /// The device thread (never the GUI thread).
    QThread* deviceThread() { return &m_thread; }
    /// Waits until everything the device thread had to tell has arrived (tests).
    void sync();

signals:
    /// An instance was added, removed or replaced (or the trial one came or went).
    void devicesChanged();
    /// The snapshot of `id` changed (state, live value, last error, counters).
    void deviceChanged(const QString& id);

private:
    /// Runs `work` in the device thread and waits for it; its exception is thrown here.
    void onDeviceThread(const std::function<void()>& work);
    /// Runs `command` in the device thread, then takes the snapshot of `id` it changed.
    void commandDevice(const QString& id, const std::function<void()>& command);
    void takeList(const QList<DeviceView>& views);
    void takeChanges(const QList<DeviceView>& views);

    const core::Clock* m_clock = nullptr;
    QThread m_thread;
    QObject* m_anchor = nullptr;  ///< lives in the device thread: the context of every call made there
    DeviceHost* m_host = nullptr;
    QList<devices::DevicePlugin*> m_plugins;
    QList<DeviceView> m_views;
};

}  // namespace tt::runtime
