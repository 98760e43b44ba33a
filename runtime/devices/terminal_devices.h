#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include "runtime/devices/device_hub.h"

namespace tt::runtime {

/// The device instances of the operator terminal, made before the main window so that every page sees the
/// same ones (the GUI's AppContext::devices): the plugins in `pluginFolder` loaded, the instances saved in QSettings
/// restored, and on a first start (nothing saved yet) one instance of the built-in simulator per device kind
/// so the terminal works out of the box; all opened. Saved again whenever an instance is added, replaced
/// or removed. Lives in the GUI thread; the devices live in the hub's device thread.
class TerminalDevices : public QObject {
    Q_OBJECT
public:
    /// Loads, restores or makes, and opens the devices (see the class).
    explicit TerminalDevices(const QString& pluginFolder, QObject* parent = nullptr);
    ~TerminalDevices() override;

    /// The instances every page uses.
    DeviceHub& hub() { return m_hub; }
    /// True when nothing was saved before and the simulator instances were added.
    bool firstStart() const { return m_firstStart; }
    /// Plugin libraries that did not load and saved instances that could not be restored, in plain words.
    QStringList problems() const { return m_problems; }

private:
    void save();

    DeviceHub m_hub;
    bool m_firstStart = false;
    QStringList m_problems;
};

}  // namespace tt::runtime
