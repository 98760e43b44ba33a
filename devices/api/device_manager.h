#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <memory>
#include <vector>

#include "devices/api/device.h"
#include "devices/api/device_plugin.h"
#include "devices/api/steady_clock.h"

class QPluginLoader;
class QSettings;

namespace tt::devices {

/// One configured device instance.
struct DeviceEntry {
    QString id;        ///< stable id ("dev-3")
    QString name;      ///< given by the user ("Micrometer at the lathe")
    QString pluginId;  ///< which plugin made it
    DeviceKind kind = DeviceKind::Gauge;
    QVariantMap settings;  ///< validated, with defaults filled in
    std::unique_ptr<Device> device;
};

/// Summary of all devices for the status bar: tone and one line.
struct DeviceSummary {
    enum class Tone { None, Ok, Warning, Fault };
    Tone tone = Tone::None;
    QString text;  ///< "3 ready" or "Gauge: no answer from /dev/ttyUSB0 for 1.0 s"
};

/// The host side of the device plugins: finds the plugins one way (those linked into the program as
/// static Qt plugins first, such as the built-in simulator, then the shared libraries in the plugin
/// folder; it names none), holds the configured instances, persists them in QSettings, and tells
/// observers when an instance changes. Lives in the thread of its instances (the runtime's device
/// thread).
class DeviceManager : public QObject {
    Q_OBJECT
public:
    /// `clock`: stamps every sample; null uses an internal steady clock.
    explicit DeviceManager(const core::Clock* clock = nullptr, QObject* parent = nullptr);
    ~DeviceManager() override;

    /// Loads every plugin library in `folder` (see defaultPluginFolder()); returns how many
    /// loaded. Libraries that fail are listed in pluginErrors(). Loading twice is harmless.
    int loadPlugins(const QString& folder);
    /// Why plugin libraries did not load ("libfoo.so: not a TrueTurn device plugin").
    QStringList pluginErrors() const { return m_pluginErrors; }
    /// Saved entries that could not be restored (their plugin is missing), as saved.
    QVariantList unavailableEntries() const { return m_unavailable; }
    /// Available plugins, the linked ones (the simulator) first.
    QList<DevicePlugin*> plugins() const;
    DevicePlugin* plugin(const QString& pluginId) const;
    /// The complete machines every plugin offers for shaft runs, the simulator's first.
    QList<ShaftMachineOffer> shaftMachineOffers() const;

    /// Creates an instance (closed) and returns its id. Throws std::invalid_argument with every
    /// settings problem, or for an unknown plugin or kind.
    QString addDevice(const QString& pluginId, DeviceKind kind, const QString& name, const QVariantMap& settings);
    /// Replaces an instance's name and settings (the old instance is closed and destroyed).
    /// Throws std::invalid_argument like addDevice; the old instance stays on failure.
    void updateDevice(const QString& id, const QString& name, const QVariantMap& settings);
    /// Closes and removes an instance; unknown ids are ignored.
    void removeDevice(const QString& id);

    QStringList deviceIds() const;
    const DeviceEntry* entry(const QString& id) const;
    Device* device(const QString& id) const;
    /// Ids of the instances of `kind`, in the order they were added.
    QStringList devicesOfKind(DeviceKind kind) const;

    /// Opens every instance.
    void openAll();
    /// Tone and one line for the status bar.
    DeviceSummary summary() const;

    /// Writes all instances to `settings` (group "devices").
    void save(QSettings& settings) const;
    /// Replaces the instances with those in `settings`; returns the problems of entries that
    /// could not be restored (e.g. their plugin is missing now). Those entries are kept and
    /// written back by save(), so nothing configured is lost. Ports and folders are not required
    /// to exist at restore time: such devices report the problem when opened.
    QStringList restore(QSettings& settings);

    const core::Clock& clock() const { return *m_clock; }

signals:
    /// An instance was added, removed or replaced.
    void devicesChanged();
    /// State, live value or last error of an instance changed.
    void deviceChanged(const QString& id);

private:
    QString insert(const QString& id, const QString& pluginId, DeviceKind kind, const QString& name,
                   const QVariantMap& settings, Validation depth);
    std::unique_ptr<Device> make(const QString& pluginId, DeviceKind kind, const QVariantMap& settings,
                                 QVariantMap& completed, Validation depth) const;
    void watch(const QString& id, Device& device);
    DeviceEntry* find(const QString& id);

    SteadyClock m_ownClock;
    const core::Clock* m_clock;
    QList<DevicePlugin*> m_static;  ///< linked into the program (QPluginLoader::staticInstances)
    QList<DevicePlugin*> m_loaded;
    QList<QPluginLoader*> m_loaders;
    QStringList m_loadedFiles;
    QStringList m_pluginErrors;
    std::vector<DeviceEntry> m_entries;
    QVariantList m_unavailable;  ///< saved entries that could not be created (plugin missing), kept
    int m_nextId = 1;
};

}  // namespace tt::devices
