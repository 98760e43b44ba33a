#pragma once

#include <QObject>

namespace tt::runtime {
class DeviceHub;
}

namespace tt::ui {

class AppState;

/// Keeps the device badge and status bar (AppState's device tone and summary) in step with the
/// device instances: none configured, all ready, some connecting or closed, some in error (the
/// first one named with its message).
class DeviceStatusBridge : public QObject {
    Q_OBJECT
public:
    DeviceStatusBridge(runtime::DeviceHub& hub, AppState& state, QObject* parent = nullptr);
    /// Writes the current summary into the AppState.
    void update();

private:
    runtime::DeviceHub& m_hub;
    AppState& m_state;
};

}  // namespace tt::ui
