#pragma once

#include <QObject>

namespace tt::devices {
class DeviceManager;
}

namespace tt::ui {

class AppState;

/// Keeps the device badge and status bar (AppState's device tone and summary) in step with the
/// device instances: none configured, all ready, some connecting or closed, some in error (the
/// first one named with its message).
class DeviceStatusBridge : public QObject {
    Q_OBJECT
public:
    DeviceStatusBridge(devices::DeviceManager& manager, AppState& state, QObject* parent = nullptr);
    /// Writes the current summary into the AppState.
    void update();

private:
    devices::DeviceManager& m_manager;
    AppState& m_state;
};

}  // namespace tt::ui
