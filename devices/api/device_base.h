#pragma once

#include <QString>

#include "devices/api/device.h"

namespace tt::devices {

/// Common bookkeeping of device instances: kind, health, live value, last error, the clock,
/// and the change notification. Plugins derive their devices from it.
class DeviceBase : public Device {
public:
    DeviceBase(DeviceKind kind, const DeviceContext& context);

    DeviceKind kind() const override { return m_kind; }
    core::DeviceHealth health() const override { return m_health; }
    QString liveValue() const override { return m_liveValue; }
    QString lastError() const override { return m_lastError; }

protected:
    /// Sets the state and its message; notifies when either changed. An Error state's message is also the
    /// last error.
    void setState(core::DeviceState state, const QString& message = {});
    void setLiveValue(const QString& value);
    /// Records a problem that does not change the state (refused reading, corrupt frame).
    void reportError(const QString& message);
    /// Clock time now, s.
    double now() const;
    core::DeviceState state() const { return m_health.state; }

private:
    DeviceKind m_kind;
    const core::Clock* m_clock;
    core::DeviceHealth m_health;
    QString m_liveValue;
    QString m_lastError;
};

}  // namespace tt::devices
