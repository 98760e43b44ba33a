#pragma once

#include <QTimer>
#include <QVariantMap>
#include <deque>
#include <memory>
#include <vector>

#include "devices/api/device_base.h"
#include "devices/modbus/modbus_link.h"
#include "devices/parsers/modbus_registers.h"

namespace tt::devices {

/// The cross-feed drive's current, velocity and position read over Modbus TCP or RTU (paper
/// 001, way 1), from a configurable register map (address, type, word order, scale, unit per
/// value), polled every 10..100 ms. Each sample is stamped with the midpoint of its request
/// and reply. Modbus exceptions are reported by name; three polls in a row without an answer
/// put the device in error; the connection is re-established with back-off.
/// Settings: modbusConnectionFields(), pollMs, and current*, velocity*, position* register fields.
class ModbusDriveDevice final : public DeviceBase, public core::DriveCurrentReadout {
public:
    ModbusDriveDevice(const QVariantMap& settings, const DeviceContext& context);
    ~ModbusDriveDevice() override;

    void open() override;
    void close() override;
    void testConnection() override;
    core::DeviceHealth health() const override { return DeviceBase::health(); }
    std::optional<core::DriveSample> takeSample() override;
    core::DriveCurrentReadout* driveCurrentReadout() override { return this; }
    QList<DeviceStatistic> statistics() const override;

private:
    struct Quantity {
        modbus::RegisterSpec spec;
        double toEngineUnit = 1.0;  ///< A, mm/s or mm per map unit
    };
    void poll();
    void blockDone(std::size_t index, const ModbusResult& result);
    void finishPoll();
    void connected();
    void lost(const QString& reason);

    std::unique_ptr<ModbusLink> m_link;
    QTimer m_timer;
    Quantity m_current;
    Quantity m_velocity;
    Quantity m_position;
    std::vector<modbus::ReadBlock> m_blocks;
    // The poll in flight.
    bool m_polling = false;
    double m_sentAtS = 0.0;
    std::size_t m_pending = 0;
    std::vector<std::vector<std::uint16_t>> m_words;
    QString m_pollError;
    bool m_pollTimedOut = false;
    bool m_pollException = false;
    // Counters.
    int m_failedInARow = 0;
    std::uint64_t m_polls = 0;
    std::uint64_t m_samplesOk = 0;
    std::uint64_t m_timeouts = 0;
    std::uint64_t m_exceptions = 0;
    std::uint64_t m_refused = 0;
    std::uint64_t m_overruns = 0;
    std::deque<core::DriveSample> m_samples;
};

}  // namespace tt::devices
