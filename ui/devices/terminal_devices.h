#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

#include "devices/api/device_manager.h"

namespace tt::ui {

/// The device instances of the operator terminal, made before the main window so that every page sees the
/// same ones (AppContext::devices): the plugins in `pluginFolder` loaded, the instances saved in QSettings
/// restored, and on a first start (nothing saved yet) one instance of the built-in simulator per device kind
/// so the terminal works out of the box; all opened. Saved again whenever an instance is added, replaced
/// or removed. Lives in the GUI thread, like the devices.
class TerminalDevices : public QObject {
    Q_OBJECT
public:
    /// Loads, restores or makes, and opens the devices (see the class).
    explicit TerminalDevices(const QString& pluginFolder, QObject* parent = nullptr);
    ~TerminalDevices() override;

    /// The instances every page uses.
    devices::DeviceManager& manager() { return m_manager; }
    /// True when nothing was saved before and the simulator instances were added.
    bool firstStart() const { return m_firstStart; }
    /// Plugin libraries that did not load and saved instances that could not be restored, in plain words.
    QStringList problems() const { return m_problems; }

private:
    void save();

    devices::DeviceManager m_manager;
    bool m_firstStart = false;
    QStringList m_problems;
};

}  // namespace tt::ui
