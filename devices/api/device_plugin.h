#pragma once

#include <QList>
#include <QString>
#include <QVariantMap>
#include <QtPlugin>
#include <memory>
#include <stdexcept>

#include "devices/api/device.h"
#include "devices/api/settings_schema.h"
#include "devices/api/shaft_machine_offer.h"

namespace tt::devices {

/// A device plugin: a factory of device instances of one or more kinds, each with a settings
/// schema. Plugins are shared libraries in the plugin folder (see plugin_folder.h) whose root
/// object implements this interface; the simulator is built in and always present.
class DevicePlugin {
public:
    virtual ~DevicePlugin() = default;

    /// Stable id stored with each instance ("gauge-serial").
    virtual QString pluginId() const = 0;
    /// Name of how the plugin connects, shown after the kind on the Devices page ("Serial data
    /// cable", "Modbus TCP/RTU"), in the user's language. Like every text a plugin shows (schema
    /// labels, units, choices, help, issues, state messages, counters), it is English in the
    /// source and goes through QCoreApplication::translate with the plugin's context.
    virtual QString displayName() const = 0;
    /// The kinds this plugin creates.
    virtual QList<DeviceKind> kinds() const = 0;
    /// The settings of an instance of `kind` (the form on the Devices page).
    virtual SettingsSchema settingsSchema(DeviceKind kind) const = 0;
    /// Problems of `settings` for `kind`; the default checks the schema.
    virtual QList<SettingIssue> validate(DeviceKind kind, const QVariantMap& settings,
                                         Validation depth = Validation::Full) const {
        return validateSettings(settingsSchema(kind), settings, depth);
    }
    /// A new, closed instance. Throws std::invalid_argument when the settings are structurally
    /// wrong (validate() with Validation::Structure) or the plugin does not make `kind`; a
    /// missing port or folder is not an error here (the device reports it when opened). Any
    /// number of instances may exist at once.
    virtual std::unique_ptr<Device> create(DeviceKind kind, const QVariantMap& settings,
                                           const DeviceContext& context) = 0;
    /// Complete machines the plugin offers for shaft runs (their own part cycle, CNC and gauge), such
    /// as the built-in simulator's lathe; most plugins offer none.
    virtual QList<ShaftMachineOffer> shaftMachines() const { return {}; }
    /// Complete machines a configured device of the plugin makes possible (`settings` validated, defaults filled
    /// in), such as the LinuxCNC lathe of a LinuxCNC device; most plugins offer none.
    virtual QList<ShaftMachineOffer> deviceMachines(DeviceKind kind, const QVariantMap& settings) const {
        (void)kind;
        (void)settings;
        return {};
    }
};

/// Throws std::invalid_argument with every structural problem of `settings` (for create()).
inline void requireValidSettings(const DevicePlugin& plugin, DeviceKind kind, const QVariantMap& settings) {
    const QList<SettingIssue> issues = plugin.validate(kind, settings, Validation::Structure);
    if (!issues.isEmpty()) throw std::invalid_argument(joinIssues(issues).toStdString());
}

}  // namespace tt::devices

/// Interface id of device plugins; bump the version when DevicePlugin or Device change.
#define TrueTurnDevicePlugin_iid "io.trueturn.DevicePlugin/1.2"
Q_DECLARE_INTERFACE(tt::devices::DevicePlugin, TrueTurnDevicePlugin_iid)
