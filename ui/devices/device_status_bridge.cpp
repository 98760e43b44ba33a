#include "ui/devices/device_status_bridge.h"

#include "devices/api/device_manager.h"
#include "ui/app_state.h"

namespace tt::ui {

DeviceStatusBridge::DeviceStatusBridge(devices::DeviceManager& manager, AppState& state, QObject* parent)
    : QObject(parent), m_manager(manager), m_state(state) {
    connect(&manager, &devices::DeviceManager::devicesChanged, this, &DeviceStatusBridge::update);
    connect(&manager, &devices::DeviceManager::deviceChanged, this, &DeviceStatusBridge::update);
    update();
}

void DeviceStatusBridge::update() {
    const devices::DeviceSummary summary = m_manager.summary();
    AppState::Tone tone = AppState::Tone::Idle;
    switch (summary.tone) {
        case devices::DeviceSummary::Tone::Ok:
            tone = AppState::Tone::Ok;
            break;
        case devices::DeviceSummary::Tone::Warning:
            tone = AppState::Tone::Warning;
            break;
        case devices::DeviceSummary::Tone::Fault:
            tone = AppState::Tone::Fault;
            break;
        case devices::DeviceSummary::Tone::None:
            break;
    }
    m_state.setDevices(tone, summary.text);
}

}  // namespace tt::ui
