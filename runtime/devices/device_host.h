#pragma once

#include <QHash>
#include <QObject>
#include <QSet>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

#include "core/control/in_process_compensation.h"
#include "core/loop/boring_relays.h"
#include "core/loop/relayed_lathe.h"
#include "devices/api/calibration_stand.h"
#include "devices/api/device_manager.h"
#include "runtime/devices/device_view.h"

namespace tt::core {
struct BoringScenario;
}

namespace tt::runtime {

class BoringLink;
class CalibrationLink;
class LatheLink;

/// Everything that lives in the device thread (DeviceHub starts it): the device manager with its plugins
/// and instances (their serial ports, Modbus clients and timers run in this thread's event loop), the
/// links that join the devices to the runs (the shaft loop's LatheLink, the boring compensation's
/// BoringLink, the calibration wizards' CalibrationLinks; their pumps run on this thread's timers, so a busy
/// window delays none of them), and the trial instance the Devices page tests typed settings on. It tells the
/// windows what changed as snapshots (viewsChanged, at most every kViewFlushMs per change). Every method is
/// called in the device thread (DeviceHub marshals the GUI's calls).
class DeviceHost : public QObject {
    Q_OBJECT
public:
    /// Made in the device thread; `clock` (may be null: a steady clock) stamps every sample.
    explicit DeviceHost(const core::Clock* clock);
    ~DeviceHost() override;

    devices::DeviceManager& manager() { return *m_manager; }
    /// Every instance (and the trial one) as a snapshot.
    QList<DeviceView> views() const;
    /// One instance as a snapshot; none when there is no such instance.
    std::optional<DeviceView> view(const QString& id) const;

    /// A trial instance of `pluginId` with `settings` (DeviceView id kTrialDeviceId) that tests them; the
    /// instance `closeId` (may be empty) lets go of its port meanwhile. Throws std::invalid_argument.
    void startTrial(const QString& pluginId, devices::DeviceKind kind, const QVariantMap& settings,
                    const QString& closeId);
    /// Ends the trial: the instance is closed and destroyed, the one closed for it reopened.
    void endTrial();
    /// Makes the device prove it answers (Device::testConnection); the trial one by kTrialDeviceId.
    void testConnection(const QString& id);
    /// Asks a gauge for one reading.
    void requestReading(const QString& id);
    /// Sets the fault switches of a simulated instrument (ignored for other devices).
    void setFaults(const QString& id, const devices::FaultSwitches& faults);

    /// Fresh relays of the lathe assembled from the CNC output `outputId` and the gauge `gaugeId` (empty:
    /// diameters by hand) for a new run; the previous run's are closed.
    std::shared_ptr<core::RelayedLathe> connectLathe(const QString& outputId, const QString& gaugeId);
    /// The lathe's run is over: its later writes are refused with `reason`.
    void disconnectLathe(const QString& reason);
    bool latheConnected() const;
    /// Fresh relays of a boring station on the source `sourceId` and the CNC output `outputId`.
    std::shared_ptr<core::RelayedBoringStation> connectBoring(const QString& sourceId, core::BoringMethod method,
                                                              const QString& outputId, double plcCycleS);
    /// The boring run is over: later offsets are refused.
    void disconnectBoring();
    /// When the boring run's offsets were written to its CNC output (BoringLink::writeTimes).
    std::vector<std::chrono::steady_clock::time_point> boringWriteTimes() const;
    /// A simulated pass of the source's own (devices::BoringTruth); throws std::invalid_argument when the
    /// source runs none.
    std::shared_ptr<core::BoringStation> beginBoringPass(const QString& sourceId, const core::BoringScenario& scenario);
    /// Writes a dynamic X offset to the CNC output `outputId` at once (the operator zeroing it between runs).
    core::OutputResult writeOffset(const QString& outputId, double xOffsetMm);
    /// A link to the probe mandrel or drive read-out `id` for a calibration wizard.
    std::shared_ptr<CalibrationLink> calibrationLink(const QString& id);
    /// The stand's screw jack bends the bar of probe `id` (devices::CalibrationStand::bendBar); throws
    /// std::invalid_argument without a stand with a screw jack.
    void bendBar(const QString& id, int plane, double tipDeflectionMm);
    /// The stand's hydraulic jack loads the tool holder of drive `id`; throws without a hydraulic jack.
    void applyLoadN(const QString& id, double loadN);
    /// Takes the jack of `id`'s stand away (nothing without one).
    void releaseJack(const QString& id);
    /// Starts uploading a linearisation table into probe `id` (devices::TableUploadTarget::uploadTable);
    /// throws std::invalid_argument when it takes none or refuses the image.
    void uploadTable(const QString& id, const std::vector<std::uint8_t>& image, std::uint16_t version,
                     std::uint32_t crc32c);

    /// Minimum time between two snapshots of a changing device, ms.
    static constexpr int kViewFlushMs = 50;
    /// How often the counters of the Devices page (frames, readings, lost) are looked at, ms: they change
    /// without a state change, so no device announces them.
    static constexpr int kStatisticsRefreshMs = 250;

signals:
    /// Snapshots of the instances that changed (state, live value, last error, counters).
    void viewsChanged(const QList<tt::runtime::DeviceView>& views);
    /// An instance was added, removed or replaced: every snapshot.
    void listChanged(const QList<tt::runtime::DeviceView>& views);

private:
    DeviceView snapshot(const QString& id, const QString& name, const QString& pluginId, devices::DeviceKind kind,
                        const QVariantMap& settings, devices::Device& device) const;
    void onDeviceChanged(const QString& id);
    void flushViews();
    void pumpCalibration();
    /// Marks for the next flush every device whose counters moved since they were last shown.
    void refreshStatistics();
    /// Marks a mandrel's view for the next flush when its table upload moved on.
    void showUploadProgress(const QString& id, devices::Device& device);
    devices::Device* deviceOrTrial(const QString& id) const;
    devices::CalibrationStand& stand(const QString& id) const;

    std::unique_ptr<devices::DeviceManager> m_manager;
    std::unique_ptr<devices::Device> m_trial;
    QString m_trialPlugin;
    devices::DeviceKind m_trialKind = devices::DeviceKind::Gauge;
    QVariantMap m_trialSettings;
    QString m_reopenAfterTrial;
    LatheLink* m_lathe = nullptr;
    BoringLink* m_boring = nullptr;
    std::vector<std::weak_ptr<CalibrationLink>> m_calibration;
    QTimer m_calibrationPump;
    QSet<QString> m_dirty;
    QTimer m_statisticsRefresh;
    QHash<QString, QList<devices::DeviceStatistic>> m_statisticsShown;
    /// The table upload each calibrated mandrel last showed: a change marks its view for the next flush.
    QHash<QString, devices::TableUploadStatus> m_uploadShown;
    QTimer m_flush;
};

}  // namespace tt::runtime
