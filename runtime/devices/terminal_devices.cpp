#include "runtime/devices/terminal_devices.h"

#include <QSettings>

#include "devices/api/device_kind.h"

namespace tt::runtime {

namespace {

const QString kSimulator = QStringLiteral("simulator");

/// Name of the simulator instance of `kind` made on a first start, in the language of that start.
QString simulatorName(devices::DeviceKind kind) {
    switch (kind) {
        case devices::DeviceKind::Gauge:
            return TerminalDevices::tr("Simulated gauge micrometer");
        case devices::DeviceKind::Probe:
            return TerminalDevices::tr("Simulated probe mandrel");
        case devices::DeviceKind::DriveCurrent:
            return TerminalDevices::tr("Simulated drive-current readout");
        case devices::DeviceKind::CorrectionOutput:
            return TerminalDevices::tr("Simulated CNC output");
    }
    return {};
}

}  // namespace

TerminalDevices::TerminalDevices(const QString& pluginFolder, QObject* parent) : QObject(parent) {
    m_hub.loadPlugins(pluginFolder);
    m_problems << m_hub.pluginErrors();
    QSettings settings;
    m_firstStart = !settings.childGroups().contains(QStringLiteral("devices"));
    if (m_firstStart) {
        for (devices::DeviceKind kind : devices::allDeviceKinds())
            m_hub.addDevice(kSimulator, kind, simulatorName(kind), {});
        m_hub.save(settings);
    } else {
        m_problems << m_hub.restore(settings);
    }
    m_hub.openAll();
    connect(&m_hub, &DeviceHub::devicesChanged, this, &TerminalDevices::save);
}

TerminalDevices::~TerminalDevices() = default;

void TerminalDevices::save() {
    QSettings settings;
    m_hub.save(settings);
}

}  // namespace tt::runtime
